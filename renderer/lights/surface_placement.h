// Where generated lights go in a scene file (--light-placement surfaces): near its surfaces, so
// that each one lights something, instead of uniformly through the bounding box, where in an
// interior most land inside walls or outside the building.
//
//   triangle  chosen with probability proportional to its area, and
//   point     uniform on the triangle (both renderer/scene/surface_samples.h);
//   offset    kSurfaceOffsetShare x the light's radius along the interpolated vertex normal (the
//             side the surface is lit from), so its sphere always reaches that surface.
//
// The same seed gives the same places on every machine (integer hashing, as generateLights), and
// a light keeps its colour and type whichever placement is chosen. Cost: one pass over the
// triangles for the table (O(T)), then O(log T) per light.
#pragma once

#include <cstdint>
#include <vector>

#include "renderer/lights/light_set.h"
#include "scenes/scene.h"

namespace ml {

inline constexpr float kSurfaceOffsetShare = 0.25f;

enum class LightPlacement { Volume, Surfaces };
const char* lightPlacementName(LightPlacement placement);
// "volume" or "surfaces"; throws std::invalid_argument naming --light-placement.
LightPlacement parseLightPlacement(const std::string& text);

// Moves the point and spot lights of `lights` onto `scene`'s surfaces (a scene without
// triangles of any area leaves them where they are).
void placeOnSurfaces(std::vector<Light>& lights, const Scene& scene, std::uint32_t seed);

// generateLights in the scene's light volume, placed as asked, then in Morton order of their
// places (renderer/lights/spatial_order.h): what render, view and bench light a frame with.
std::vector<Light> generateLights(const Scene& scene, const LightGeneration& generation, LightPlacement placement);

}  // namespace ml
