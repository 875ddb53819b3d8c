// Per-pass timing. Each pass is a named scope: its name is its KHR_debug group and its row in
// the timing table. On real GPUs the times come from GL timestamp queries; on llvmpipe, whose
// queries do not reflect real cost (design.md), from a wall clock around glFinish.
#pragma once

#include <chrono>
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

class PassTimer {
public:
    PassTimer() = default;
    PassTimer(bool enabled, TimingClock clock) : enabled_(enabled), clock_(clock) {}
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
    // Waits for the frame's results; passes in the order they ran (repeated names summed).
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

    bool enabled_ = false;
    TimingClock clock_ = TimingClock::GpuQueries;
    std::vector<Pending> pending_;
    std::vector<GLuint> freeQueries_;
    std::vector<GLuint> allQueries_;
};

// Sum of the pass times.
double totalMilliseconds(const std::vector<PassTime>& times);

}  // namespace ml
