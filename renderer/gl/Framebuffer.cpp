#include "gl/Framebuffer.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace vct::gl {

void deleteFramebuffer(GLuint id)
{
    glDeleteFramebuffers(1, &id);
}

Framebuffer Framebuffer::create()
{
    Framebuffer fb;
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    fb.m_handle = Handle<deleteFramebuffer>(id);
    return fb;
}

Framebuffer Framebuffer::createEmpty(int width, int height)
{
    Framebuffer fb = create();
    glNamedFramebufferParameteri(fb.id(), GL_FRAMEBUFFER_DEFAULT_WIDTH, width);
    glNamedFramebufferParameteri(fb.id(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, height);
    glNamedFramebufferDrawBuffer(fb.id(), GL_NONE);
    return fb;
}

void Framebuffer::attachColor(int index, const Texture& texture, int level)
{
    glNamedFramebufferTexture(id(), GLenum(GL_COLOR_ATTACHMENT0 + index), texture.id(), level);
}

void Framebuffer::attachColorLayer(int index, const Texture& texture, int layer)
{
    glNamedFramebufferTextureLayer(id(), GLenum(GL_COLOR_ATTACHMENT0 + index), texture.id(), 0, layer);
}

void Framebuffer::attachDepth(const Texture& texture, int level)
{
    const bool stencil = texture.format() == GL_DEPTH32F_STENCIL8 || texture.format() == GL_DEPTH24_STENCIL8;
    glNamedFramebufferTexture(
        id(), stencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT, texture.id(), level);
}

void Framebuffer::attachDepthLayer(const Texture& texture, int layer)
{
    glNamedFramebufferTextureLayer(id(), GL_DEPTH_ATTACHMENT, texture.id(), 0, layer);
}

void Framebuffer::finish(int colorCount)
{
    GLenum buffers[8];
    for (int i = 0; i < colorCount; ++i)
        buffers[i] = GLenum(GL_COLOR_ATTACHMENT0 + i);
    if (colorCount > 0)
        glNamedFramebufferDrawBuffers(id(), colorCount, buffers);
    else
        glNamedFramebufferDrawBuffer(id(), GL_NONE);
    const GLenum status = glCheckNamedFramebufferStatus(id(), GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("framebuffer incomplete, status 0x" + std::to_string(status));
}

void Framebuffer::drawTo(std::initializer_list<int> colors)
{
    GLenum buffers[8] = { GL_NONE, GL_NONE, GL_NONE, GL_NONE, GL_NONE, GL_NONE, GL_NONE, GL_NONE };
    int count = 0;
    for (const int c : colors) {
        buffers[c] = GLenum(GL_COLOR_ATTACHMENT0 + c);
        count = std::max(count, c + 1);
    }
    glNamedFramebufferDrawBuffers(id(), count, buffers);
}

void Framebuffer::bind() const
{
    glBindFramebuffer(GL_FRAMEBUFFER, id());
}

void Framebuffer::follow(std::initializer_list<const Texture*> colors, const Texture* depth)
{
    std::vector<std::uint64_t> serials;
    for (const Texture* color : colors)
        serials.push_back(color->serial());
    serials.push_back(depth ? depth->serial() : 0);
    if (m_handle && serials == m_followed)
        return;
    *this = create();
    int index = 0;
    for (const Texture* color : colors)
        attachColor(index++, *color);
    if (depth)
        attachDepth(*depth);
    finish(index);
    m_followed = std::move(serials);
}

} // namespace vct::gl
