// The conservative block of clusters a light may reach: slices from its view-space depth
// extent, tiles from the screen rectangle of its bounding box (the whole screen when it
// crosses the near plane). Needs frame_uniforms, lights and cluster_grid.

struct ClusterRange {
    uvec3 lo;      // first tile x, tile y, slice
    uvec3 hi;      // last (inclusive)
    vec3 center;   // view space
    float radius;
};

// False when the light cannot reach any cluster.
bool lightClusterRange(uint lightIndex, out ClusterRange range) {
    vec4 pr = lights[lightIndex].positionRadius;
    float r = pr.w;
    range.radius = r;
    range.lo = uvec3(0u);
    range.hi = uvec3(0u);
    if (!(r > 0.0)) return false;
    vec3 c = (u_view * vec4(pr.xyz, 1.0)).xyz;
    range.center = c;
    float zMin = -c.z - r, zMax = -c.z + r;

    // The first and last slices reach the camera's planes (see cluster_bounds.comp).
    float gridNear = min(grid.tile.z, grid.slicing.x) * (1.0 - 1e-4);
    float gridFar = max(grid.tile.w, grid.slicing.y) * (1.0 + 1e-4);
    if (zMax < gridNear || zMin > gridFar) return false;
    uint s0 = sliceForDepth(max(zMin, 1e-7));
    uint s1 = sliceForDepth(zMax);

    uvec2 t0 = uvec2(0u), t1 = grid.dims.xy - 1u;
    if (zMin > gridNear * 1e-3) {
        // Entirely in front of the camera: project the corners of the sphere's bounding box.
        vec2 lo = vec2(1e30), hi = vec2(-1e30);
        for (int k = 0; k < 8; ++k) {
            vec3 v = c + r * vec3((k & 1) != 0 ? 1.0 : -1.0, (k & 2) != 0 ? 1.0 : -1.0, (k & 4) != 0 ? 1.0 : -1.0);
            vec2 ndc = vec2(u_proj[0][0] * v.x, u_proj[1][1] * v.y) / -v.z;
            lo = min(lo, ndc);
            hi = max(hi, ndc);
        }
        if (any(lessThan(hi, vec2(-1.0))) || any(greaterThan(lo, vec2(1.0)))) return false;
        // A hundredth of a pixel of slack: rounding must not drop a tile the sphere touches.
        vec2 pxLo = (clamp(lo, -1.0, 1.0) * 0.5 + 0.5) * u_viewport.xy - 0.01;
        vec2 pxHi = (clamp(hi, -1.0, 1.0) * 0.5 + 0.5) * u_viewport.xy + 0.01;
        t0 = tileForPixel(pxLo);
        t1 = tileForPixel(pxHi);
    }
    range.lo = uvec3(t0, s0);
    range.hi = uvec3(t1, s1);
    return true;
}
