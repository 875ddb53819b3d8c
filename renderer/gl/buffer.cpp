#include "renderer/gl/buffer.h"

#include <algorithm>

namespace ml::gl {

Buffer::Buffer(std::string_view name, std::size_t bytes, const void* data, GLbitfield flags) : size_(bytes) {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    handle_ = Handle<BufferDeleter>(id);
    // Zero-sized storage is an error in GL; keep one element's worth so bindings stay valid.
    glNamedBufferStorage(id, static_cast<GLsizeiptr>(std::max<std::size_t>(bytes, 16)), bytes ? data : nullptr, flags);
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
