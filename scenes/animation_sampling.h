// Keyframe interpolation as glTF 2.0 defines it (Appendix C, "Animation sampler interpolation
// modes"): STEP, LINEAR (rotations by spherical interpolation along the shorter arc) and
// CUBICSPLINE (Hermite, tangents scaled by the keyframe interval), the first key's value before
// it and the last key's after it.
#pragma once

#include <span>

#include "scenes/scene_animation.h"

namespace ml {

// A scene time in the clip, which loops: seconds mod duration, in [0, duration); 0 for a clip
// of no duration. Negative times wrap too (-0.25 in a 1 s clip is 0.75).
float clipTime(const AnimationClip& clip, double seconds);

// The sampler's value at clip time t: `out` holds sampler.width floats. A rotation (x, y, z, w)
// comes out unit length.
void sampleAnimation(const AnimationSampler& sampler, AnimatedProperty property, float t, std::span<float> out);

// glTF's slerp of unit quaternions, along the shorter arc (b negated where a . b < 0), as a
// normalised lerp where they are within about 1.8 degrees.
glm::quat shortestSlerp(const glm::quat& a, const glm::quat& b, float t);

}  // namespace ml
