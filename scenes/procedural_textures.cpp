#include "scenes/procedural_textures.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/gtc/constants.hpp>

namespace ml::proctex {

namespace {

// An integer hash (a murmur-style finaliser): the same bits on every platform, unlike <random>'s
// distributions.
std::uint32_t hash(std::uint32_t x, std::uint32_t y, std::uint32_t seed) {
    std::uint32_t h = x * 0x8da6b343u ^ y * 0xd8163841u ^ seed * 0xcb1ab31fu;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return h;
}

// In [0, 1).
float hashUnit(int x, int y, std::uint32_t seed) {
    return float(hash(std::uint32_t(x), std::uint32_t(y), seed) >> 8) * (1.0f / 16777216.0f);
}

int wrap(int i, int period) {
    const int m = i % period;
    return m < 0 ? m + period : m;
}

// Value noise on a lattice that repeats every `period` cells, in [0, 1).
float valueNoise(float x, float y, int period, std::uint32_t seed) {
    const float fx = std::floor(x), fy = std::floor(y);
    const int x0 = int(fx), y0 = int(fy);
    float tx = x - fx, ty = y - fy;
    tx = tx * tx * (3.0f - 2.0f * tx);
    ty = ty * ty * (3.0f - 2.0f * ty);
    auto at = [&](int i, int j) { return hashUnit(wrap(x0 + i, period), wrap(y0 + j, period), seed); };
    const float a = at(0, 0) + (at(1, 0) - at(0, 0)) * tx;
    const float b = at(0, 1) + (at(1, 1) - at(0, 1)) * tx;
    return a + (b - a) * ty;
}

// Fractal sum of value noise over an image of `size` pixels; `cells` lattice cells across the
// image at the coarsest octave, so it tiles with the image. Roughly in [0, 1).
float fbm(float px, float py, int size, int cells, int octaves, std::uint32_t seed) {
    float sum = 0.0f, amp = 0.5f, norm = 0.0f;
    int c = cells;
    for (int o = 0; o < octaves; ++o) {
        const float k = float(c) / float(size);
        sum += amp * valueNoise(px * k, py * k, c, seed + 977u * std::uint32_t(o));
        norm += amp;
        amp *= 0.5f;
        c *= 2;
    }
    return sum / norm;
}

std::uint8_t encodeSrgb(float linear) {
    const float c = std::clamp(linear, 0.0f, 1.0f);
    const float s = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    return static_cast<std::uint8_t>(std::lround(s * 255.0f));
}

// Writes linear RGB, sRGB-encoded, and an opaque alpha at pixel (x, y) of a square image.
void putOpaqueSrgb(Image& img, int x, int y, const glm::vec3& c) {
    std::uint8_t* p = &img.rgba8[(std::size_t(y) * std::size_t(img.width) + std::size_t(x)) * 4];
    p[0] = encodeSrgb(c.r);
    p[1] = encodeSrgb(c.g);
    p[2] = encodeSrgb(c.b);
    p[3] = 255;
}

// Fills an image from a function of the pixel centre giving linear RGB.
Image makeImage(const char* name, int size, const std::function<glm::vec3(int, int)>& shade) {
    Image img;
    img.name = name;
    img.width = size;
    img.height = size;
    img.rgba8.resize(std::size_t(size) * std::size_t(size) * 4);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) putOpaqueSrgb(img, x, y, shade(x, y));
    }
    return img;
}

float smoothstep(float e0, float e1, float x) {
    const float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

// A tangent-space normal map (linear RGBA8, glTF's encoding n * 0.5 + 0.5) of a tileable height
// field given in pixels of height per pixel: x follows +u, y follows +v (down the image rows),
// z out of the surface.
Image normalMapFromHeight(const char* name, int size, const std::function<float(float, float)>& height) {
    Image img;
    img.name = name;
    img.width = size;
    img.height = size;
    img.srgb = false;
    img.rgba8.resize(std::size_t(size) * std::size_t(size) * 4);
    std::vector<float> h(std::size_t(size) * std::size_t(size));
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) h[std::size_t(y) * std::size_t(size) + std::size_t(x)] = height(float(x) + 0.5f, float(y) + 0.5f);
    const auto at = [&](int x, int y) { return h[std::size_t(wrap(y, size)) * std::size_t(size) + std::size_t(wrap(x, size))]; };
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const float dx = 0.5f * (at(x + 1, y) - at(x - 1, y));
            const float dy = 0.5f * (at(x, y + 1) - at(x, y - 1));
            const glm::vec3 n = glm::normalize(glm::vec3(-dx, -dy, 1.0f));
            std::uint8_t* p = &img.rgba8[(std::size_t(y) * std::size_t(size) + std::size_t(x)) * 4];
            for (int c = 0; c < 3; ++c) p[c] = static_cast<std::uint8_t>(std::lround((n[c] * 0.5f + 0.5f) * 255.0f));
            p[3] = 255;
        }
    }
    return img;
}

// Where a pixel centre falls in a pattern of rectangular cells: the cell and the distance to its
// nearest edge, in pixels.
struct CellHit {
    int column = 0, row = 0;
    float edge = 0.0f;
};

// floorTiles' 8 x 8 tiles.
CellHit floorTileAt(float px, float py, float cell) {
    CellHit h;
    h.column = int(px / cell);
    h.row = int(py / cell);
    const float lx = px - float(h.column) * cell, ly = py - float(h.row) * cell;
    h.edge = std::min(std::min(lx, cell - lx), std::min(ly, cell - ly));
    return h;
}

// stoneBlocks' running bond: each row shifted by half a block from the one above.
CellHit stoneBlockAt(float px, float py, float bw, float bh, int perRow) {
    CellHit h;
    h.row = int(py / bh);
    const float shifted = px + ((h.row % 2) ? 0.5f * bw : 0.0f);
    h.column = int(shifted / bw) % perRow;
    const float lx = std::fmod(shifted, bw), ly = py - float(h.row) * bh;
    h.edge = std::min(std::min(lx, bw - lx), std::min(ly, bh - ly));
    return h;
}

constexpr int kFloorTiles = 8;
constexpr int kBlocksPerRow = 4, kBlockRows = 8;

}  // namespace

Image floorTiles(int size) {
    const float cell = float(size) / float(kFloorTiles);
    const float mortar = std::max(1.0f, cell / 40.0f);  // half-width in pixels
    const glm::vec3 cream{0.58f, 0.49f, 0.35f};
    const glm::vec3 rose{0.36f, 0.20f, 0.13f};
    const glm::vec3 mortarColour{0.10f, 0.09f, 0.08f};
    return makeImage("floor_tiles", size, [&](int x, int y) {
        const float px = float(x) + 0.5f, py = float(y) + 0.5f;
        const CellHit tile = floorTileAt(px, py, cell);
        const int tx = tile.column, ty = tile.row;
        const float edge = tile.edge;
        glm::vec3 stone = ((tx + ty) % 2 == 0) ? cream : rose;
        stone *= 0.8f + 0.4f * hashUnit(tx, ty, 11u);                        // per-tile value
        stone *= 0.75f + 0.5f * fbm(px, py, size, 16, 4, 12u);               // grain
        stone *= 0.85f + 0.15f * smoothstep(mortar, mortar + cell * 0.08f, edge);  // worn edges
        const float m = smoothstep(mortar + 0.5f, mortar - 0.5f, edge);
        return glm::mix(stone, mortarColour, m);
    });
}

Image floorTilesNormal(int size) {
    const float cell = float(size) / float(kFloorTiles);
    const float mortar = std::max(1.0f, cell / 40.0f);
    return normalMapFromHeight("floor_tiles_normal", size, [&](float px, float py) {
        const CellHit tile = floorTileAt(px, py, cell);
        // Tiles stand 2 px proud of the mortar with rounded edges; a little surface grain.
        const float bevel = smoothstep(mortar - 0.5f, mortar + cell * 0.06f, tile.edge);
        return 2.0f * bevel + 0.6f * fbm(px, py, size, 32, 3, 13u);
    });
}

Image stoneBlocks(int size) {
    const int perRow = kBlocksPerRow, rows = kBlockRows;
    const float bw = float(size) / float(perRow), bh = float(size) / float(rows);
    const float mortar = std::max(1.0f, bh / 24.0f);
    const glm::vec3 sand{0.47f, 0.39f, 0.28f};
    const glm::vec3 mortarColour{0.30f, 0.28f, 0.24f};
    return makeImage("stone_blocks", size, [&](int x, int y) {
        const float px = float(x) + 0.5f, py = float(y) + 0.5f;
        const CellHit block = stoneBlockAt(px, py, bw, bh, perRow);
        const int row = block.row, col = block.column;
        const float edge = block.edge;
        glm::vec3 stone = sand * (0.8f + 0.35f * hashUnit(col, row, 21u));
        stone.r *= 0.95f + 0.1f * hashUnit(col, row, 22u);  // slight hue shift per block
        stone *= 0.7f + 0.6f * fbm(px, py, size, 8, 5, 23u);
        stone *= 0.8f + 0.2f * smoothstep(mortar, mortar + 4.0f, edge);
        const float m = smoothstep(mortar + 0.5f, mortar - 0.5f, edge);
        return glm::mix(stone, mortarColour, m);
    });
}

Image stoneBlocksNormal(int size) {
    const float bw = float(size) / float(kBlocksPerRow), bh = float(size) / float(kBlockRows);
    const float mortar = std::max(1.0f, bh / 24.0f);
    return normalMapFromHeight("stone_blocks_normal", size, [&](float px, float py) {
        const CellHit block = stoneBlockAt(px, py, bw, bh, kBlocksPerRow);
        // Rough-hewn faces: deep mortar joints, chamfered edges, a rough face per block.
        const float chamfer = smoothstep(mortar - 0.5f, mortar + 3.0f, block.edge);
        return 2.5f * chamfer + 2.0f * chamfer * fbm(px, py, size, 8, 5, 24u);
    });
}

Image foliage(int size) {
    Image img;
    img.name = "foliage";
    img.width = size;
    img.height = size;
    img.rgba8.assign(std::size_t(size) * std::size_t(size) * 4, 0);
    // Leaves: ellipses scattered over a bush's silhouette (wider at the bottom), each its own shade;
    // alpha is 1 on a leaf and 0 between them, for alphaMode MASK.
    const int leaves = 420;
    const float s = float(size);
    for (int i = 0; i < leaves; ++i) {
        const float v = 0.08f + 0.9f * std::sqrt(hashUnit(i, 0, 71u));  // denser towards the bottom
        const float halfWidth = 0.12f + 0.36f * v;
        const float cx = s * (0.5f + halfWidth * (2.0f * hashUnit(i, 1, 71u) - 1.0f)), cy = s * v;
        const float angle = glm::two_pi<float>() * hashUnit(i, 2, 71u);
        const float length = s * (0.035f + 0.03f * hashUnit(i, 3, 71u)), width = length * 0.45f;
        const glm::vec3 green = glm::mix(glm::vec3(0.05f, 0.16f, 0.03f), glm::vec3(0.20f, 0.42f, 0.08f), hashUnit(i, 4, 71u));
        const float ca = std::cos(angle), sa = std::sin(angle);
        const int r = int(length) + 1;
        for (int y = std::max(0, int(cy) - r); y <= std::min(size - 1, int(cy) + r); ++y) {
            for (int x = std::max(0, int(cx) - r); x <= std::min(size - 1, int(cx) + r); ++x) {
                const float dx = float(x) + 0.5f - cx, dy = float(y) + 0.5f - cy;
                const float along = (dx * ca + dy * sa) / length, across = (-dx * sa + dy * ca) / width;
                const float d = along * along + across * across;
                if (d > 1.0f) continue;
                // Lighter towards the tip, darker at the rim.
                putOpaqueSrgb(img, x, y, green * (0.75f + 0.25f * (1.0f - d)) * (0.8f + 0.2f * along));
            }
        }
    }
    return img;
}

Image marble(int size) {
    const glm::vec3 white{0.80f, 0.77f, 0.70f};
    const glm::vec3 vein{0.33f, 0.31f, 0.29f};
    return makeImage("marble", size, [&](int x, int y) {
        const float px = float(x) + 0.5f, py = float(y) + 0.5f;
        const float turbulence = fbm(px, py, size, 4, 5, 31u);
        // Integer wave numbers across the image keep the veins tileable.
        const float phase = glm::two_pi<float>() * (2.0f * px + py) / float(size) + 9.0f * turbulence;
        const float v = std::pow(1.0f - std::abs(std::sin(phase)), 10.0f);
        glm::vec3 c = white * (0.9f + 0.2f * fbm(px, py, size, 16, 3, 32u));
        return glm::mix(c, vein, 0.75f * v);
    });
}

Image plaster(int size) {
    const glm::vec3 ochre{0.72f, 0.55f, 0.36f};
    return makeImage("plaster", size, [&](int x, int y) {
        const float px = float(x) + 0.5f, py = float(y) + 0.5f;
        const float mottle = fbm(px, py, size, 4, 6, 41u);
        const float stain = smoothstep(0.55f, 0.75f, fbm(px, py, size, 2, 4, 42u));
        glm::vec3 c = ochre * (0.55f + 0.9f * mottle);
        return c * (1.0f - 0.3f * stain);
    });
}

Image fabric(int size) {
    const int thread = std::max(2, size / 64);  // pixels per thread
    return makeImage("fabric", size, [&](int x, int y) {
        const int cx = x / thread, cy = y / thread;
        const bool warpOnTop = ((cx + cy) % 2) == 0;  // plain weave
        const float along = warpOnTop ? float(y % thread) : float(x % thread);
        const float across = warpOnTop ? float(x % thread) : float(y % thread);
        const float t = (across + 0.5f) / float(thread);
        float shade = 0.55f + 0.45f * std::sin(glm::pi<float>() * t);  // round thread
        shade *= 0.9f + 0.1f * std::cos(glm::two_pi<float>() * (along + 0.5f) / float(thread));
        shade *= 0.85f + 0.3f * fbm(float(x), float(y), size, 8, 3, 51u);
        // Two woven stripes per image, a little brighter.
        const float band = std::fmod(float(y) + 0.5f, float(size) / 2.0f) / float(size);
        if (band > 0.40f && band < 0.44f) shade *= 1.25f;
        return glm::vec3(0.78f) * shade;
    });
}

Image woodPlanks(int size) {
    const int planks = 8;
    const float ph = float(size) / float(planks);
    const glm::vec3 light{0.42f, 0.25f, 0.12f};
    const glm::vec3 dark{0.20f, 0.10f, 0.045f};
    return makeImage("wood_planks", size, [&](int x, int y) {
        const float px = float(x) + 0.5f, py = float(y) + 0.5f;
        const int plank = int(py / ph);
        const float ly = py - float(plank) * ph;
        // Grain: rings stretched along x, disturbed by noise; each plank has its own offset.
        const float offset = 50.0f * hashUnit(plank, 0, 61u);
        const float g = fbm(px, py * 4.0f, size, 4, 4, 62u + std::uint32_t(plank));
        const float ring = 0.5f + 0.5f * std::sin((ly + offset + 24.0f * g) * 0.9f);
        glm::vec3 c = glm::mix(dark, light, 0.35f + 0.65f * ring);
        c *= 0.85f + 0.3f * hashUnit(plank, 1, 63u);
        // Seams between planks, and one butt joint per plank.
        const float seamY = std::min(ly, ph - ly);
        const float joint = std::fmod(px - float(size) * hashUnit(plank, 2, 64u) + float(size), float(size));
        const float seamX = std::min(joint, float(size) - joint);
        if (seamY < 1.0f || seamX < 1.0f) c *= 0.35f;
        return c;
    });
}

}  // namespace ml::proctex
