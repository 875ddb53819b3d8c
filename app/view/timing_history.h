// Recent frame and pass times for the view's statistics: means over the last kWindow frames,
// so numbers are readable instead of flickering, and a ring of frame times for the graph.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include "renderer/pass_timer.h"

namespace ml::app {

class TimingHistory {
public:
    static constexpr std::size_t kWindow = 60;   // frames averaged
    static constexpr std::size_t kGraph = 240;   // frames in the graph

    void addFrame(double milliseconds);
    // A frame's pass times (empty when none were ready: nothing changes). A different list of
    // passes (the method changed) starts the averages afresh.
    void addPasses(const std::vector<PassTime>& times);

    double meanFrameMilliseconds() const;
    // Mean per pass over the frames seen since the passes last changed, in running order.
    std::vector<PassTime> meanPasses() const;
    // The graph's values, oldest first.
    std::vector<float> frameGraph() const;

private:
    struct Samples {
        std::array<double, kWindow> values{};
        std::size_t count = 0, next = 0;
        void add(double v);
        double mean() const;
    };
    Samples frames_;
    std::vector<std::string> passOrder_;
    std::map<std::string, Samples> passes_;
    std::array<float, kGraph> graph_{};
    std::size_t graphCount_ = 0, graphNext_ = 0;
};

}  // namespace ml::app
