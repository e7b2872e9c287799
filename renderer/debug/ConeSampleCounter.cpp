#include "debug/ConeSampleCounter.h"

namespace vct::render {

ConeSampleCounter::ConeSampleCounter()
    : m_buffer(2 * sizeof(GLuint), nullptr)
{
    reset();
}

void ConeSampleCounter::reset()
{
    const GLuint zero[2] = { 0, 0 };
    m_buffer.upload(zero, sizeof zero);
}

void ConeSampleCounter::bind() const
{
    m_buffer.bindBase(GL_SHADER_STORAGE_BUFFER, kBinding);
}

std::uint64_t ConeSampleCounter::read() const
{
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    GLuint words[2] = { 0, 0 };
    glGetNamedBufferSubData(m_buffer.id(), 0, sizeof words, words);
    return (std::uint64_t(words[1]) << 32) | words[0];
}

} // namespace vct::render
