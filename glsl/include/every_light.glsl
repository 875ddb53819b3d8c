// Every light of the frame, in index order, added to `color`: naive's loop, and Forward+'s for a
// fragment whose cluster list was skipped (glsl/forward_plus.frag, --msaa with --active-only).
// Needs lights.glsl and shading.glsl.
vec3 addEveryLight(SurfacePoint s, vec3 viewDir, vec3 color) {
    uint n = lightCount();
    for (uint i = 0u; i < n; ++i) {
        Light l = lights[i];
        color += shadeLight(s, viewDir, l.positionRadius, l.colorCosInner, lightCone(i));
    }
    return color;
}
