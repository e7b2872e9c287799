#pragma once

#include "gl/Handle.h"
#include "gl/TextureDesc.h"

#include <cstddef>
#include <cstdint>

namespace vct::gl {

void deleteTexture(GLuint id);

/** An immutable-storage texture of any target (DSA). */
class Texture {
public:
    Texture() = default;
    /** What @p desc describes, sampled and (when it says so) cleared as it says; desc() returns it. */
    static Texture create(const TextureDesc& desc);
    static Texture create2D(GLenum internalFormat, int width, int height, int levels = 1);
    static Texture create2DArray(GLenum internalFormat, int width, int height, int layers);
    static Texture create3D(GLenum internalFormat, int size, int levels = 1);
    /** A single-level 3D texture that need not be a cube. */
    static Texture create3D(GLenum internalFormat, int width, int height, int depth);
    static Texture createCubeArray(GLenum internalFormat, int size, int cubes);
    /** A buffer texture (samplerBuffer) over `texels` texels of @p buffer, which must outlive it. */
    static Texture createBufferView(GLenum internalFormat, GLuint buffer, int texels);
    /**
     * `tiles` cubic volumes of side `size` stacked along z in one mipmapped 3D texture, filtered and bordered
     * like create3D. Shaders pick a tile by coordinate, which costs nothing, where picking one of several
     * samplers per pixel costs a fetch from each (llvmpipe). Between tiles lies an empty (zeroed, never
     * written) gap of size >> gapShift texels, so at every level a trilinear lookup past a tile's end reads
     * zeros, exactly as the border of a texture of its own would give, and the levels halve tiles and gaps
     * alike (scene/DirectionalStackLayout.h). The gap must be at least one texel at every level.
     */
    static Texture create3DStack(GLenum internalFormat, int size, int tiles, int levels, int gapShift);

    GLuint id() const { return m_handle.id(); }
    GLenum target() const { return m_target; }
    GLenum format() const { return m_format; }
    int width() const { return m_width; }
    int height() const { return m_height; }
    int depth() const { return m_depth; }
    int levels() const { return m_levels; }
    explicit operator bool() const { return bool(m_handle); }
    /** What create() was asked for; an empty description for textures made by the other functions. */
    const TextureDesc& desc() const { return m_desc; }
    /**
     * Unique to this texture among all made in the process, unlike id(), which GL may give again after a
     * deletion: what tells a framebuffer or a pass that a texture was made anew.
     */
    std::uint64_t serial() const { return m_serial; }

    void setFilter(GLenum minFilter, GLenum magFilter);
    void setWrap(GLenum wrap);
    /**
     * For a depth texture read by shadow samplers: lookups compare against the reference (less or equal) and
     * filter the four nearest results bilinearly, so a shadow edge is the texel-area average it is in a
     * reference image rather than a step.
     */
    void setDepthComparison();
    void setBorderColor(float r, float g, float b, float a);
    void bindUnit(GLuint unit) const;
    /** Binds one mip level as an image (all layers of a 3D or array texture). */
    void bindImage(GLuint unit, int level, GLenum access, GLenum format = 0) const;
    /** Bytes of texel storage over all levels, from the internal format's size. */
    std::size_t byteSize() const;

private:
    Texture(GLenum target, GLenum format, int w, int h, int d, int levels);
    Handle<deleteTexture> m_handle;
    GLenum m_target = 0;
    GLenum m_format = 0;
    int m_width = 0, m_height = 0, m_depth = 0, m_levels = 0;
    TextureDesc m_desc;
    std::uint64_t m_serial = 0;
};

/** Bytes per texel of the internal formats we use. */
std::size_t bytesPerTexel(GLenum internalFormat);

} // namespace vct::gl
