// `render --timing-csv F.csv`: one row per frame of a sequence, so a clip along a camera path
// doubles as a benchmark along it. Column names are the bench's where they mean the same
// (frame_index, clock, frame_ms, wall_ms, pass_<name>_ms; docs/bench/README.md), plus the
// camera of the frame:
//
//   frame_index,eye_x,eye_y,eye_z,target_x,target_y,target_z,fovy,clock,frame_ms,wall_ms,pass_..._ms,...
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "renderer/camera/camera.h"
#include "renderer/pass_timer.h"

namespace ml::app {

class SequenceTiming {
public:
    explicit SequenceTiming(TimingClock clock) : clock_(clock) {}

    // `wallMs`: the frame's render call up to glFinish, as the bench's wall_ms.
    void add(std::uint32_t frame, const Camera& camera, const std::vector<PassTime>& passes, double wallMs);
    // Through a temporary file and a rename; throws std::runtime_error naming the path.
    void writeCsv(const std::string& path) const;
    // Per-pass means over the frames (for --time), "total" last.
    std::vector<PassTime> meanPasses() const;

private:
    struct Row {
        std::uint32_t frame;
        Camera camera;
        std::vector<PassTime> passes;
        double wallMs;
    };
    TimingClock clock_;
    std::vector<Row> rows_;
    std::vector<std::string> passNames_;  // in the order first seen
};

}  // namespace ml::app
