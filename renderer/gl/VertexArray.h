#pragma once

#include "gl/Handle.h"

namespace vct::gl {

void deleteVertexArray(GLuint id);

/** A vertex array object (DSA); buffers are owned elsewhere. */
class VertexArray {
public:
    static VertexArray create();
    GLuint id() const { return m_handle.id(); }
    explicit operator bool() const { return bool(m_handle); }
    /** Float attribute `index` with `components` floats at `offset` in a buffer of `stride`-byte vertices. */
    void setAttribute(GLuint index, GLuint bufferId, int components, GLsizei stride, GLuint offset);
    void setIndexBuffer(GLuint bufferId);
    void bind() const;

private:
    Handle<deleteVertexArray> m_handle;
};

} // namespace vct::gl
