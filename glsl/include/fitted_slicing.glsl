// Fitted slicing (--slicing fitted): the log slicing of the visible samples' view depth range,
// or of the camera's near and far where nothing is visible. The range is grid.reduction (from
// the glass's extent, ClusteredLighting::uploadGrid, and cluster_depth_range.comp's reduction of
// the depth), joined with two words of a raster's work buffer where the raster reduced its own
// depth as it wrote it (the compute raster's finish; the reduction then does not run). Needs
// cluster_grid.glsl.
layout(std430, binding = ML_SSBO_RASTER_WORK) readonly buffer RasterWork { uint rasterWork[]; };
uniform uint u_rasterRangeWord;  // ~0u: no raster's words; else where the raster's two lie

// zNear, zFar, scale and bias, as grid.slicing holds them.
vec4 fittedSlicing() {
    float n = grid.tile.z, f = grid.tile.w;
    // Positive floats order like their bit patterns.
    uvec2 range = grid.reduction.xy;
    if (u_rasterRangeWord != ~0u)
        range = uvec2(min(range.x, rasterWork[u_rasterRangeWord]), max(range.y, rasterWork[u_rasterRangeWord + 1u]));
    if (range.x <= range.y) {
        n = uintBitsToFloat(range.x);
        f = uintBitsToFloat(range.y);
    }
    f = max(f, n * (1.0 + 1e-4) + 1e-6);
    float scale = float(grid.dims.z) / log(f / n);
    return vec4(n, f, scale, -log(n) * scale);
}
