// The bright part of a linear colour, mirrored in C++ by ml::bloomBrightPart (renderer/reference/bloom_reference.h):
// zero at or below the threshold luminance, then growing from zero, so the bloom fades in
// rather than switching on.
const vec3 kLuminance = vec3(0.2126, 0.7152, 0.0722);  // Rec. 709

vec3 bloomBrightPart(vec3 c, float threshold) {
    float lum = dot(c, kLuminance);
    return lum > threshold ? c * ((lum - threshold) / lum) : vec3(0.0);
}
