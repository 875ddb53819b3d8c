// Procedural textures for the built-in scenes: deterministic, tileable (the right edge continues
// into the left, the bottom into the top), sRGB-encoded RGBA8 with opaque alpha; normal maps
// linear (Image::srgb false), foliage with a cut-out alpha.
#pragma once

#include "scenes/scene.h"

namespace ml::proctex {

// Square floor tiles, 8 x 8 per image, in a two-stone checker with dark mortar lines, per-tile
// value noise and fine grain.
Image floorTiles(int size);

// floorTiles' tangent-space normal map: tiles proud of the mortar, bevelled, grained.
Image floorTilesNormal(int size);

// Ashlar: rows of stone blocks in running bond (4 blocks per row, 8 rows) with light mortar.
Image stoneBlocks(int size);

// stoneBlocks' tangent-space normal map: sunken joints, chamfers, rough faces.
Image stoneBlocksNormal(int size);

// A leafy bush for alpha-tested cross quads: alpha 1 on leaves, 0 between; v = 0 is the top.
// Not tileable (clamp it).
Image foliage(int size);

// Veined white marble.
Image marble(int size);

// Mottled lime plaster.
Image plaster(int size);

// Woven cloth, near white, to be tinted by a material's base colour factor.
Image fabric(int size);

// Wooden planks (8 per image) with grain and seams.
Image woodPlanks(int size);

}  // namespace ml::proctex
