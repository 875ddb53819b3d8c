// --material-variant on the commands (render, view, bench, info) and the view panel's variant
// (--panel material-variant=NAME, as if chosen in its combo): on a two-variant file the tests
// write, each command draws the variant asked for, and a variant the file lacks, or a file without
// variants, is one line naming the value and what there is.
#include <algorithm>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "renderer/image/image.h"
#include "renderer/image/image_compare.h"
#include "tests/gpu/gpu_test.h"
#include "tests/scenes/gltf_test_files.h"

namespace ml::test {
namespace {

using namespace gltf_test;

// A red wall without mappings behind a quad whose variants "Leaf" and "Sea" make it green and blue.
std::string writeVariantsFile(const fs::path& dir) {
    Gltf g;
    for (const glm::vec4& c : {glm::vec4(0.8f, 0.1f, 0.1f, 1.0f), glm::vec4(0.1f, 0.8f, 0.1f, 1.0f), glm::vec4(0.1f, 0.1f, 0.8f, 1.0f)})
        colourMaterial(g, c, "OPAQUE");
    g.doc["extensionsUsed"] = {"KHR_materials_variants"};
    g.doc["extensions"]["KHR_materials_variants"]["variants"] = json::array({{{"name", "Leaf"}}, {{"name", "Sea"}}});
    json quad = square(g, 0.0f, 1.0f, 0);
    quad["extensions"]["KHR_materials_variants"]["mappings"] =
        json::array({{{"material", 1}, {"variants", {0}}}, {{"material", 2}, {"variants", {1}}}});
    g.scene({g.node({{"mesh", g.mesh({square(g, -0.5f, 3.0f, 0), quad})}})});
    return g.writeGlb(dir, "variants").string();
}

const std::string kFrame = " --size 96x54 --lights 16 --seed 2 --camera 0,0,4,0,0,0,60 --exposure 0 --method deferred";

// The middle pixel's brightest channel: 0 red, 1 green, 2 blue.
int middleChannel(const RgbaImage& image) {
    const std::uint8_t* p = &image.pixels[(static_cast<std::size_t>(image.height / 2) * image.width + image.width / 2) * 4];
    return static_cast<int>(std::max_element(p, p + 3) - p);
}

TEST(MaterialVariantCommand, RenderDrawsTheVariantAndBadNamesAreOneLine) {
    const fs::path dir = testDir();
    const std::string file = writeVariantsFile(dir);
    std::string output;
    int expected = 0;
    for (const std::string variant : {"", "Leaf", "Sea", "default"}) {
        const std::string out = (dir / ("render_" + (variant.empty() ? "none" : variant) + ".png")).string();
        const std::string flag = variant.empty() ? "" : " --material-variant " + variant;
        ASSERT_EQ(runManylights("render --scene " + file + kFrame + flag + " --out " + out, output), 0) << output;
        EXPECT_EQ(middleChannel(readPng(out)), variant == "default" ? 0 : expected++) << variant;
    }
    EXPECT_EQ(readPng((dir / "render_none.png").string()).pixels, readPng((dir / "render_default.png").string()).pixels);

    for (const auto& [args, culprits] : std::vector<std::pair<std::string, std::vector<std::string>>>{
             {"render --out /dev/null --scene " + file + " --material-variant Moss",
              {"--material-variant 'Moss'", "no such variant", "2 variants: 'Leaf', 'Sea'"}},
             {"render --out /dev/null --scene boxes --material-variant Leaf",
              {"--material-variant 'Leaf'", "no material variants (KHR_materials_variants)"}},
             {"bench --scene " + file + " --size 64x36 --lights 4 --warmup 0 --timed-frames 1 --out " + dir.string() +
                  " --material-variant Moss",
              {"--material-variant 'Moss'", "'Leaf', 'Sea'"}},
             {"info " + file + " --material-variant leaf", {"--material-variant 'leaf'", "'Leaf', 'Sea'"}}}) {
        EXPECT_NE(runManylights(args, output), 0) << args;
        for (const std::string& culprit : culprits) EXPECT_NE(output.find(culprit), std::string::npos) << args << ": " << output;
        // bench goes on past a failed point, its progress lines around the point's one-line error.
        if (args.rfind("bench", 0) != 0) {
            EXPECT_EQ(std::count(output.begin(), output.end(), '\n'), 1) << output;
        }
    }
}

TEST(MaterialVariantCommand, InfoListsTheVariants) {
    const fs::path dir = testDir();
    const std::string file = writeVariantsFile(dir);
    std::string output;
    ASSERT_EQ(runManylights("info " + file + " --material-variant Sea", output), 0) << output;
    for (const char* line : {"material variants (KHR_materials_variants): 2", "  0 'Leaf'", "  1 'Sea'", "draws 'Sea'"})
        EXPECT_NE(output.find(line), std::string::npos) << line << " in: " << output;
    EXPECT_EQ(output.find("not modelled"), std::string::npos) << output;
    ASSERT_EQ(runManylights("info boxes", output), 0) << output;
    EXPECT_NE(output.find("material variants (KHR_materials_variants): none"), std::string::npos) << output;
}

// The view starts on --material-variant's variant, and the panel's choice (rebuilding the
// renderer on the remapped scene) gives the frame `render --material-variant` gives.
TEST(MaterialVariantCommand, ViewDrawsTheFlagsAndThePanelsVariant) {
    REQUIRE_XVFB();
    const fs::path dir = testDir();
    const std::string file = writeVariantsFile(dir);
    const std::string common = "--scene " + file + kFrame + " --frames 3";
    std::string output;
    for (const auto& [name, viewFlags, renderFlags] : std::vector<std::tuple<std::string, std::string, std::string>>{
             {"flag", "--material-variant Leaf", "--material-variant Leaf"},
             {"panel", "--material-variant Leaf --panel material-variant=Sea", "--material-variant Sea"},
             {"back", "--material-variant Sea --panel material-variant=default", ""}}) {
        const std::string view = (dir / ("view_" + name + ".png")).string(), render = (dir / ("render_" + name + ".png")).string();
        ASSERT_EQ(runViewUnderXvfb(common + " " + viewFlags + " --screenshot " + view, output), 0) << output;
        ASSERT_EQ(runManylights("render " + common + " " + renderFlags + " --out " + render, output), 0) << output;
        const RgbaImage a = readPng(view), b = readPng(render);
        EXPECT_LE(compareImages(a, b).maxAbs, 1.0 / 255.0 + 1e-9) << name << ": images in " << writeFailureImages(name, a, b);
    }
    EXPECT_EQ(middleChannel(readPng((dir / "view_panel.png").string())), 2);
    EXPECT_NE(runViewUnderXvfb(common + " --panel material-variant=Moss", output), 0);
    EXPECT_NE(output.find("--panel 'material-variant=Moss'"), std::string::npos) << output;
}

}  // namespace
}  // namespace ml::test
