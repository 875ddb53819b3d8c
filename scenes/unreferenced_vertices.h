// A glTF accessor may hold vertices that no index of its primitives uses (a shared buffer, an
// exporter's leftovers). They are not part of the scene: kept, they would widen its bounds (and
// with them the framing, the clip planes and the lights' volume), fill GPU buffers and be posed
// every frame. The loader drops them once every primitive is read.
#pragma once

#include "scenes/scene.h"

namespace ml {

// Removes the vertices no index references from every per-vertex stream (the vertices, tangents,
// TEXCOORD_1 and colours, and an animation's rest data, influences and morph deltas), keeping the
// order of the rest, and renumbers the indices. A deformed mesh none of whose vertices is drawn
// is dropped from the animation.
void dropUnreferencedVertices(Scene& scene);

}  // namespace ml
