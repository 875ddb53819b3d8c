// A few 32-bit words that the GPU writes mid-frame and the CPU reads without draining the
// pipeline: a persistently mapped buffer and a fence after the commands that write it. Reading
// waits for those commands alone, not for the work queued after them, so the GPU keeps running
// while the CPU decides what to issue next (a buffer's size, say). glGetNamedBufferSubData in
// its place waits for everything issued before it, and the GPU then idles until the next
// command arrives (0.1-0.2 ms a read on an H100: docs/bench/nvidia-h100/list-sync/).
#pragma once

#include <cstdint>
#include <string_view>

#include "renderer/gl/buffer.h"
#include "renderer/gl/fence.h"

namespace ml::gl {

class MappedWords {
public:
    MappedWords(std::string_view label, std::size_t words)
        : buffer_(label, words * sizeof(std::uint32_t), nullptr, kFlags),
          words_(static_cast<const std::uint32_t*>(
              glMapNamedBufferRange(buffer_.id(), 0, static_cast<GLsizeiptr>(buffer_.size()), kFlags))) {}

    // Where the GPU writes the words: a copy, or a shader followed by
    // glMemoryBarrier(GL_CLIENT_MAPPED_BUFFER_BARRIER_BIT).
    const Buffer& buffer() const { return buffer_; }
    // After the commands that write the words.
    void fence() { ready_ = Fence::now(); }
    // Between fence() and read().
    bool fenced() const { return static_cast<bool>(ready_); }
    // Waits for the fence (at once where the GPU has passed it) and returns the words, valid
    // until the GPU writes them again.
    const std::uint32_t* read() {
        ready_.wait();
        ready_.reset();
        return words_;
    }

private:
    static constexpr GLbitfield kFlags = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;

    Buffer buffer_;
    const std::uint32_t* words_ = nullptr;
    Fence ready_;
};

}  // namespace ml::gl
