#include "app/render/video_encoder.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace ml::app {

namespace {

// For `sh -c`: the path in single quotes, each ' as '\''.
std::string shellQuoted(const std::string& text) {
    std::string q = "'";
    for (char c : text) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

std::string extensionOf(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

// The encoder arguments for the container the extension names; empty for one we do not know.
std::string codecArguments(const VideoSettings& s) {
    const std::string ext = extensionOf(s.path);
    const std::string crf = std::to_string(s.crf);
    // yuv420p halves the chroma resolution, so H.264 and VP9 need even sides: pad by a pixel.
    const std::string evenSides = (s.width % 2 || s.height % 2) ? " -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2'" : "";
    if (ext == ".mp4" || ext == ".mkv" || ext == ".mov")
        return "-c:v libx264 -preset medium -crf " + crf + " -pix_fmt yuv420p" + evenSides +
               (ext == ".mkv" ? "" : " -movflags +faststart");
    if (ext == ".webm") return "-c:v libvpx-vp9 -crf " + crf + " -b:v 0 -pix_fmt yuv420p" + evenSides;
    if (ext == ".webp")
        return "-c:v libwebp_anim -loop 0 -lossless 0 -quality " + std::to_string(std::clamp(100 - 2 * s.crf, 0, 100));
    if (ext == ".gif") return "-vf 'split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse' -loop 0";
    return "";
}

}  // namespace

std::optional<std::string> findFfmpeg() {
    const char* path = std::getenv("PATH");
    if (!path) return std::nullopt;
    const std::string dirs = path;
    std::size_t start = 0;
    while (start <= dirs.size()) {
        const std::size_t colon = dirs.find(':', start);
        const std::string dir = dirs.substr(start, colon == std::string::npos ? std::string::npos : colon - start);
        start = colon == std::string::npos ? dirs.size() + 1 : colon + 1;
        if (dir.empty()) continue;  // an empty entry would mean the working directory: not trusted
        const std::string candidate = dir + "/ffmpeg";
        if (access(candidate.c_str(), X_OK) == 0 && std::filesystem::is_regular_file(candidate)) return candidate;
    }
    return std::nullopt;
}

void validateVideo(const VideoSettings& s) {
    if (codecArguments(s).empty())
        throw std::invalid_argument("--video " + s.path + ": unknown container; use .mp4, .mkv, .mov, .webm, .webp or .gif");
    if (!(std::isfinite(s.fps) && s.fps > 0.0 && s.fps <= 1000.0))
        throw std::invalid_argument("--video-fps: must be in (0, 1000]");
    if (s.crf < 0 || s.crf > 51) throw std::invalid_argument("--video-crf " + std::to_string(s.crf) + ": must be 0 to 51");
    if (!findFfmpeg())
        throw std::invalid_argument("--video: ffmpeg not found on PATH; install it with `apt-get install ffmpeg` (Debian)");
}

VideoEncoder::VideoEncoder(const VideoSettings& settings) : settings_(settings) {
    validateVideo(settings_);
    char fps[32];
    std::snprintf(fps, sizeof fps, "%.6g", settings_.fps);
    const std::string command = shellQuoted(*findFfmpeg()) + " -hide_banner -loglevel error -y -f rawvideo -pix_fmt rgba -s " +
                                std::to_string(settings_.width) + "x" + std::to_string(settings_.height) + " -framerate " +
                                fps + " -i - " + codecArguments(settings_) + " " + shellQuoted(settings_.path);
    // A write into a pipe whose reader has exited would kill us with SIGPIPE; fwrite's error
    // is reported instead, with ffmpeg's exit status.
    std::signal(SIGPIPE, SIG_IGN);
    pipe_ = popen(command.c_str(), "w");
    if (!pipe_) throw std::runtime_error("--video " + settings_.path + ": cannot start ffmpeg");
}

VideoEncoder::~VideoEncoder() {
    if (pipe_) pclose(pipe_);
}

void VideoEncoder::addFrame(const RgbaImage& frame) {
    if (frame.width != settings_.width || frame.height != settings_.height)
        throw std::logic_error("video frame size changed");
    if (std::fwrite(frame.pixels.data(), 1, frame.pixels.size(), pipe_) != frame.pixels.size()) {
        finish();  // throws with ffmpeg's status
        throw std::runtime_error("--video " + settings_.path + ": ffmpeg stopped reading frames");
    }
    ++frames_;
}

void VideoEncoder::finish() {
    if (!pipe_) return;
    const int status = pclose(pipe_);
    pipe_ = nullptr;
    if (status == -1) throw std::runtime_error("--video " + settings_.path + ": lost ffmpeg");
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw std::runtime_error("--video " + settings_.path + ": ffmpeg failed (" +
                                 (WIFEXITED(status) ? "exit status " + std::to_string(WEXITSTATUS(status))
                                                    : std::string("killed by a signal")) +
                                 "); its message is above");
}

}  // namespace ml::app
