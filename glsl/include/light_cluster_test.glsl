// Does a light reach a cluster? The sphere test of --cull, chosen at compile time by ML_CULL
// (bindings.h), and for a spot also its cone (include/spot_cone.glsl). Every variant is conservative: a sphere that reaches any point of the cluster's
// volume (its tile's frustum between its depth extent, include/cluster_grid.glsl) always
// passes; they differ in how many spheres that miss the volume still pass (false positives,
// measured by `render --stats` against the exact distance, renderer/clustering/cluster_culling.h).
// Needs frame_uniforms, lights, cluster_grid and spot_cone. Mirrored on the CPU by ml::passesCullTest.

#ifndef ML_CULL
#define ML_CULL ML_CULL_AABB
#endif

struct ClusterAabb { vec4 minPoint; vec4 maxPoint; };
layout(std430, binding = ML_SSBO_CLUSTER_AABBS) readonly buffer ClusterAabbs { ClusterAabb aabbs[]; };

// A relative margin on the radius: float rounding must never turn a touch into a miss.
const float kCullRadiusSlack = 1.0 + 1e-5;

// aabb: the sphere against the cluster's view-space AABB (exact distance to the box). The box
// is looser than the frustum piece it bounds, most at wide tiles and deep slices.
bool sphereReachesAabb(uint cluster, vec3 c, float r) {
    vec3 d = max(max(aabbs[cluster].minPoint.xyz - c, c - aabbs[cluster].maxPoint.xyz), vec3(0.0));
    return dot(d, d) <= r * r;
}

// sphere: signed distances to the six planes of the cluster's frustum. Conservative (a sphere
// that reaches the volume is inside or crosses every plane) but loose near edges and corners:
// a sphere outside two planes' intersection near a corner passes each plane alone.
bool sphereReachesFrustumPlanes(uvec3 c3, vec3 c, float r) {
    vec2 z = clusterDepthExtent(c3.z);
    if (-c.z + r < z.x || -c.z - r > z.y) return false;
    // Side planes through the eye: x / -z between a.x and b.x (likewise y), normals inward.
    vec4 ndc = clusterTileNdc(c3.xy);
    vec2 a = ndc.xy / vec2(u_proj[0][0], u_proj[1][1]);
    vec2 b = ndc.zw / vec2(u_proj[0][0], u_proj[1][1]);
    vec2 lower = (c.xy + a * c.z) * inversesqrt(1.0 + a * a);   // x + a z >= 0 inside
    vec2 upper = (-c.xy - b * c.z) * inversesqrt(1.0 + b * b);  // -x - b z >= 0 inside
    return all(greaterThanEqual(lower, vec2(-r))) && all(greaterThanEqual(upper, vec2(-r)));
}

// cone (seed 001, after lxjk's "spherical-sliced cone", 2018): the tile's frustum is wrapped in
// a cone from the eye (axis through the tile's centre, half-angle to its widest corner ray) and
// the slice in a spherical shell [zNear, zFar / cos of the widest corner] of distance from the
// eye. The sphere passes when its own cone from the eye meets the tile's (angle between axes
// <= sum of half-angles) and, along the cone edge nearest to it (or its own ray when its centre
// is inside the cone), the chord it cuts overlaps the shell. Exact against the cone-in-shell,
// which contains the cluster: conservative, tight at corners, loose in depth at wide tiles.
bool sphereReachesSlicedCone(uvec3 c3, vec3 c, float r) {
    vec4 ndc = clusterTileNdc(c3.xy);
    vec2 a = ndc.xy / vec2(u_proj[0][0], u_proj[1][1]);
    vec2 b = ndc.zw / vec2(u_proj[0][0], u_proj[1][1]);
    vec3 corner0 = normalize(vec3(a.x, a.y, -1.0)), corner1 = normalize(vec3(b.x, a.y, -1.0));
    vec3 corner2 = normalize(vec3(a.x, b.y, -1.0)), corner3 = normalize(vec3(b.x, b.y, -1.0));
    vec3 axis = normalize(corner0 + corner1 + corner2 + corner3);
    float tileCos = min(min(dot(axis, corner0), dot(axis, corner1)), min(dot(axis, corner2), dot(axis, corner3)));
    tileCos = clamp(tileCos - 1e-6, 0.0, 1.0);
    float tileSin = sqrt(1.0 - tileCos * tileCos);
    vec2 z = clusterDepthExtent(c3.z);
    float shellNear = z.x;
    float shellFar = z.y / min(min(-corner0.z, -corner1.z), min(-corner2.z, -corner3.z));

    float dist = length(c);
    if (dist <= r) return dist + r >= shellNear;  // the eye is inside the sphere: every direction
    vec3 dir = c / dist;
    float lightSin = r / dist, lightCos = sqrt(max(1.0 - lightSin * lightSin, 0.0));
    float cosToAxis = clamp(dot(dir, axis), -1.0, 1.0), sinToAxis = sqrt(1.0 - cosToAxis * cosToAxis);
    // Cone against cone: angle(dir, axis) <= tile half-angle + sphere half-angle.
    float cosSum = tileCos * lightCos - tileSin * lightSin;
    if (cosToAxis < cosSum) return false;
    // Spherical slice: the sphere's chord along the nearest cone edge (angle to it: max(angle to
    // the axis - tile half-angle, 0)) against the shell.
    float sinDiff = clamp(sinToAxis * tileCos - cosToAxis * tileSin, 0.0, 1.0);
    float cosDiff = sinDiff == 0.0 ? 1.0 : cosToAxis * tileCos + sinToAxis * tileSin;
    float base = dist * cosDiff;
    float chord = sqrt(max(r * r - dist * dist * sinDiff * sinDiff, 0.0));
    return base - chord <= shellFar && base + chord >= shellNear;
}

bool sphereReachesCluster(uint cluster, uvec3 c3, vec3 center, float radius) {
    float r = radius * kCullRadiusSlack;
#if ML_CULL == ML_CULL_SPHERE
    return sphereReachesFrustumPlanes(c3, center, r);
#elif ML_CULL == ML_CULL_CONE
    return sphereReachesSlicedCone(c3, center, r);
#else
    return sphereReachesAabb(cluster, center, r);
#endif
}

// A spot's sector against the sphere around the cluster's view-space AABB (Wronski's cone
// test); always true for a point light. Reads the light's cone itself, so point-only lists pay
// one read.
bool spotConeReachesCluster(uint cluster, uint light) {
    vec4 directionCosOuter = lightCone(light);
    if (!isSpotCone(directionCosOuter.w)) return true;
    vec4 positionRadius = lights[light].positionRadius;
    vec3 apex = (u_view * vec4(positionRadius.xyz, 1.0)).xyz;
    vec3 lo = aabbs[cluster].minPoint.xyz, hi = aabbs[cluster].maxPoint.xyz;
    return spotMayReachSphere(apex, mat3(u_view) * directionCosOuter.xyz, directionCosOuter.w, positionRadius.w,
                              0.5 * (lo + hi), 0.5 * length(hi - lo));
}

// The whole test: `center`, `radius` are the light's bounding sphere (a spot's sector's,
// ClusterRange), then the spot's cone.
bool lightReachesCluster(uint cluster, uvec3 c3, uint light, vec3 center, float radius) {
    return sphereReachesCluster(cluster, c3, center, radius) && spotConeReachesCluster(cluster, light);
}
