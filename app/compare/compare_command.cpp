#include "app/compare/compare_command.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "renderer/image/image.h"
#include "renderer/image/image_compare.h"

namespace ml::app {
namespace {

struct CompareOptions {
    std::string test, reference, diff, crop = "320x180";
    float gain = 8.0f;
};

bool isPfm(const std::string& path) { return path.size() > 4 && path.substr(path.size() - 4) == ".pfm"; }

// The pixel whose largest channel difference is the largest (the first such, row by row).
void worstPixel(const RgbaImage& test, const RgbaImage& reference, int& worstX, int& worstY) {
    int worst = -1;
    for (int y = 0; y < test.height; ++y)
        for (int x = 0; x < test.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const int d = std::abs(int(test.at(x, y)[c]) - int(reference.at(x, y)[c]));
                if (d > worst) worst = d, worstX = x, worstY = y;
            }
}

RgbaImage crop(const RgbaImage& image, int x0, int y0, int width, int height) {
    RgbaImage out{width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 4)};
    for (int y = 0; y < height; ++y)
        std::copy_n(image.at(x0, y0 + y), std::size_t(width) * 4, &out.pixels[std::size_t(y) * width * 4]);
    return out;
}

// Reference | test | difference, each cropped to width x height around the worst pixel.
RgbaImage comparisonStrip(const RgbaImage& test, const RgbaImage& reference, float gain, int width, int height) {
    width = std::min(width, test.width);
    height = std::min(height, test.height);
    int wx = 0, wy = 0;
    worstPixel(test, reference, wx, wy);
    const int x0 = std::clamp(wx - width / 2, 0, test.width - width), y0 = std::clamp(wy - height / 2, 0, test.height - height);
    const RgbaImage parts[] = {crop(reference, x0, y0, width, height), crop(test, x0, y0, width, height),
                               crop(differenceImage(test, reference, gain), x0, y0, width, height)};
    RgbaImage strip{3 * width, height, std::vector<std::uint8_t>(std::size_t(3) * width * height * 4)};
    for (int i = 0; i < 3; ++i)
        for (int y = 0; y < height; ++y)
            std::copy_n(parts[i].at(0, y), std::size_t(width) * 4, &strip.pixels[(std::size_t(y) * strip.width + i * width) * 4]);
    return strip;
}

int runCompare(const CompareOptions& o) {
    if (isPfm(o.test) != isPfm(o.reference)) throw std::invalid_argument("compare: give two PNGs or two PFMs, not one of each");
    ImageDifference d;
    double unit = 255.0;
    if (isPfm(o.test)) {
        if (!o.diff.empty()) throw std::invalid_argument("--diff: needs PNGs (the 8-bit output)");
        d = compareImages(readPfm(o.test), readPfm(o.reference));
        unit = 1.0;
    } else {
        const RgbaImage test = readPng(o.test), reference = readPng(o.reference);
        d = compareImages(test, reference);
        if (!o.diff.empty()) {
            const auto x = o.crop.find('x');
            int width = 0, height = 0;
            if (x == std::string::npos || std::sscanf(o.crop.c_str(), "%dx%d", &width, &height) != 2 || width < 1 || height < 1)
                throw std::invalid_argument("--crop '" + o.crop + "': expected WxH, e.g. 320x180");
            writePng(o.diff, comparisonStrip(test, reference, o.gain, width, height));
        }
    }
    // One line, key=value, for a person and for a script alike.
    std::printf("max_abs=%.6g%s bad_pixel_share=%.8f psnr_db=%.3f rmse=%.6g\n", d.maxAbs * unit, unit == 255.0 ? "/255" : "",
                d.badPixelShare, d.psnrDb, d.rmse);
    return 0;
}

}  // namespace

void addCompareCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<CompareOptions>();
    CLI::App* cmd = app.add_subcommand("compare", "compare an image with a reference: max error, share of pixels over 1/255, "
                                                  "PSNR (two PNGs or two PFMs of one size)");
    cmd->add_option("test", options->test, "the image under test (.png or .pfm)")->required()->check(CLI::ExistingFile);
    cmd->add_option("reference", options->reference, "the reference, e.g. naive's frame")->required()->check(CLI::ExistingFile);
    cmd->add_option("--diff", options->diff, "write reference | test | difference side by side, cropped around the worst pixel (PNG)");
    cmd->add_option("--crop", options->crop, "size of each part of --diff")->capture_default_str();
    cmd->add_option("--gain", options->gain, "difference scale of --diff")->capture_default_str();
    cmd->callback([options, &exitCode] { exitCode = runCompare(*options); });
}

}  // namespace ml::app
