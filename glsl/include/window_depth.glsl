// The window depth every pass reads and writes is reversed: 1 at the near plane, 0 at the far
// plane and where nothing was drawn (the depth clear), with GL's clip depth in [0, 1]
// (glClipControl, renderer/gl/depth_convention.h), so a nearer surface has the greater depth.
// Perspective depth goes as near / distance and a float's steps shrink towards 0, so depth keeps
// about 24 bits of relative precision at every distance; with 1 at the far plane, a step near 1
// was 2.4 mm at 20 m under Sponza's near plane of 0.01, and two surfaces a few millimetres apart
// tied. Needs frame_uniforms.glsl.

// The depth of the far plane, and of every pixel nothing was drawn at.
const float kBackgroundDepth = 0.0;

bool isBackgroundDepth(float windowDepth) { return windowDepth <= kBackgroundDepth; }

// Whether a window depth lies within the near and far planes (a depth the raster keeps).
bool isVisibleDepth(float windowDepth) { return windowDepth > kBackgroundDepth && windowDepth <= 1.0; }

// The view-space position at a window position and depth.
vec3 viewPositionAtWindow(vec2 windowPos, float windowDepth) {
    vec2 ndc = windowPos * u_viewport.zw * 2.0 - 1.0;
    vec4 v = u_invProj * vec4(ndc, windowDepth, 1.0);
    return v.xyz / v.w;
}

// Positive view-space distance of a depth-buffer value.
float viewDepthFromWindowDepth(float windowDepth) {
    vec4 v = u_invProj * vec4(0.0, 0.0, windowDepth, 1.0);
    return -v.z / v.w;
}
