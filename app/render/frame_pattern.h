// A file name per frame from a printf-style pattern: "shots/frame_%04d.png" -> frame 7 is
// "shots/frame_0007.png". One field, %d with an optional 0 flag and width ("%d", "%4d",
// "%04d"), in the file name (not the directory); "%%" is a literal '%'. Formatted here, never
// by printf, so a user's pattern cannot read the stack.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace ml::app {

class FramePattern {
public:
    // `flag` names the option in messages ("--out"). With several frames the pattern needs its
    // field; a single frame may use a plain name (written as is). Throws std::invalid_argument
    // with one line naming the flag and the pattern.
    static FramePattern parse(const std::string& flag, const std::string& pattern, bool severalFrames);

    std::string path(std::uint32_t frame) const;
    bool numbered() const { return hasField_; }
    const std::string& text() const { return pattern_; }

    // Creates the directory if missing and checks it takes files. Throws std::invalid_argument.
    void prepareDirectory() const;

private:
    std::string flag_;
    std::string pattern_;
    std::string prefix_;  // with "%%" already turned into '%'
    std::string suffix_;
    bool hasField_ = false;
    bool zeroPad_ = false;
    int width_ = 0;
};

// Creates the directory `file` goes into if it is missing and checks that it takes files.
// Throws std::invalid_argument naming `flag` and `file`.
void prepareDirectoryOf(const std::string& flag, const std::string& file);

}  // namespace ml::app
