#include "scenes/animation_sampling.h"

#include <algorithm>
#include <cmath>

namespace ml {
namespace {

glm::quat quatAt(const float* p) { return glm::quat(p[3], p[0], p[1], p[2]); }  // glTF stores x, y, z, w

void storeQuat(const glm::quat& q, std::span<float> out) {
    out[0] = q.x;
    out[1] = q.y;
    out[2] = q.z;
    out[3] = q.w;
}

void normalizeQuat(std::span<float> out) {
    const glm::quat q = quatAt(out.data());
    const float length = glm::length(q);
    if (length > 0.0f && std::isfinite(length)) storeQuat(q / length, out);
    else storeQuat(glm::quat(1.0f, 0.0f, 0.0f, 0.0f), out);
}

}  // namespace

float clipTime(const AnimationClip& clip, double seconds) {
    if (!(clip.duration > 0.0f) || !std::isfinite(seconds)) return 0.0f;
    const double duration = clip.duration;
    const double wrapped = seconds - std::floor(seconds / duration) * duration;
    // Rounding can land exactly on the duration; the loop's start is the same pose in a looping clip.
    return wrapped >= duration ? 0.0f : static_cast<float>(wrapped);
}

glm::quat shortestSlerp(const glm::quat& a, const glm::quat& b, float t) {
    double d = glm::dot(glm::dquat(a), glm::dquat(b));
    glm::dquat end(b);
    if (d < 0.0) {
        end = -end;
        d = -d;
    }
    glm::dquat q;
    if (d > 0.9995) {
        q = glm::dquat(a) * (1.0 - t) + end * double(t);
    } else {
        const double theta0 = std::acos(d), theta = theta0 * t;
        const double s1 = std::sin(theta) / std::sin(theta0);
        const double s0 = std::cos(theta) - d * s1;
        q = glm::dquat(a) * s0 + end * s1;
    }
    return glm::quat(glm::normalize(q));
}

void sampleAnimation(const AnimationSampler& s, AnimatedProperty property, float t, std::span<float> out) {
    const std::size_t width = s.width, keys = s.times.size();
    const bool cubic = s.interpolation == Interpolation::CubicSpline;
    const bool rotation = property == AnimatedProperty::Rotation;
    // Key j's value (a cubic spline's sits between its in- and out-tangent).
    const auto value = [&](std::size_t j) { return &s.values[(cubic ? 3 * j + 1 : j) * width]; };
    const auto copy = [&](const float* p) { std::copy_n(p, width, out.begin()); };
    if (keys == 0) return;
    const std::size_t next = static_cast<std::size_t>(std::upper_bound(s.times.begin(), s.times.end(), t) - s.times.begin());
    if (next == 0) return copy(value(0));
    if (next == keys) return copy(value(keys - 1));
    const std::size_t k = next - 1;
    if (s.interpolation == Interpolation::Step) return copy(value(k));
    const float interval = s.times[next] - s.times[k];
    const float u = (t - s.times[k]) / interval;
    if (!cubic) {
        if (rotation) return storeQuat(shortestSlerp(quatAt(value(k)), quatAt(value(next)), u), out);
        const float* a = value(k);
        const float* b = value(next);
        for (std::size_t c = 0; c < width; ++c) out[c] = a[c] + u * (b[c] - a[c]);
        return;
    }
    // Hermite between v_k and v_k+1 with the out-tangent of k and the in-tangent of k+1, each
    // scaled by the interval (the tangents are per second, the curve's parameter per interval).
    const float u2 = u * u, u3 = u2 * u;
    const float h00 = 2.0f * u3 - 3.0f * u2 + 1.0f, h10 = u3 - 2.0f * u2 + u, h01 = -2.0f * u3 + 3.0f * u2, h11 = u3 - u2;
    const float* v0 = value(k);
    const float* v1 = value(next);
    const float* outTangent = v0 + width;     // k's out-tangent follows its value
    const float* inTangent = v1 - width;      // k+1's in-tangent precedes its value
    for (std::size_t c = 0; c < width; ++c)
        out[c] = h00 * v0[c] + h10 * interval * outTangent[c] + h01 * v1[c] + h11 * interval * inTangent[c];
    if (rotation) normalizeQuat(out);
}

}  // namespace ml
