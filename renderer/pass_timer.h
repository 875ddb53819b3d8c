// Per-pass timing. Each pass is a named scope: its name is its KHR_debug group and its row in
// the timing table. On real GPUs the times come from GL timestamp queries; on llvmpipe, whose
// queries do not reflect real cost (design.md), from a wall clock around glFinish.
#pragma once

#include <chrono>
#include <deque>
#include <string>
#include <string_view>
#include <vector>

#include "renderer/gl/gl_handle.h"

namespace ml {

struct PassTime {
    std::string name;
    double milliseconds = 0.0;
};

enum class TimingClock { GpuQueries, WallClockAfterFinish };
const char* timingClockName(TimingClock clock);

// When a frame's GPU times are read. Wait: endFrame() blocks until the frame's queries are done,
// so the numbers belong to that frame (render, bench). Latest: endFrame() never blocks and returns
// the newest frame whose queries are done, typically 1-3 frames late, or nothing yet; the live
// view uses it so timing does not drain the CPU-GPU pipeline every frame.
enum class TimingReadback { Wait, Latest };

class PassTimer {
public:
    PassTimer() = default;
    PassTimer(bool enabled, TimingClock clock, TimingReadback readback = TimingReadback::Wait)
        : enabled_(enabled), clock_(clock), readback_(readback) {}
    ~PassTimer();
    PassTimer(const PassTimer&) = delete;
    PassTimer& operator=(const PassTimer&) = delete;

    class Scope {
    public:
        Scope(PassTimer& timer, std::string_view name);
        ~Scope();
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;

    private:
        PassTimer& timer_;
        gl::DebugGroup group_;
        std::size_t index_;
    };

    // Opens a timed, labelled pass that closes when the returned scope ends.
    [[nodiscard]] Scope pass(std::string_view name) { return Scope(*this, name); }

    void beginFrame();
    // Passes in the order they ran (repeated names summed). With TimingReadback::Wait, this
    // frame's; with Latest, the newest finished frame's (empty when none has finished yet).
    std::vector<PassTime> endFrame();

    bool enabled() const { return enabled_; }
    TimingClock clock() const { return clock_; }

private:
    struct Pending {
        std::string name;
        GLuint startQuery = 0, endQuery = 0;
        std::chrono::steady_clock::time_point start, end;
    };
    std::size_t begin(std::string_view name);
    void end(std::size_t index);
    GLuint takeQuery();
    std::vector<PassTime> collect(const std::vector<Pending>& frame) const;  // blocks until done
    void recycle(std::vector<Pending>& frame);
    std::vector<PassTime> newestFinishedFrame();

    // TimingReadback::Latest: beyond this many unfinished frames, endFrame() waits for the oldest.
    static constexpr std::size_t kMaxFramesInFlight = 4;

    bool enabled_ = false;
    TimingClock clock_ = TimingClock::GpuQueries;
    TimingReadback readback_ = TimingReadback::Wait;
    std::vector<Pending> pending_;
    std::deque<std::vector<Pending>> inFlight_;  // TimingReadback::Latest: oldest first
    std::vector<GLuint> freeQueries_;
    std::vector<GLuint> allQueries_;
};

// Sum of the pass times.
double totalMilliseconds(const std::vector<PassTime>& times);

}  // namespace ml
