// The binding points of glsl/include/bindings.h against what every GL 4.5 implementation has.
// Mesa's llvmpipe exposes more than the minimum, so a binding past it passes every test here
// and fails to compile on the GPU (NVIDIA: exactly 8 image units): this test is where it shows.
#include <fstream>
#include <set>
#include <regex>
#include <string>

#include <gtest/gtest.h>

namespace {

// GL 4.5's guaranteed minimums (the specification's table 23.60 onwards).
constexpr int kMinImageUnits = 8;           // GL_MAX_IMAGE_UNITS
constexpr int kMinTextureUnitsAStage = 16;  // GL_MAX_TEXTURE_IMAGE_UNITS (fragment and compute)
// The units past the minimum that bindings.h allows, each checked against the GPU where a scene
// needs it (SceneGpu refuses the scene in one line), and how many a stage must have for them.
const std::set<std::string> kUnitsPastTheMinimum = {"ML_TEX_TRANSMISSION", "ML_TEX_THICKNESS"};
constexpr int kTextureUnitsTheyNeed = 18;

TEST(BindingLimits, EveryImageAndTextureUnitExistsOnEveryGl45Implementation) {
    std::ifstream file(ML_BINDINGS_FILE);
    ASSERT_TRUE(file) << "cannot open bindings.h";
    const std::regex definition(R"(^#define (ML_(IMG|TEX)_[A-Z0-9_]+) ([0-9]+))");
    int images = 0, textures = 0;
    for (std::string line; std::getline(file, line);) {
        std::smatch match;
        if (!std::regex_search(line, match, definition)) continue;
        const int unit = std::stoi(match[3].str());
        if (match[2] == "IMG") {
            ++images;
            EXPECT_LT(unit, kMinImageUnits) << match[1] << " is image unit " << unit;
        } else {
            ++textures;
            const bool allowedPast = kUnitsPastTheMinimum.count(match[1].str()) != 0;
            EXPECT_LT(unit, allowedPast ? kTextureUnitsTheyNeed : kMinTextureUnitsAStage) << match[1] << " is texture unit " << unit;
        }
    }
    EXPECT_GT(images, 5);  // the pattern still finds the definitions
    EXPECT_GT(textures, 10);
}

}  // namespace
