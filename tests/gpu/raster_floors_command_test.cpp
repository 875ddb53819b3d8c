// `manylights raster-floors`: every probe timed per camera, the compute raster and its steps
// among them where the GPU runs it (llvmpipe does, by two passes of 32-bit atomics).
#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "gpu_test.h"

namespace ml::test {
namespace {

TEST(RasterFloorsCommand, TimesEveryProbeAndTheComputeRastersSteps) {
    std::string output;
    ASSERT_EQ(runManylights("raster-floors --scene atrium --detail 0.25 --size 160x90 --lights 16 --warmup 0 --timed-frames 2"
                            " --camera 'default;0,28,0.5,0,0,0,60'",
                            output),
              0)
        << output;
    std::istringstream lines(output);
    std::string line;
    ASSERT_TRUE(std::getline(lines, line));
    ASSERT_EQ(line.rfind("scene,detail,", 0), 0u) << line;
    std::map<std::string, int> rowsPerProbe;
    while (std::getline(lines, line)) {
        // Split at commas outside quotes (the camera and the renderer hold commas).
        std::vector<std::string> fields(1);
        bool quoted = false;
        for (char ch : line) {
            if (ch == '"') quoted = !quoted;
            else if (ch == ',' && !quoted) fields.emplace_back();
            else fields.back() += ch;
        }
        ASSERT_EQ(fields.size(), 16u) << line;
        EXPECT_GE(std::stod(fields[11]), 0.0) << line;  // ms
        ++rowsPerProbe[fields[10]];
    }
    for (const char* probe : {"clear-depth", "clear-ids", "clear-ids-compute", "fullscreen", "fullscreen-depth", "scene",
                              "scene-rop-ids", "scene-depth-only", "scene-no-raster", "scene-compute", "scene-compute.setup",
                              "scene-compute.tiles", "scene-compute.finish"})
        EXPECT_EQ(rowsPerProbe[probe], 2) << probe << " (one row per camera)\n" << output;
}

}  // namespace
}  // namespace ml::test
