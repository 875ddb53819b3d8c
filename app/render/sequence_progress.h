// What a running sequence tells the person waiting: on a terminal (isatty(stderr)) one line,
// redrawn after every frame, with the frame, the time a frame takes and an ETA; nothing in a
// log or a test.
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>

namespace ml::app {

class SequenceProgress {
public:
    SequenceProgress(std::uint32_t totalFrames, std::FILE* out = stderr);
    void frameDone(std::uint32_t frame, std::uint32_t framesDone);
    void done();  // clears the line

private:
    std::uint32_t total_;
    std::FILE* out_;
    bool terminal_;
    bool shown_ = false;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace ml::app
