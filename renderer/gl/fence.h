// A move-only GL fence (glFenceSync): the CPU waits for the commands before it and no later
// ones, so a small result can be read without draining the whole pipeline.
#pragma once

#include <utility>

#include "renderer/gl/gl_api.h"

namespace ml::gl {

class Fence {
public:
    Fence() = default;
    // Inserts the fence after every command issued so far.
    static Fence now() {
        Fence f;
        f.sync_ = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
        return f;
    }
    ~Fence() { reset(); }
    Fence(Fence&& other) noexcept : sync_(std::exchange(other.sync_, nullptr)) {}
    Fence& operator=(Fence&& other) noexcept {
        if (this != &other) {
            reset();
            sync_ = std::exchange(other.sync_, nullptr);
        }
        return *this;
    }
    Fence(const Fence&) = delete;
    Fence& operator=(const Fence&) = delete;

    explicit operator bool() const { return sync_ != nullptr; }
    // Blocks until the commands before the fence have completed (at once where they have).
    void wait() const {
        if (!sync_) return;
        GLbitfield flags = GL_SYNC_FLUSH_COMMANDS_BIT;
        while (glClientWaitSync(sync_, flags, 1'000'000'000) == GL_TIMEOUT_EXPIRED) flags = 0;
    }
    void reset() {
        if (sync_) glDeleteSync(sync_);
        sync_ = nullptr;
    }

private:
    GLsync sync_ = nullptr;
};

}  // namespace ml::gl
