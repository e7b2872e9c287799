#include "gl/Sampler.h"

namespace vct::gl {

void deleteSampler(GLuint id)
{
    glDeleteSamplers(1, &id);
}

Sampler Sampler::createRawDepth()
{
    GLuint id = 0;
    glCreateSamplers(1, &id);
    glSamplerParameteri(id, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(id, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    Sampler sampler;
    sampler.m_handle = Handle<deleteSampler>(id);
    return sampler;
}

} // namespace vct::gl
