#include "app/render/frame_pattern.h"

#include <unistd.h>

#include <cctype>
#include <stdexcept>
#include <system_error>

namespace ml::app {

FramePattern FramePattern::parse(const std::string& flag, const std::string& pattern, bool severalFrames) {
    FramePattern p;
    p.flag_ = flag;
    p.pattern_ = pattern;
    const std::string culprit = flag + " '" + pattern + "': ";
    if (pattern.empty()) throw std::invalid_argument(flag + ": empty file name");
    std::size_t fieldStart = std::string::npos;
    std::string literal;
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%') {
            literal += pattern[i];
            continue;
        }
        if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
            literal += '%';
            ++i;
            continue;
        }
        // A field: %[0][width]d.
        std::size_t j = i + 1;
        const bool zero = j < pattern.size() && pattern[j] == '0';
        if (zero) ++j;
        int width = 0;
        while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j])) && width < 100)
            width = width * 10 + (pattern[j++] - '0');
        if (j >= pattern.size() || pattern[j] != 'd' || width >= 100)
            throw std::invalid_argument(culprit + "the only field allowed is the frame number, %d or %0Nd (e.g. %04d); "
                                                  "write %% for a literal %");
        if (p.hasField_) throw std::invalid_argument(culprit + "more than one frame-number field; give exactly one");
        p.hasField_ = true;
        p.zeroPad_ = zero;
        p.width_ = width;
        p.prefix_ = literal;
        literal.clear();
        fieldStart = i;
        i = j;
    }
    if (p.hasField_) p.suffix_ = literal;
    else p.prefix_ = literal;
    if (p.hasField_ && pattern.find('/', fieldStart) != std::string::npos)
        throw std::invalid_argument(culprit + "the frame number must be in the file name, not in a directory");
    if (severalFrames && !p.hasField_)
        throw std::invalid_argument(culprit + "several frames need a frame-number field in the name, e.g. frame_%04d.png");
    return p;
}

std::string FramePattern::path(std::uint32_t frame) const {
    if (!hasField_) return prefix_;
    std::string digits = std::to_string(frame);
    if (static_cast<int>(digits.size()) < width_)
        digits.insert(0, static_cast<std::size_t>(width_) - digits.size(), zeroPad_ ? '0' : ' ');
    return prefix_ + digits + suffix_;
}

void FramePattern::prepareDirectory() const { prepareDirectoryOf(flag_ + " '" + pattern_ + "'", path(0)); }

void prepareDirectoryOf(const std::string& flag, const std::string& file) {
    const std::filesystem::path directory = std::filesystem::path(file).parent_path();
    if (directory.empty()) {
        if (access(".", W_OK) != 0) throw std::invalid_argument(flag + ": the working directory is not writable");
        return;
    }
    std::error_code ec;
    std::filesystem::create_directories(directory, ec);
    if (ec || !std::filesystem::is_directory(directory))
        throw std::invalid_argument(flag + ": cannot create the directory " + directory.string() +
                                    (ec ? " (" + ec.message() + ")" : ""));
    if (access(directory.c_str(), W_OK) != 0)
        throw std::invalid_argument(flag + ": the directory " + directory.string() + " is not writable");
}

}  // namespace ml::app
