// Automatic exposure (renderer/passes/auto_exposure_pass.h) against the CPU's metering of the
// same HDR frame: the log-average luminance of the lit pixels and the exposure that maps it to
// middle grey. The pass is one dispatch whose last workgroup to finish sums every tile's partial
// and sets the counter back; frames after the first must find it set back.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "gpu_test.h"

namespace ml::test {
namespace {

class AutoExposure : public GpuTest {};

struct Metering {
    double logAverage = 0.0;
    double litShare = 0.0;
};

// glsl/exposure_reduce.comp's metering, in double precision.
Metering meter(const FloatImage& hdr) {
    double sum = 0.0;
    std::size_t lit = 0;
    for (int y = 0; y < hdr.height; ++y)
        for (int x = 0; x < hdr.width; ++x) {
            const float* c = hdr.at(x, y);
            const float luminance = 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2];
            if (!(luminance > 1e-6f)) continue;
            sum += std::clamp(std::log2(double(luminance)), -64.0, 64.0);
            ++lit;
        }
    return {lit ? sum / double(lit) : 0.0, double(lit) / (double(hdr.width) * hdr.height)};
}

// At a size whose tiles end inside the frame (333x187: 6x3 tiles) and one of more tiles than the
// last workgroup has invocations (1100x1000: 288 tiles of 64x64); a second frame with other lights.
TEST_F(AutoExposure, OneDispatchMetersTheFrameAsTheCpuDoes) {
    const TestScene t = testScene("atrium", 64, 7);
    const TestScene dim = testScene("atrium", 8, 3);
    for (const auto& [width, height] : {std::pair{333, 187}, std::pair{1100, 1000}}) {
        FrameRenderer renderer(t.scene, t.lights, smallFrame(t.scene, width, height));
        renderer.setAutoExposure(true, 1.0f);
        for (int frame = 0; frame < 2; ++frame) {
            const std::string label = std::to_string(width) + "x" + std::to_string(height) + " frame " + std::to_string(frame);
            SCOPED_TRACE(label);
            if (frame == 1) renderer.setLights(dim.lights);
            renderer.render(0);
            const Metering cpu = meter(renderer.readHdr());
            const std::optional<AutoExposureReading> gpu = renderer.autoExposure();
            ASSERT_TRUE(gpu.has_value());
            ASSERT_GT(cpu.litShare, 0.1) << "the frame is lit";
            EXPECT_NEAR(gpu->litShare, cpu.litShare, 1e-6);
            EXPECT_NEAR(gpu->logAverage, cpu.logAverage, 1e-4);
            const double expected = std::exp2(std::clamp(std::log2(double(kAutoExposureKey)) - cpu.logAverage, -16.0, 16.0));
            EXPECT_NEAR(gpu->exposure / expected, 1.0, 1e-4);
        }
    }
}

}  // namespace
}  // namespace ml::test
