#include "core/FrameResources.h"

namespace vct::render {

std::vector<TextureSlot> ScreenTargets::tracedGrid(const char* const (&names)[3], gl::Texture& values,
    gl::Texture& guide, gl::Texture& stencil, int divisor, bool needed) const
{
    using gl::TextureDesc;
    const int w = tracedSize(width, divisor), h = tracedSize(height, divisor);
    const auto desc
        = [&](GLenum format) { return needed ? TextureDesc::plane(format, w, h) : TextureDesc {}; };
    return { { names[0], ResourceGroup::Screen, &values, desc(GL_RGBA16F) },
        { names[1], ResourceGroup::Screen, &guide,
            needed ? desc(GL_RGBA32F).sampled(TextureDesc::Sampling::Nearest) : TextureDesc {} },
        { names[2], ResourceGroup::Screen, &stencil, desc(GL_DEPTH24_STENCIL8) } };
}

} // namespace vct::render
