#include "gl/Sampler.h"

namespace vct::gl {

void deleteSampler(GLuint id)
{
    glDeleteSamplers(1, &id);
}

Sampler Sampler::create(GLenum minFilter, GLenum magFilter, GLenum wrap)
{
    GLuint id = 0;
    glCreateSamplers(1, &id);
    glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, GLint(minFilter));
    glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, GLint(magFilter));
    glSamplerParameteri(id, GL_TEXTURE_WRAP_S, GLint(wrap));
    glSamplerParameteri(id, GL_TEXTURE_WRAP_T, GLint(wrap));
    glSamplerParameteri(id, GL_TEXTURE_WRAP_R, GLint(wrap));
    Sampler sampler;
    sampler.m_handle = Handle<deleteSampler>(id);
    return sampler;
}

Sampler Sampler::createRawDepth()
{
    Sampler sampler = create(GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(sampler.id(), GL_TEXTURE_COMPARE_MODE, GL_NONE);
    return sampler;
}

Sampler Sampler::createNearestLevel()
{
    Sampler sampler = create(GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR, GL_CLAMP_TO_BORDER);
    const float none[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
    glSamplerParameterfv(sampler.id(), GL_TEXTURE_BORDER_COLOR, none);
    return sampler;
}

} // namespace vct::gl
