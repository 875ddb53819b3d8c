// An immutable-storage GL buffer (glNamedBufferStorage), labelled at creation.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "renderer/gl/gl_handle.h"

namespace ml::gl {

class Buffer {
public:
    Buffer() = default;
    // flags: GL_DYNAMIC_STORAGE_BIT to allow glNamedBufferSubData, 0 for GPU-only.
    Buffer(std::string_view label, std::size_t bytes, const void* data = nullptr,
           GLbitfield flags = GL_DYNAMIC_STORAGE_BIT);

    template <typename T>
    static Buffer fromSpan(std::string_view label, std::span<const T> items,
                           GLbitfield flags = GL_DYNAMIC_STORAGE_BIT) {
        return Buffer(label, items.size_bytes(), items.data(), flags);
    }

    GLuint id() const { return handle_.id(); }
    std::size_t size() const { return size_; }
    explicit operator bool() const { return static_cast<bool>(handle_); }

    void upload(const void* data, std::size_t bytes, std::size_t offset = 0);
    void bindBase(GLenum target, GLuint index) const { glBindBufferBase(target, index, handle_.id()); }
    void download(void* out, std::size_t bytes, std::size_t offset = 0) const;

    template <typename T>
    std::vector<T> downloadAll() const {
        std::vector<T> out(size_ / sizeof(T));
        download(out.data(), out.size() * sizeof(T));
        return out;
    }

private:
    Handle<BufferDeleter> handle_;
    std::size_t size_ = 0;
};

// A buffer that is re-created larger when a frame needs more than it holds (never shrinks).
class GrowableBuffer {
public:
    explicit GrowableBuffer(std::string label) : label_(std::move(label)) {}
    // Returns true when the buffer was re-created (its contents are then undefined).
    bool ensure(std::size_t bytes);
    const Buffer& buffer() const { return buffer_; }
    Buffer& buffer() { return buffer_; }

private:
    std::string label_;
    Buffer buffer_;
};

}  // namespace ml::gl
