#pragma once

#include <glad/gl.h>

#include <utility>

namespace vct::gl {

/** Move-only ownership of one GL object name; Deleter is called once with the name. */
template <void (*Deleter)(GLuint)> class Handle {
public:
    Handle() = default;
    explicit Handle(GLuint id)
        : m_id(id)
    {
    }
    ~Handle() { reset(); }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    Handle(Handle&& other) noexcept
        : m_id(std::exchange(other.m_id, 0))
    {
    }
    Handle& operator=(Handle&& other) noexcept
    {
        if (this != &other) {
            reset();
            m_id = std::exchange(other.m_id, 0);
        }
        return *this;
    }
    GLuint id() const { return m_id; }
    explicit operator bool() const { return m_id != 0; }
    void reset()
    {
        if (m_id)
            Deleter(m_id);
        m_id = 0;
    }

private:
    GLuint m_id = 0;
};

} // namespace vct::gl
