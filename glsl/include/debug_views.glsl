// --view: what a pixel shows instead of (or over) the shaded colour. Colours are for display:
// the tonemap pass writes them without the Reinhard curve.

// A compact approximation of the Turbo colour map, t in [0, 1].
vec3 heatColor(float t) {
    t = clamp(t, 0.0, 1.0);
    const vec4 kr = vec4(0.13572138, 4.61539260, -42.66032258, 132.13108234);
    const vec2 kr2 = vec2(-152.94239396, 59.28637943);
    const vec4 kg = vec4(0.09140261, 2.19418839, 4.84296658, -14.18503333);
    const vec2 kg2 = vec2(4.27729857, 2.82956604);
    const vec4 kb = vec4(0.10667330, 12.64194608, -60.58204836, 110.36276771);
    const vec2 kb2 = vec2(-89.90310912, 27.34824973);
    vec4 v4 = vec4(1.0, t, t * t, t * t * t);
    vec2 v2 = v4.zw * v4.z;
    return clamp(vec3(dot(v4, kr) + dot(v2, kr2), dot(v4, kg) + dot(v2, kg2), dot(v4, kb) + dot(v2, kb2)), 0.0, 1.0);
}

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
