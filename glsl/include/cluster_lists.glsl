// Read access to the per-cluster light lists built by the assignment passes.
layout(std430, binding = ML_SSBO_CLUSTER_COUNTS) readonly buffer ClusterCounts { uint clusterCounts[]; };
layout(std430, binding = ML_SSBO_CLUSTER_OFFSETS) readonly buffer ClusterOffsets { uint clusterOffsets[]; };
layout(std430, binding = ML_SSBO_LIGHT_INDICES) readonly buffer LightIndices { uint lightIndices[]; };

// The list a shaded point reads: its cluster's, or with --normal-cones (ML_NORMAL_CONES, deferred
// and visibility only) the one of its (cluster, view-space normal bin) key. Needs normal_bins.
uint clusterListKey(uint cluster, vec3 worldNormal) {
#if defined(ML_NORMAL_CONES)
    return cluster * uint(ML_NORMAL_BINS) + normalBin(normalize(mat3(u_view) * worldNormal));
#else
    return cluster;
#endif
}

// First list entry and entry count of a cluster. Capped lists (the seeds' baseline) live at
// cluster * cap and hold at most cap entries; the rest were dropped and counted.
uvec2 clusterListRange(uint cluster) {
    uint count = clusterCounts[cluster];
    uint cap = grid.options.y;
    if (cap > 0u) return uvec2(cluster * cap, min(count, cap));
    return uvec2(clusterOffsets[cluster], count);
}

vec3 shadeClusterLights(SurfacePoint s, vec3 viewDir, uint cluster) {
    uvec2 range = clusterListRange(clusterListKey(cluster, s.normal));
    vec3 color = vec3(0.0);
    for (uint k = 0u; k < range.y; ++k) {
        Light l = lights[lightIndices[range.x + k]];
        color += shadePointLight(s, viewDir, l.positionRadius, l.color.rgb);
    }
    return color;
}
