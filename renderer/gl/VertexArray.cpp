#include "gl/VertexArray.h"

namespace vct::gl {

void deleteVertexArray(GLuint id)
{
    glDeleteVertexArrays(1, &id);
}

VertexArray VertexArray::create()
{
    VertexArray vao;
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    vao.m_handle = Handle<deleteVertexArray>(id);
    return vao;
}

void VertexArray::setAttribute(GLuint index, GLuint bufferId, int components, GLsizei stride, GLuint offset)
{
    // One binding point per attribute keeps the layout explicit; the buffers are tiny in number.
    glVertexArrayVertexBuffer(id(), index, bufferId, GLintptr(offset), stride);
    glVertexArrayAttribFormat(id(), index, components, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(id(), index, index);
    glEnableVertexArrayAttrib(id(), index);
}

void VertexArray::setIndexBuffer(GLuint bufferId)
{
    glVertexArrayElementBuffer(id(), bufferId);
}

void VertexArray::bind() const
{
    glBindVertexArray(id());
}

} // namespace vct::gl
