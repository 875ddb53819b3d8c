// How a point adds up the contributions of its point and spot lights (--light-sum). A float sum
// depends on the order of its terms, and the fill passes write the light lists in whatever order
// their atomics ran: float sums need every list sorted by light index (assign.sort) to give the
// same bits from run to run and as naive's loop. With ML_FIXED_LIGHT_SUM each contribution is
// rounded once, on its own, to a 64-bit integer count of 2^-32 and the integers add exactly, so
// every order gives the same sum, bit for bit, and the lists need no sort. A contribution keeps
// its 24 mantissa bits from 2^-8 up and rounds to 2^-32 below; one light adds at most 2^20 (the
// tonemap shows such a pixel white either way, though --bloom spreads a clamped one less), so a
// sum reaches the int64's 2^31 only past 2048 such lights. The file that includes this enables
// GL_ARB_gpu_shader_int64 under ML_FIXED_LIGHT_SUM (an #extension must precede the code).
#if ML_FIXED_LIGHT_SUM
#define LightSum i64vec3
const float kLightSumUnits = 4294967296.0;  // 2^32 units to 1
const float kLightSumMaxTerm = 1048576.0;   // 2^20
const float kTwoTo26 = 67108864.0;
LightSum noLight() { return i64vec3(0); }
// A contribution as a count of units, rounded to nearest, through two 32-bit conversions: a float
// to int64 conversion in NVIDIA's driver (580, H100) kept at most 2^31 units (half a unit of
// radiance), which darkened the highlights. v < 2^52, so its whole 2^26s fit 32 bits, and the
// rest is exact (a multiple of v's ulp below 2^26) before it is rounded.
i64vec3 lightUnits(vec3 contribution) {
    vec3 v = clamp(contribution, 0.0, kLightSumMaxTerm) * kLightSumUnits;  // exact: a power of two
    vec3 high = floor(v * (1.0 / kTwoTo26));
    vec3 low = floor(v - high * kTwoTo26 + 0.5);
    return (i64vec3(uvec3(high)) << 26) + i64vec3(uvec3(low));
}
void addLight(inout LightSum sum, vec3 contribution) { sum += lightUnits(contribution); }
vec3 lightSumValue(LightSum sum) { return vec3(sum) * (1.0 / kLightSumUnits); }
#else
#define LightSum vec3
LightSum noLight() { return vec3(0.0); }
void addLight(inout LightSum sum, vec3 contribution) { sum += contribution; }
vec3 lightSumValue(LightSum sum) { return sum; }
#endif
