// What a pass's own screen-sized targets were made for: the frame's size and depth texture. A
// pass that attaches the frame's depth re-creates its targets when either changes (a resize, or
// FrameTargets::configure swapping the depth format).
#pragma once

#include "renderer/frame_targets.h"

namespace ml {

class FrameTargetsStamp {
public:
    // True (and the stamp updated) when `targets` differ from what the stamp last saw.
    bool update(const FrameTargets& targets) {
        if (targets.width() == width_ && targets.height() == height_ && targets.depth().id() == depthId_) return false;
        width_ = targets.width();
        height_ = targets.height();
        depthId_ = targets.depth().id();
        return true;
    }
    int width() const { return width_; }
    int height() const { return height_; }

private:
    int width_ = 0, height_ = 0;
    GLuint depthId_ = 0;
};

}  // namespace ml
