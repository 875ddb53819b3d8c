// Named sets of `bench --camera` values, so a sweep over a fixed set of views can be asked for
// by name and every run measures the same cameras:
//
//   --camera atrium-set     (also as "camera": "atrium-set" in a sweep file)
//
// expands, in order, to the atrium's default view; a low view along the ground-floor gallery
// (z = -6.3); straight down from 28 m above the roof; across the courtyard from a corner. These
// are issue 17's cameras: the raster, assignment and lighting costs differ most between them
// (the roof view sees every floor's lights in few clusters).
//
//   --camera atrium-above   two views straight down into the courtyard, from just above and
//                           from just under the roof line, that see nearly every light of the
//                           volume: the light assignment's largest lists (issue 64)
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace ml::app {

// The set's camera values, or nullopt where `name` names no set.
std::optional<std::vector<std::string>> namedCameraSet(const std::string& name);

// "atrium-set", ... for help texts.
std::string cameraSetNames();

}  // namespace ml::app
