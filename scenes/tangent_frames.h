// Per-vertex tangent frames for normal mapping, from positions, normals and a UV set.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "scenes/scene.h"

namespace ml {

// Index ranges (first index, index count; whole triangles) into Scene::indices.
using IndexRanges = std::vector<std::pair<std::size_t, std::size_t>>;

// Sets Scene::tangents (sized to the vertices first, (1,0,0,1) where unset) for every vertex the
// triangles of `indexRanges` use, from world-space positions, Vertex::normal and the UV set
// `texCoordSet` (0: Vertex::uv, 1: Scene::uv1, which must then hold one element per vertex).
//
// Each triangle contributes its UV-derivative tangent and bitangent, weighted by its area; a
// vertex's sum is made orthogonal to its normal (Gram-Schmidt) and w is the sign of the summed
// bitangent against cross(normal, tangent), glTF's convention. A triangle with degenerate UVs
// contributes nothing; a vertex with no usable tangent gets a unit vector orthogonal to its normal.
// Vertices equal in position, normal and UV share their sums (one vertex, as MikkTSpace welds them),
// so a file's duplicate vertices get the frame a re-export that merges them does.
//
// glTF names MikkTSpace for tangents a file leaves out. MikkTSpace splits a vertex where the
// tangent frame is discontinuous (UV seams, mirrored UV islands) and weights faces by angle; this
// per-vertex version shares one frame per vertex and weights by area. The two agree on planar and
// smoothly mapped surfaces and differ at UV seams and mirrored UVs, where a shared vertex here
// gets an averaged frame.
void generateTangents(Scene& scene, const IndexRanges& indexRanges, int texCoordSet);

}  // namespace ml
