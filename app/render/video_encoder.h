// `render --video clip.mp4`: frames piped as raw RGBA into Debian's ffmpeg (popen), which
// encodes by the file's extension: .mp4/.mkv/.mov H.264 (yuv420p, plays everywhere), .webm
// VP9, .webp animated WebP, .gif (a palette per clip). The clip is only as good as ffmpeg's
// exit status: finish() checks it.
#pragma once

#include <cstdio>
#include <optional>
#include <string>

#include "renderer/image/image.h"

namespace ml::app {

struct VideoSettings {
    std::string path;
    int width = 0;
    int height = 0;
    double fps = 30.0;
    int crf = 23;  // lower is better and larger; 0-51 (x264, VP9); WebP quality is 100 - 2 * crf
};

// ffmpeg's full path found on PATH, or nothing.
std::optional<std::string> findFfmpeg();

// Checks the settings and that ffmpeg exists before any frame is rendered. Throws
// std::invalid_argument with one line (for a missing ffmpeg: how to install it).
void validateVideo(const VideoSettings& settings);

class VideoEncoder {
public:
    // Starts ffmpeg (validateVideo first). Throws std::runtime_error.
    explicit VideoEncoder(const VideoSettings& settings);
    ~VideoEncoder();  // a clip never finished: ffmpeg is closed, its status ignored
    VideoEncoder(const VideoEncoder&) = delete;
    VideoEncoder& operator=(const VideoEncoder&) = delete;

    // Throws std::runtime_error when ffmpeg has gone (its own message is on stderr above).
    void addFrame(const RgbaImage& frame);
    // Closes the pipe and waits; throws std::runtime_error naming ffmpeg's exit status.
    void finish();

private:
    VideoSettings settings_;
    std::FILE* pipe_ = nullptr;
    int frames_ = 0;
};

}  // namespace ml::app
