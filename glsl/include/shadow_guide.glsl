// --shadows sampled: how the reuse and the filter decide that two pixels (or a pixel and its place
// in the previous frame) show the same surface, from the guide the lighting pass stored
// (sampled_shadow_lighting.glsl): xyz the world position, w the octahedral normal's bits. Needs
// frame_uniforms and octahedral.
struct ShadowGuide {
    vec3 position;
    vec3 normal;
};

ShadowGuide readShadowGuide(sampler2D guides, ivec2 p) {
    vec4 g = texelFetch(guides, p, 0);
    return ShadowGuide(g.xyz, octDecode(unpackSnorm2x16(floatBitsToUint(g.w))));
}

// Whether `other` lies on the plane of `g`'s surface (within 1 % of its distance from the eye,
// so that the test scales with the depth precision and the pixel's footprint) and faces about
// the same way (normals within 25 degrees).
bool sameShadowSurface(ShadowGuide g, ShadowGuide other) {
    float reach = 0.01 * distance(g.position, u_cameraPos.xyz) + 1e-4;
    return abs(dot(other.position - g.position, g.normal)) <= reach && dot(g.normal, other.normal) >= 0.9;
}
