// A window position's ray from the eye in view space, unit length: the visibility resolve casts
// it through the pixel's triangle, and the exact G-buffer layout stores the distance along it.
// Needs frame_uniforms.glsl.
vec3 pixelRayView(vec2 windowPos) {
    vec2 ndc = windowPos * u_viewport.zw * 2.0 - 1.0;
    vec4 farView = u_invProj * vec4(ndc, 1.0, 1.0);
    return normalize(farView.xyz / farView.w);
}
