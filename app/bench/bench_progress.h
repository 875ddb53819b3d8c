// What a running sweep tells the person waiting: on a terminal, a line per point and a
// progress bar with an ETA redrawn under them; otherwise (a log, CI) plain lines only.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace ml::app {

class BenchProgress {
public:
    // Decides bar or plain lines by isatty(stderr).
    explicit BenchProgress(int totalPoints, std::FILE* out = stderr);

    void starting(int index, const std::string& what);  // redraws the bar (terminal only)
    void finished(int index, const std::string& result);  // prints the point's line
    void done();                                         // clears the bar

private:
    std::string eta(int pointsDone) const;
    void drawBar(int index, const std::string& what);

    int total_;
    std::FILE* out_;
    bool terminal_;
    std::chrono::steady_clock::time_point start_;
    bool barShown_ = false;
};

}  // namespace ml::app
