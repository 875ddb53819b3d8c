// Procedural scenes: deterministic geometry built in code, no files needed.
#pragma once

#include "scenes/scene.h"

namespace ml {

// A Sponza-like courtyard: floor, two storeys of arched colonnades along both long sides, end
// walls and a few objects on the floor. detail scales tessellation; 1.0 gives 100k-300k triangles.
Scene makeAtrium(float detail = 1.0f);

// A 20 x 20 unit square at y = 0, facing +y: the simplest surface to check shading on.
Scene makePlane();

// A few boxes on a plane.
Scene makeBoxes();

}  // namespace ml
