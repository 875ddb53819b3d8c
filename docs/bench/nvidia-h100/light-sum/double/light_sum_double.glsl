// How a point adds up the contributions of its point and spot lights (--light-sum). A float sum
// depends on the order of its terms, and the fill passes write the light lists in whatever order
// their atomics ran: float sums need every list sorted by light index (assign.sort) to give the
// same bits from run to run and as naive's loop. With ML_FIXED_LIGHT_SUM each contribution is
// rounded once, on its own, to a 64-bit integer count of 2^-32 and the integers add exactly, so
// every order gives the same sum, bit for bit, and the lists need no sort. A contribution keeps
// its 24 mantissa bits from 2^-8 up and rounds to 2^-32 below; one light adds at most 2^20 (a
// radiance no display shows: the HDR frame's tonemap and bloom saturate long before), so a sum
// reaches the int64's 2^31 only past 2048 such lights. The file that includes this enables
// GL_ARB_gpu_shader_int64 under ML_FIXED_LIGHT_SUM (an #extension must precede the code).
#if ML_FIXED_LIGHT_SUM
#define LightSum dvec3
const float kLightSumMaxTerm = 1048576.0;   // 2^20
LightSum noLight() { return dvec3(0.0); }
// Each term on the 2^-23 grid (from 1 up a float already is), so doubles add them exactly below 2^30.
void addLight(inout LightSum sum, vec3 contribution) {
    vec3 v = clamp(contribution, 0.0, kLightSumMaxTerm);
    precise vec3 shifted = v + 1.0;
    precise vec3 grid = shifted - 1.0;
    sum += dvec3(mix(grid, v, greaterThanEqual(v, vec3(1.0))));
}
vec3 lightSumValue(LightSum sum) { return vec3(sum); }
#else
#define LightSum vec3
LightSum noLight() { return vec3(0.0); }
void addLight(inout LightSum sum, vec3 contribution) { sum += contribution; }
vec3 lightSumValue(LightSum sum) { return sum; }
#endif
