// --view: what a pixel shows instead of (or over) the shaded colour. Colours are for display:
// the tonemap pass writes them without the Reinhard curve.

#include "include/heat_color.glsl"

vec3 indexColor(uint i) {
    uint h = i * 2654435761u;
    return vec3(float((h >> 8u) & 255u), float((h >> 16u) & 255u), float((h >> 24u) & 255u)) / 255.0 * 0.8 + 0.2;
}

// Lights per cluster on a log scale: 0 is black, 1 blue, ~1000 and more red.
vec3 lightCountColor(uint count) {
    if (count == 0u) return vec3(0.0);
    return heatColor(log2(float(count) + 1.0) / 10.0);
}

vec3 debugViewColor(uint view, SurfacePoint s, uint cluster, float viewDepth, vec3 shaded) {
    if (view == ML_VIEW_LIGHT_COUNT) return lightCountColor(clusterLightCount(cluster, s.normal, viewDepth));
    if (view == ML_VIEW_SLICES) {
        uint slice = cluster / (grid.dims.x * grid.dims.y);
        return indexColor(slice * 7919u + 1u);
    }
    if (view == ML_VIEW_CLUSTERS) return indexColor(cluster);
    if (view == ML_VIEW_OVERFLOW) {
        uint cap = grid.options.y;
        bool over = cap > 0u && clusterCounts[clusterListKey(cluster, s.normal)] > cap;
        float grey = dot(shaded / (1.0 + shaded), vec3(0.3333));
        return over ? vec3(1.0, 0.0, 0.0) : vec3(grey);
    }
    if (view == ML_VIEW_ALBEDO) return s.baseColor;
    if (view == ML_VIEW_NORMAL) return s.normal * 0.5 + 0.5;
    if (view == ML_VIEW_DEPTH) {
        float n = grid.slicing.x, f = grid.slicing.y;
        return vec3(clamp(log(viewDepth / n) / log(f / n), 0.0, 1.0));
    }
    return shaded;
}
