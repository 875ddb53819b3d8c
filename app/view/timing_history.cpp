#include "app/view/timing_history.h"

#include <algorithm>

namespace ml::app {

void TimingHistory::Samples::add(double v) {
    values[next] = v;
    next = (next + 1) % values.size();
    count = std::min(count + 1, values.size());
}

double TimingHistory::Samples::mean() const {
    if (count == 0) return 0.0;
    double sum = 0.0;
    for (std::size_t i = 0; i < count; ++i) sum += values[i];
    return sum / static_cast<double>(count);
}

void TimingHistory::addFrame(double milliseconds) {
    frames_.add(milliseconds);
    graph_[graphNext_] = static_cast<float>(milliseconds);
    graphNext_ = (graphNext_ + 1) % graph_.size();
    graphCount_ = std::min(graphCount_ + 1, graph_.size());
}

void TimingHistory::addPasses(const std::vector<PassTime>& times) {
    if (times.empty()) return;
    std::vector<std::string> order;
    for (const PassTime& t : times) order.push_back(t.name);
    if (order != passOrder_) {
        passOrder_ = std::move(order);
        passes_.clear();
    }
    for (const PassTime& t : times) passes_[t.name].add(t.milliseconds);
}

double TimingHistory::meanFrameMilliseconds() const { return frames_.mean(); }

std::vector<PassTime> TimingHistory::meanPasses() const {
    std::vector<PassTime> out;
    for (const std::string& name : passOrder_) out.push_back({name, passes_.at(name).mean()});
    return out;
}

std::vector<float> TimingHistory::frameGraph() const {
    std::vector<float> out;
    const std::size_t start = graphCount_ < graph_.size() ? 0 : graphNext_;
    for (std::size_t i = 0; i < graphCount_; ++i) out.push_back(graph_[(start + i) % graph_.size()]);
    return out;
}

}  // namespace ml::app
