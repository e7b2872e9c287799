#include "gl/Texture.h"

#include <algorithm>
#include <atomic>
#include <stdexcept>

namespace vct::gl {

void deleteTexture(GLuint id)
{
    glDeleteTextures(1, &id);
}

std::size_t bytesPerTexel(GLenum internalFormat)
{
    switch (internalFormat) {
    case GL_R8:
        return 1;
    case GL_RGBA8:
    case GL_SRGB8_ALPHA8:
    case GL_R32F:
    case GL_R32UI:
    case GL_DEPTH_COMPONENT32F:
    case GL_DEPTH_COMPONENT24:
    case GL_DEPTH24_STENCIL8:
    case GL_RGB10_A2:
    case GL_RGBA8_SNORM:
    case GL_R11F_G11F_B10F:
        return 4;
    case GL_RGBA16F:
    case GL_RG32F:
    case GL_RG32UI:
    case GL_DEPTH32F_STENCIL8: // 32-bit depth, 8-bit stencil, 24 bits unused
        return 8;
    case GL_RGBA32F:
    case GL_RGBA32UI:
        return 16;
    default:
        throw std::logic_error("bytesPerTexel: unknown internal format");
    }
}

Texture::Texture(GLenum target, GLenum format, int w, int h, int d, int levels)
    : m_target(target)
    , m_format(format)
    , m_width(w)
    , m_height(h)
    , m_depth(d)
    , m_levels(levels)
{
    GLuint id = 0;
    glCreateTextures(target, 1, &id);
    m_handle = Handle<deleteTexture>(id);
    static std::atomic<std::uint64_t> made { 0 };
    m_serial = ++made;
}

Texture Texture::create(const TextureDesc& desc)
{
    using Kind = TextureDesc::Kind;
    Texture t;
    switch (desc.kind) {
    case Kind::None:
        return t;
    case Kind::Plane:
        t = create2D(desc.format, desc.width, desc.height, desc.levels);
        break;
    case Kind::PlaneArray:
        t = create2DArray(desc.format, desc.width, desc.height, desc.depth);
        break;
    case Kind::Volume:
        if (desc.width == desc.height && desc.width == desc.depth) {
            t = create3D(desc.format, desc.width, desc.levels);
        } else { // a brick pool: one level, and its border empty space like a grid's
            t = create3D(desc.format, desc.width, desc.height, desc.depth);
            t.setWrap(GL_CLAMP_TO_BORDER);
            t.setBorderColor(0, 0, 0, 0);
        }
        break;
    case Kind::VolumeStack:
        t = create3DStack(desc.format, desc.width, desc.depth, desc.levels, desc.gapShift);
        break;
    case Kind::CubeArray:
        t = createCubeArray(desc.format, desc.width, desc.depth);
        break;
    }
    switch (desc.sampling) {
    case TextureDesc::Sampling::Filtered:
        t.setFilter(desc.levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR, GL_LINEAR);
        break;
    case TextureDesc::Sampling::Nearest:
        t.setFilter(GL_NEAREST, GL_NEAREST);
        break;
    case TextureDesc::Sampling::DepthComparison:
        t.setDepthComparison();
        break;
    }
    if (desc.zeroed) {
        const bool integer
            = desc.format == GL_R32UI || desc.format == GL_RG32UI || desc.format == GL_RGBA32UI;
        const bool depth = desc.format == GL_DEPTH_COMPONENT32F || desc.format == GL_DEPTH_COMPONENT24;
        const GLenum format = integer ? GL_RED_INTEGER : depth ? GL_DEPTH_COMPONENT : GL_RGBA;
        for (int level = 0; level < desc.levels; ++level)
            glClearTexImage(t.id(), level, format, integer ? GL_UNSIGNED_INT : GL_FLOAT, nullptr);
    }
    t.m_desc = desc;
    return t;
}

Texture Texture::create2D(GLenum internalFormat, int width, int height, int levels)
{
    Texture t(GL_TEXTURE_2D, internalFormat, width, height, 1, levels);
    glTextureStorage2D(t.id(), levels, internalFormat, width, height);
    t.setFilter(levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR, GL_LINEAR);
    t.setWrap(GL_CLAMP_TO_EDGE);
    return t;
}

Texture Texture::create2DArray(GLenum internalFormat, int width, int height, int layers)
{
    Texture t(GL_TEXTURE_2D_ARRAY, internalFormat, width, height, layers, 1);
    glTextureStorage3D(t.id(), 1, internalFormat, width, height, layers);
    t.setFilter(GL_NEAREST, GL_NEAREST);
    t.setWrap(GL_CLAMP_TO_EDGE);
    return t;
}

Texture Texture::create3D(GLenum internalFormat, int size, int levels)
{
    Texture t(GL_TEXTURE_3D, internalFormat, size, size, size, levels);
    glTextureStorage3D(t.id(), levels, internalFormat, size, size, size);
    t.setFilter(levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR, GL_LINEAR);
    // Outside the grid is empty space: border zero, so cones fade out instead of smearing the edge voxels.
    t.setWrap(GL_CLAMP_TO_BORDER);
    t.setBorderColor(0, 0, 0, 0);
    return t;
}

Texture Texture::create3DStack(GLenum internalFormat, int size, int tiles, int levels, int gapShift)
{
    if (levels < 1 || gapShift < 0 || size % (1 << gapShift) != 0 || ((size >> (levels - 1)) >> gapShift) < 1)
        throw std::logic_error("a tile stack needs a gap of at least one texel at every level");
    const int depth = tiles * size + (tiles - 1) * (size >> gapShift);
    Texture t(GL_TEXTURE_3D, internalFormat, size, size, depth, levels);
    glTextureStorage3D(t.id(), levels, internalFormat, size, size, depth);
    t.setFilter(levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR, GL_LINEAR);
    t.setWrap(GL_CLAMP_TO_BORDER);
    t.setBorderColor(0, 0, 0, 0);
    for (int level = 0; level < levels; ++level) // the gaps must read as empty space
        glClearTexImage(t.id(), level, GL_RGBA, GL_FLOAT, nullptr);
    return t;
}

Texture Texture::create3D(GLenum internalFormat, int width, int height, int depth)
{
    Texture t(GL_TEXTURE_3D, internalFormat, width, height, depth, 1);
    glTextureStorage3D(t.id(), 1, internalFormat, width, height, depth);
    t.setFilter(GL_NEAREST, GL_NEAREST);
    t.setWrap(GL_CLAMP_TO_EDGE);
    return t;
}

Texture Texture::createBufferView(GLenum internalFormat, GLuint buffer, int texels)
{
    Texture t(GL_TEXTURE_BUFFER, internalFormat, texels, 1, 1, 1);
    glTextureBuffer(t.id(), internalFormat, buffer);
    return t;
}

Texture Texture::createCubeArray(GLenum internalFormat, int size, int cubes)
{
    Texture t(GL_TEXTURE_CUBE_MAP_ARRAY, internalFormat, size, size, 6 * cubes, 1);
    glTextureStorage3D(t.id(), 1, internalFormat, size, size, 6 * cubes);
    t.setFilter(GL_NEAREST, GL_NEAREST);
    t.setWrap(GL_CLAMP_TO_EDGE);
    return t;
}

void Texture::setFilter(GLenum minFilter, GLenum magFilter)
{
    glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, GLint(minFilter));
    glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, GLint(magFilter));
}

void Texture::setDepthComparison()
{
    glTextureParameteri(id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTextureParameteri(id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    setFilter(GL_LINEAR, GL_LINEAR);
}

void Texture::setWrap(GLenum wrap)
{
    glTextureParameteri(id(), GL_TEXTURE_WRAP_S, GLint(wrap));
    glTextureParameteri(id(), GL_TEXTURE_WRAP_T, GLint(wrap));
    glTextureParameteri(id(), GL_TEXTURE_WRAP_R, GLint(wrap));
}

void Texture::setBorderColor(float r, float g, float b, float a)
{
    const float color[4] = { r, g, b, a };
    glTextureParameterfv(id(), GL_TEXTURE_BORDER_COLOR, color);
}

void Texture::bindUnit(GLuint unit) const
{
    glBindTextureUnit(unit, id());
}

void Texture::bindImage(GLuint unit, int level, GLenum access, GLenum format) const
{
    const bool layered = m_target != GL_TEXTURE_2D;
    glBindImageTexture(
        unit, id(), level, layered ? GL_TRUE : GL_FALSE, 0, access, format ? format : m_format);
}

std::size_t Texture::byteSize() const
{
    std::size_t total = 0;
    int w = m_width, h = m_height, d = m_depth;
    for (int level = 0; level < m_levels; ++level) {
        total += std::size_t(w) * std::size_t(h) * std::size_t(d) * bytesPerTexel(m_format);
        w = std::max(1, w / 2);
        h = std::max(1, h / 2);
        if (m_target == GL_TEXTURE_3D)
            d = std::max(1, d / 2);
    }
    return total;
}

} // namespace vct::gl
