// Read access to the light lists built by the assignment passes: the one light loop of every
// clustered method (Forward+, both deferred resolves, the visibility buffer). ML_ZBIN selects
// z-binning (--assign zbin, glsl/include/zbin.glsl); without it, the per-cluster lists.
// A pass that reads z-binning's lists alone (ML_ZBIN_LISTS_ONLY: no debug views, the transparent
// shading) leaves the per-cluster buffers out: llvmpipe gives a compute shader 16 storage
// blocks, and with every vertex stream and spot lights that shading needs them all.
#if !(defined(ML_ZBIN) && defined(ML_ZBIN_LISTS_ONLY))
layout(std430, binding = ML_SSBO_CLUSTER_COUNTS) readonly buffer ClusterCounts { uint clusterCounts[]; };
layout(std430, binding = ML_SSBO_CLUSTER_OFFSETS) readonly buffer ClusterOffsets { uint clusterOffsets[]; };
layout(std430, binding = ML_SSBO_LIGHT_INDICES) readonly buffer LightIndices { uint lightIndices[]; };
#endif

// The list a shaded point reads: its cluster's, or with --normal-cones (ML_NORMAL_CONES, deferred
// and visibility only) the one of its (cluster, view-space normal bin) key. Needs normal_bins.
uint clusterListKey(uint cluster, vec3 worldNormal) {
#if defined(ML_NORMAL_CONES)
    return cluster * uint(ML_NORMAL_BINS) + normalBin(normalize(mat3(u_view) * worldNormal));
#else
    return cluster;
#endif
}

#include "include/light_sum.glsl"

#ifdef ML_ZBIN
#include "include/zbin.glsl"

// The tile of a cluster index: the cluster grid's tiles are the z-binning tiles.
uint zbinTileOf(uint cluster) { return cluster % (grid.dims.x * grid.dims.y); }

// Walks the bin's range of sorted lights a word at a time, shading those whose tile bit is set.
vec3 shadeClusterLights(SurfacePoint s, vec3 viewDir, uint cluster, float viewDepth) {
    uvec2 range = zbinRanges[zbinForDepth(viewDepth)];
    uint tile = zbinTileOf(cluster);
    LightSum sum = noLight();
    if (range.x > range.y) return lightSumValue(sum);
    for (uint w = range.x >> 5; w <= range.y >> 5; ++w) {
        uint bits = zbinWordBits(tile, range, w);
        while (bits != 0u) {
            uint i = w * 32u + uint(findLSB(bits));
            bits &= bits - 1u;
            uint index = zbinSortedLights[i];
            Light l = lights[index];
            vec3 c = shadeLight(s, viewDir, l.positionRadius, l.colorCosInner, lightCone(index));
            addLight(sum, c);
            ML_OFFER_SHADOW_SAMPLE(c, vec4(l.positionRadius.xyz, 1.0), index);
        }
    }
    return lightSumValue(sum);
}

// Lights a pixel shades (--view light-count): the set bits within its bin's range.
uint clusterLightCount(uint cluster, vec3 worldNormal, float viewDepth) {
    uvec2 range = zbinRanges[zbinForDepth(viewDepth)];
    uint n = 0u;
    if (range.x <= range.y)
        for (uint w = range.x >> 5; w <= range.y >> 5; ++w) n += bitCount(zbinWordBits(zbinTileOf(cluster), range, w));
    return n;
}

#else

// First list entry and entry count of a cluster. Capped lists (the seeds' baseline) live at
// cluster * cap and hold at most cap entries; the rest were dropped and counted.
uvec2 clusterListRange(uint cluster) {
    uint count = clusterCounts[cluster];
    uint cap = grid.options.y;
    if (cap > 0u) return uvec2(cluster * cap, min(count, cap));
    return uvec2(clusterOffsets[cluster], count);
}

// viewDepth is unused here: the cluster (and normal bin) already say which list applies.
vec3 shadeClusterLights(SurfacePoint s, vec3 viewDir, uint cluster, float viewDepth) {
    uvec2 range = clusterListRange(clusterListKey(cluster, s.normal));
    LightSum sum = noLight();
    for (uint k = 0u; k < range.y; ++k) {
        uint index = lightIndices[range.x + k];
        Light l = lights[index];
        vec3 c = shadeLight(s, viewDir, l.positionRadius, l.colorCosInner, lightCone(index));
        addLight(sum, c);
        ML_OFFER_SHADOW_SAMPLE(c, vec4(l.positionRadius.xyz, 1.0), index);
    }
    return lightSumValue(sum);
}

uint clusterLightCount(uint cluster, vec3 worldNormal, float viewDepth) { return clusterCounts[clusterListKey(cluster, worldNormal)]; }
#endif
