#include "app/bench/bench_progress.h"

#include <unistd.h>

#include <algorithm>

#include "app/duration_format.h"

namespace ml::app {

BenchProgress::BenchProgress(int totalPoints, std::FILE* out)
    : total_(totalPoints), out_(out), terminal_(isatty(fileno(out)) != 0), start_(std::chrono::steady_clock::now()) {}

std::string BenchProgress::eta(int pointsDone) const {
    // The mean time per point so far times the points left: points differ in cost (naive at
    // many lights is the slow kind), so this is a guide, refined as the sweep goes on.
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (pointsDone <= 0) return "elapsed " + formatDuration(elapsed);
    const double left = elapsed / pointsDone * (total_ - pointsDone);
    return "elapsed " + formatDuration(elapsed) + ", ETA " + formatDuration(left);
}

void BenchProgress::drawBar(int index, const std::string& what) {
    constexpr int kWidth = 24;
    const int filled = total_ > 0 ? kWidth * index / total_ : 0;
    std::string bar(static_cast<std::size_t>(filled), '#');
    bar.resize(kWidth, '.');
    std::string line = "[" + bar + "] " + std::to_string(index) + "/" + std::to_string(total_) + "  " + eta(index) + "  " + what;
    if (line.size() > 118) line = line.substr(0, 115) + "...";
    std::fprintf(out_, "\r\033[K%s", line.c_str());
    std::fflush(out_);
    barShown_ = true;
}

void BenchProgress::starting(int index, const std::string& what) {
    if (terminal_) drawBar(index, what);
}

void BenchProgress::finished(int index, const std::string& result) {
    if (terminal_) {
        std::fprintf(out_, "\r\033[K[%d/%d] %s\n", index + 1, total_, result.c_str());
        drawBar(index + 1, "");
    } else {
        std::fprintf(out_, "bench [%d/%d] %s (%s)\n", index + 1, total_, result.c_str(), eta(index + 1).c_str());
    }
    std::fflush(out_);
}

void BenchProgress::done() {
    if (terminal_ && barShown_) std::fprintf(out_, "\r\033[K");
    std::fflush(out_);
}

}  // namespace ml::app
