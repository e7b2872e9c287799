#include "gl/Buffer.h"

namespace vct::gl {

void deleteBuffer(GLuint id)
{
    glDeleteBuffers(1, &id);
}

Buffer::Buffer(std::size_t bytes, const void* data, GLbitfield flags)
    : m_size(bytes)
{
    GLuint id = 0;
    glCreateBuffers(1, &id);
    m_handle = Handle<deleteBuffer>(id);
    glNamedBufferStorage(id, GLsizeiptr(bytes ? bytes : 4), data, flags);
}

void Buffer::upload(const void* data, std::size_t bytes, std::size_t offset)
{
    glNamedBufferSubData(id(), GLintptr(offset), GLsizeiptr(bytes), data);
}

void Buffer::bindBase(GLenum target, GLuint index) const
{
    glBindBufferBase(target, index, id());
}

} // namespace vct::gl
