// Procedural textures for the built-in scenes: deterministic, tileable (the right edge continues
// into the left, the bottom into the top), sRGB-encoded RGBA8 with opaque alpha.
#pragma once

#include "scenes/scene.h"

namespace ml::proctex {

// Square floor tiles, 8 x 8 per image, in a two-stone checker with dark mortar lines, per-tile
// value noise and fine grain.
Image floorTiles(int size);

// Ashlar: rows of stone blocks in running bond (4 blocks per row, 8 rows) with light mortar.
Image stoneBlocks(int size);

// Veined white marble.
Image marble(int size);

// Mottled lime plaster.
Image plaster(int size);

// Woven cloth, near white, to be tinted by a material's base colour factor.
Image fabric(int size);

// Wooden planks (8 per image) with grain and seams.
Image woodPlanks(int size);

}  // namespace ml::proctex
