#include "renderer/pass_timer.h"

#include <algorithm>
#include <limits>

namespace ml {

const char* timingClockName(TimingClock clock) {
    return clock == TimingClock::GpuQueries ? "GPU timer queries" : "wall clock after glFinish";
}

PassTimer::~PassTimer() {
    if (!allQueries_.empty()) glDeleteQueries(static_cast<GLsizei>(allQueries_.size()), allQueries_.data());
}

PassTimer::Scope::Scope(PassTimer& timer, std::string_view name)
    : timer_(timer), group_(name), index_(timer.begin(name)) {}

PassTimer::Scope::~Scope() { timer_.end(index_); }

GLuint PassTimer::takeQuery() {
    if (freeQueries_.empty()) {
        GLuint id = 0;
        glCreateQueries(GL_TIMESTAMP, 1, &id);
        allQueries_.push_back(id);
        return id;
    }
    const GLuint id = freeQueries_.back();
    freeQueries_.pop_back();
    return id;
}

void PassTimer::recycle(std::vector<Pending>& frame) {
    for (const Pending& p : frame) {
        if (p.startQuery) freeQueries_.push_back(p.startQuery);
        if (p.endQuery) freeQueries_.push_back(p.endQuery);
    }
    frame.clear();
}

void PassTimer::beginFrame() { recycle(pending_); }

std::size_t PassTimer::begin(std::string_view name) {
    if (!enabled_) return 0;
    Pending p;
    p.name = std::string(name);
    if (clock_ == TimingClock::GpuQueries) {
        p.startQuery = takeQuery();
        glQueryCounter(p.startQuery, GL_TIMESTAMP);
    } else {
        glFinish();
        p.start = std::chrono::steady_clock::now();
    }
    pending_.push_back(std::move(p));
    return pending_.size() - 1;
}

void PassTimer::end(std::size_t index) {
    if (!enabled_) return;
    Pending& p = pending_[index];
    if (clock_ == TimingClock::GpuQueries) {
        p.endQuery = takeQuery();
        glQueryCounter(p.endQuery, GL_TIMESTAMP);
    } else {
        glFinish();
        p.end = std::chrono::steady_clock::now();
    }
}

std::vector<PassTime> PassTimer::endFrame() {
    if (!enabled_) return {};
    // The wall clock has its numbers already (it waited with glFinish around each pass).
    if (readback_ == TimingReadback::Latest && clock_ == TimingClock::GpuQueries) return newestFinishedFrame();
    return collect(pending_);
}

std::vector<PassTime> PassTimer::newestFinishedFrame() {
    inFlight_.push_back(std::move(pending_));
    pending_.clear();
    std::vector<PassTime> newest;
    while (!inFlight_.empty()) {
        std::vector<Pending>& oldest = inFlight_.front();
        GLint available = GL_TRUE;
        // Timestamps complete in submission order: the frame's last query done means all are.
        if (!oldest.empty()) glGetQueryObjectiv(oldest.back().endQuery, GL_QUERY_RESULT_AVAILABLE, &available);
        if (!available && inFlight_.size() <= kMaxFramesInFlight) break;
        newest = collect(oldest);
        recycle(oldest);
        inFlight_.pop_front();
    }
    return newest;
}

std::vector<PassTime> PassTimer::collect(const std::vector<Pending>& frame) const {
    std::vector<PassTime> out;
    for (const Pending& p : frame) {
        double ms = 0.0;
        if (clock_ == TimingClock::GpuQueries) {
            GLuint64 t0 = 0, t1 = 0;
            glGetQueryObjectui64v(p.startQuery, GL_QUERY_RESULT, &t0);
            glGetQueryObjectui64v(p.endQuery, GL_QUERY_RESULT, &t1);
            // NVIDIA 580 on an H100 returned an end before the start for a pass of 20 s (naive,
            // 65,536 lights, 2560x1440): such an interval is unknown (NaN), not 2^64 ns.
            ms = t1 >= t0 && t0 != 0 ? static_cast<double>(t1 - t0) * 1e-6 : std::numeric_limits<double>::quiet_NaN();
        } else {
            ms = std::chrono::duration<double, std::milli>(p.end - p.start).count();
        }
        auto same = std::find_if(out.begin(), out.end(), [&](const PassTime& t) { return t.name == p.name; });
        if (same != out.end()) same->milliseconds += ms;
        else out.push_back({p.name, ms});
    }
    return out;
}

double totalMilliseconds(const std::vector<PassTime>& times) {
    double total = 0.0;
    for (const PassTime& t : times) total += t.milliseconds;
    return total;
}

}  // namespace ml
