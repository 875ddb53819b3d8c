// Tests of the procedural textures: sizes, opacity, determinism, tiling, and that they show
// something.
#include "scenes/procedural_textures.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace ml {
namespace {

using Generator = std::function<Image(int)>;

const std::vector<std::pair<std::string, Generator>>& generators() {
    static const std::vector<std::pair<std::string, Generator>> g{
        {"floorTiles", proctex::floorTiles}, {"stoneBlocks", proctex::stoneBlocks}, {"marble", proctex::marble},
        {"plaster", proctex::plaster},       {"fabric", proctex::fabric},           {"woodPlanks", proctex::woodPlanks}};
    return g;
}

int px(const Image& img, int x, int y, int c) { return int(img.rgba8[(std::size_t(y) * img.width + x) * 4 + c]); }

TEST(ProceduralTexturesTest, HaveTheRequestedSizeAndAreOpaque) {
    for (const auto& [name, make] : generators()) {
        const Image img = make(128);
        EXPECT_EQ(img.width, 128) << name;
        EXPECT_EQ(img.height, 128) << name;
        ASSERT_EQ(img.rgba8.size(), 128u * 128u * 4u) << name;
        EXPECT_FALSE(img.name.empty()) << name;
        bool opaque = true;
        for (std::size_t i = 3; i < img.rgba8.size(); i += 4) opaque = opaque && img.rgba8[i] == 255;
        EXPECT_TRUE(opaque) << name;
    }
}

TEST(ProceduralTexturesTest, AreDeterministic) {
    for (const auto& [name, make] : generators()) EXPECT_EQ(make(64).rgba8, make(64).rgba8) << name;
}

// The right edge runs on into the left edge (and bottom into top): the step across the wrap is no
// larger than typical steps between neighbouring interior columns (rows).
TEST(ProceduralTexturesTest, Tile) {
    for (const auto& [name, make] : generators()) {
        const Image img = make(256);
        const int w = img.width, h = img.height;
        auto colDiff = [&](int x0, int x1) {
            double d = 0;
            for (int y = 0; y < h; ++y)
                for (int c = 0; c < 3; ++c) d += std::abs(px(img, x0, y, c) - px(img, x1, y, c));
            return d / (3.0 * h);
        };
        auto rowDiff = [&](int y0, int y1) {
            double d = 0;
            for (int x = 0; x < w; ++x)
                for (int c = 0; c < 3; ++c) d += std::abs(px(img, x, y0, c) - px(img, x, y1, c));
            return d / (3.0 * w);
        };
        double interiorX = 0, interiorY = 0;
        for (int x = 0; x + 1 < w; ++x) interiorX += colDiff(x, x + 1);
        for (int y = 0; y + 1 < h; ++y) interiorY += rowDiff(y, y + 1);
        interiorX /= (w - 1);
        interiorY /= (h - 1);
        EXPECT_LE(colDiff(w - 1, 0), 3.0 * interiorX + 2.0) << name << " does not tile horizontally";
        EXPECT_LE(rowDiff(h - 1, 0), 3.0 * interiorY + 2.0) << name << " does not tile vertically";
    }
}

// A flat texture would be memory spent on nothing.
TEST(ProceduralTexturesTest, ShowAPattern) {
    for (const auto& [name, make] : generators()) {
        const Image img = make(128);
        int lo = 255, hi = 0;
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x) {
                lo = std::min(lo, px(img, x, y, 0));
                hi = std::max(hi, px(img, x, y, 0));
            }
        EXPECT_GT(hi - lo, 24) << name;
    }
}

}  // namespace
}  // namespace ml
