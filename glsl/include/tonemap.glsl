// Mirrored in C++ by ml::tonemapToSrgb (renderer/reference/tonemap_reference.h) for the tests' CPU reference.
vec3 linearToSrgb(vec3 c) {
    c = clamp(c, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
vec3 tonemapToSrgb(vec3 hdr, float exposure) {
    vec3 c = max(hdr * exposure, vec3(0.0));
    return linearToSrgb(c / (1.0 + c));
}
