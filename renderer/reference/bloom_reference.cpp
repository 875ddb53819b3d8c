#include "renderer/reference/bloom_reference.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ml {

glm::vec3 bloomBrightPart(glm::vec3 c, float threshold) {
    const float lum = glm::dot(c, glm::vec3(0.2126f, 0.7152f, 0.0722f));
    return lum > threshold ? c * ((lum - threshold) / lum) : glm::vec3(0.0f);
}

namespace {
// A plane of colours in GL's row order (row 0 at the bottom), as the shaders index it.
struct Plane {
    int width = 0, height = 0;
    std::vector<glm::vec3> texels;
    glm::vec3& at(int x, int y) { return texels[static_cast<std::size_t>(y) * width + x]; }
    glm::vec3 clamped(int x, int y) const {
        x = std::clamp(x, 0, width - 1);
        y = std::clamp(y, 0, height - 1);
        return texels[static_cast<std::size_t>(y) * width + x];
    }
};

Plane blur(const Plane& in, bool vertical) {
    const auto w = bloomKernel();
    Plane out{in.width, in.height, std::vector<glm::vec3>(in.texels.size())};
    const int dx = vertical ? 0 : 1, dy = vertical ? 1 : 0;
    for (int y = 0; y < in.height; ++y)
        for (int x = 0; x < in.width; ++x) {
            glm::vec3 sum = w[0] * in.clamped(x, y);
            for (int i = 1; i <= ML_BLOOM_RADIUS; ++i)
                sum += w[i] * (in.clamped(x + i * dx, y + i * dy) + in.clamped(x - i * dx, y - i * dy));
            out.at(x, y) = sum;
        }
    return out;
}
}  // namespace

FloatImage bloomReference(const FloatImage& hdr, const BloomSettings& s) {
    if (!s.enabled) return hdr;
    const int w = hdr.width, h = hdr.height;
    Plane full{w, h, std::vector<glm::vec3>(static_cast<std::size_t>(w) * h)};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float* c = hdr.at(x, h - 1 - y);
            full.at(x, y) = glm::vec3(c[0], c[1], c[2]);
        }
    Plane half{(w + 1) / 2, (h + 1) / 2, {}};
    half.texels.resize(static_cast<std::size_t>(half.width) * half.height);
    for (int y = 0; y < half.height; ++y)
        for (int x = 0; x < half.width; ++x) {
            glm::vec3 sum = bloomBrightPart(full.clamped(2 * x, 2 * y), s.threshold);
            sum += bloomBrightPart(full.clamped(2 * x + 1, 2 * y), s.threshold);
            sum += bloomBrightPart(full.clamped(2 * x, 2 * y + 1), s.threshold);
            sum += bloomBrightPart(full.clamped(2 * x + 1, 2 * y + 1), s.threshold);
            half.at(x, y) = sum * 0.25f;
        }
    const Plane blurred = blur(blur(half, false), true);

    FloatImage out = hdr;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const glm::vec2 t = (glm::vec2(x, y) + 0.5f) * 0.5f - 0.5f;
            const int x0 = static_cast<int>(std::floor(t.x)), y0 = static_cast<int>(std::floor(t.y));
            const glm::vec2 f = t - glm::vec2(x0, y0);
            const glm::vec3 below = blurred.clamped(x0, y0) * (1.0f - f.x) + blurred.clamped(x0 + 1, y0) * f.x;
            const glm::vec3 above = blurred.clamped(x0, y0 + 1) * (1.0f - f.x) + blurred.clamped(x0 + 1, y0 + 1) * f.x;
            const glm::vec3 bloom = below * (1.0f - f.y) + above * f.y;
            float* c = &out.pixels[(static_cast<std::size_t>(h - 1 - y) * w + x) * 3];
            for (int i = 0; i < 3; ++i) c[i] += s.strength * bloom[i];
        }
    return out;
}

}  // namespace ml
