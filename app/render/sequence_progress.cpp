#include "app/render/sequence_progress.h"

#include <unistd.h>

#include "app/duration_format.h"

namespace ml::app {

SequenceProgress::SequenceProgress(std::uint32_t totalFrames, std::FILE* out)
    : total_(totalFrames), out_(out), terminal_(isatty(fileno(out)) != 0), start_(std::chrono::steady_clock::now()) {}

void SequenceProgress::frameDone(std::uint32_t frame, std::uint32_t framesDone) {
    if (!terminal_ || total_ < 2) return;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double perFrame = elapsed / framesDone;
    std::fprintf(out_, "\r\033[Kframe %u (%u of %u), %.2f s a frame, ETA %s", frame, framesDone, total_, perFrame,
                 formatDuration(perFrame * (total_ - framesDone)).c_str());
    std::fflush(out_);
    shown_ = true;
}

void SequenceProgress::done() {
    if (shown_) std::fprintf(out_, "\r\033[K");
    std::fflush(out_);
}

}  // namespace ml::app
