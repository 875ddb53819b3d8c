// The conservative block of clusters a light may reach: slices from its view-space depth
// extent, tiles from the screen rectangle of its bounding box (the whole screen when it
// crosses the near plane). A spot's box is the exact box of its cone's sector (apex and cap,
// include/spot_cone.glsl), not its sphere's. Needs frame_uniforms, lights, cluster_grid and spot_cone.

struct ClusterRange {
    uvec3 lo;      // first tile x, tile y, slice
    uvec3 hi;      // last (inclusive)
    vec3 center;   // view space: the light's sphere, or the sphere holding a spot's sector
    float radius;
};

// A light in view space, as the cluster tests take it.
struct ViewLight {
    vec3 position;  // the light (a spot's apex)
    float radius;
    vec3 axis;      // a spot's direction, unit
    float cosOuter; // ML_POINT_LIGHT_CONE_COS for a point light
};

ViewLight viewLight(uint lightIndex) {
    Light l = lights[lightIndex];
    ViewLight v;
    v.position = (u_view * vec4(l.positionRadius.xyz, 1.0)).xyz;
    v.radius = l.positionRadius.w;
    vec4 cone = lightCone(lightIndex);
    v.axis = mat3(u_view) * cone.xyz;
    v.cosOuter = cone.w;
    return v;
}

// The view-space box of what the light can reach: its sphere's, or its sector's from the
// sector's support along each axis.
void viewLightBox(ViewLight v, out vec3 lo, out vec3 hi) {
    if (!isSpotCone(v.cosOuter)) {
        lo = v.position - v.radius;
        hi = v.position + v.radius;
        return;
    }
    float slack = kSpotSlack * (v.radius + length(v.position));
    for (int a = 0; a < 3; ++a) {
        vec3 e = vec3(0.0);
        e[a] = 1.0;
        hi[a] = v.position[a] + spotReach(e, v.axis, v.cosOuter, v.radius) + slack;
        lo[a] = v.position[a] - spotReach(-e, v.axis, v.cosOuter, v.radius) - slack;
    }
}

// False when the light cannot reach any cluster.
bool lightClusterRange(uint lightIndex, out ClusterRange range) {
    ViewLight v = viewLight(lightIndex);
    vec4 sphere = spotBoundingSphere(v.position, v.axis, v.cosOuter, v.radius);
    range.center = sphere.xyz;
    range.radius = sphere.w;
    range.lo = uvec3(0u);
    range.hi = uvec3(0u);
    if (!(v.radius > 0.0)) return false;
    vec3 boxLo, boxHi;
    viewLightBox(v, boxLo, boxHi);
    float zMin = -boxHi.z, zMax = -boxLo.z;

    // The first and last slices reach the camera's planes (see cluster_bounds.comp).
    float gridNear = min(grid.tile.z, grid.slicing.x) * (1.0 - 1e-4);
    float gridFar = max(grid.tile.w, grid.slicing.y) * (1.0 + 1e-4);
    if (zMax < gridNear || zMin > gridFar) return false;
    uint s0 = sliceForDepth(max(zMin, 1e-7));
    uint s1 = sliceForDepth(zMax);

    uvec2 t0 = uvec2(0u), t1 = grid.dims.xy - 1u;
    if (zMin > gridNear * 1e-3) {
        // Entirely in front of the camera: project the corners of the bounding box.
        vec2 lo = vec2(1e30), hi = vec2(-1e30);
        for (int k = 0; k < 8; ++k) {
            vec3 p = vec3((k & 1) != 0 ? boxHi.x : boxLo.x, (k & 2) != 0 ? boxHi.y : boxLo.y, (k & 4) != 0 ? boxHi.z : boxLo.z);
            vec2 ndc = vec2(u_proj[0][0] * p.x, u_proj[1][1] * p.y) / -p.z;
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
