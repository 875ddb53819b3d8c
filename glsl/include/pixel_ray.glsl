// A window position's ray from the eye in view space, unit length: the visibility resolve casts
// it through the pixel's triangle, and the exact G-buffer layout stores the distance along it.
// Needs frame_uniforms.glsl.
#include "include/window_depth.glsl"

vec3 pixelRayView(vec2 windowPos) {
    return normalize(viewPositionAtWindow(windowPos, 1.0));  // through its point on the near plane
}

// World-space ray through a window position.
void pixelRay(vec2 windowPos, out vec3 origin, out vec3 direction) {
    origin = u_cameraPos.xyz;
    direction = normalize(mat3(u_invView) * pixelRayView(windowPos));
}

// The point at distance t along the ray through a window position: every method's surface
// position (triangle_surface.glsl), and what the exact G-buffer layout rebuilds from the t it
// stores. One expression, `precise`, so a fragment and a compute shader get the same bits: the
// position used to be the vertices' interpolation, stored as its distance from the eye and
// rebuilt along the ray, which moved it by a few ulps, and where a light nearly touches a glossy
// surface that was up to 69/255 (ToyCar on the H100; docs/accuracy-and-stability.md).
vec3 pixelRayPoint(vec2 windowPos, float t) {
    vec3 origin, direction;
    pixelRay(windowPos, origin, direction);
    precise vec3 point = origin + direction * t;
    return point;
}

