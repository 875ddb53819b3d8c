#include "renderer/gl/buffer.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>

namespace ml::gl {

Buffer::Buffer(std::string_view name, std::size_t bytes, const void* data, GLbitfield flags) : size_(bytes) {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    handle_ = Handle<BufferDeleter>(id);
    // Zero-sized storage is an error in GL, so small buffers get 16 bytes and bindings stay
    // valid. GL copies the whole storage size from `data`, so small data goes through a padded
    // copy: reading past the caller's data would overrun it (AddressSanitizer caught this).
    constexpr std::size_t kMinimum = 16;
    if (bytes >= kMinimum || !data) {
        glNamedBufferStorage(id, static_cast<GLsizeiptr>(std::max(bytes, kMinimum)), bytes ? data : nullptr, flags);
    } else {
        std::array<std::uint8_t, kMinimum> padded{};
        std::memcpy(padded.data(), data, bytes);
        glNamedBufferStorage(id, static_cast<GLsizeiptr>(kMinimum), padded.data(), flags);
    }
    label(GL_BUFFER, id, name);
}

void Buffer::upload(const void* data, std::size_t bytes, std::size_t offset) {
    if (bytes == 0) return;
    glNamedBufferSubData(handle_.id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
}

void Buffer::download(void* out, std::size_t bytes, std::size_t offset) const {
    if (bytes == 0) return;
    glGetNamedBufferSubData(handle_.id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), out);
}

bool GrowableBuffer::ensure(std::size_t bytes) {
    if (buffer_ && buffer_.size() >= bytes) return false;
    // Grow by half again so a slowly rising need does not re-create the buffer every frame.
    const std::size_t capacity = buffer_ ? std::max(bytes, buffer_.size() + buffer_.size() / 2) : bytes;
    buffer_ = Buffer(label_, capacity, nullptr, GL_DYNAMIC_STORAGE_BIT);
    return true;
}

}  // namespace ml::gl
