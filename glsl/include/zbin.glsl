// Z-binning (Drobot 2017, --assign zbin): lights sorted by view depth; per z-bin the first and
// last sorted index of the lights whose depth extent reaches the bin; per screen tile (the
// cluster grid's tiles) one bit per sorted light whose sphere reaches the tile's frustum.
// Needs bindings.h and cluster_grid.glsl. Built by glsl/zbin_assign.comp (ML_ZBIN_WRITABLE),
// read by shading through cluster_lists.glsl.
//
// Bins: ML_ZBIN_PER_SLICE per cluster slice, splitting each slice evenly in the grid's own
// depth mapping (log or linear, the fitted range included), so bins follow the slicing and are
// finer than it. Depths outside the sliced range clamp to the first or last bin, as slices do.

#ifdef ML_ZBIN_WRITABLE
#define ML_ZBIN_ACCESS
#else
#define ML_ZBIN_ACCESS readonly
#endif
// x: words per tile, y: visible (listed) lights
layout(std430, binding = ML_SSBO_ZBIN_PARAMS) ML_ZBIN_ACCESS buffer ZBinParams { uvec4 zbinParams; };
// x: first, y: last sorted index reaching the bin; first > last when none does
layout(std430, binding = ML_SSBO_ZBIN_RANGES) ML_ZBIN_ACCESS buffer ZBinRanges { uvec2 zbinRanges[]; };
layout(std430, binding = ML_SSBO_ZBIN_TILE_MASKS) ML_ZBIN_ACCESS buffer ZBinTileMasks { uint zbinTileMasks[]; };
layout(std430, binding = ML_SSBO_ZBIN_SORTED_LIGHTS) ML_ZBIN_ACCESS buffer ZBinSortedLights { uint zbinSortedLights[]; };

uint zbinCount() { return grid.dims.z * uint(ML_ZBIN_PER_SLICE); }

uint zbinForDepth(float z) {
    float f = grid.tile.y > 0.5 ? log(max(z, 1e-7)) : z;
    float b = floor((f * grid.slicing.z + grid.slicing.w) * float(ML_ZBIN_PER_SLICE));
    return uint(clamp(b, 0.0, float(zbinCount() - 1u)));
}

// Sorted lights in the bin's index range whose tile bit is set, one word (32 sorted lights) at
// a time: bits of word w of `tile` restricted to [range.x, range.y].
uint zbinWordBits(uint tile, uvec2 range, uint w) {
    uint bits = zbinTileMasks[tile * zbinParams.x + w];
    if (w == range.x >> 5) bits &= ~0u << (range.x & 31u);
    if (w == range.y >> 5) bits &= ~0u >> (31u - (range.y & 31u));
    return bits;
}
