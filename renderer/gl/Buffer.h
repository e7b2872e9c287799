#pragma once

#include "gl/Handle.h"

#include <cstddef>

namespace vct::gl {

void deleteBuffer(GLuint id);

/** An immutable-storage buffer object (DSA). */
class Buffer {
public:
    Buffer() = default;
    /** Allocates bytes (contents undefined when data is null); flags as for glNamedBufferStorage. */
    Buffer(std::size_t bytes, const void* data, GLbitfield flags = GL_DYNAMIC_STORAGE_BIT);
    GLuint id() const { return m_handle.id(); }
    explicit operator bool() const { return bool(m_handle); }
    std::size_t size() const { return m_size; }
    void upload(const void* data, std::size_t bytes, std::size_t offset = 0);
    void bindBase(GLenum target, GLuint index) const;

private:
    Handle<deleteBuffer> m_handle;
    std::size_t m_size = 0;
};

} // namespace vct::gl
