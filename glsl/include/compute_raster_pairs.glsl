// The compute raster's pair list (renderer/passes/compute_raster.h): (large triangle, screen
// tile) for the tile pass, listed by the binning and, for a large triangle of a few 8x8 tiles, by
// its setup invocation. Needs include/compute_raster.glsl, and rasterWork (coherent), pairs and
// u_pairCapacity declared.
//
// A triangle takes its pairs' slots with one atomic, in order: once one triangle's slots do not
// fit, no later one's do, so the pairs written are the slots before the first that did not fit.
// That one lowers the list's end (ML_RASTER_PAIR_END) to its first slot, and the tile pass reads
// no further: a slot past it holds an earlier frame's pair, whose triangle's record is stale.

// The first of `tiles` slots, or ~0u where they do not fit (the caller sends the triangle to
// the hardware).
uint rasterTakePairSlots(uint tiles) {
    uint first = atomicAdd(rasterWork[ML_RASTER_PAIR_COUNT], tiles);
    if (first + tiles > u_pairCapacity || first + tiles < first) {
        atomicMin(rasterWork[ML_RASTER_PAIR_END], first);
        return ~0u;
    }
    atomicMax(rasterWork[ML_RASTER_TILE_DISPATCH], min(first + tiles, 65535u));
    return first;
}
