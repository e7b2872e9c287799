#pragma once

#include <glad/gl.h>

#include <cstdint>

namespace vct::gl {

/**
 * What a texture is, as plain data: its shape, format, size, levels and how it is sampled. A pass says what
 * it needs by one of these every frame; the pipeline compares it with what is allocated (Texture::desc) and
 * allocates, resizes or frees to match (core/ResourceTable).
 */
struct TextureDesc {
    enum class Kind : std::uint8_t {
        None, ///< no texture: the pass needs none this frame
        Plane, ///< 2D
        PlaneArray, ///< 2D array, `depth` layers
        Volume, ///< 3D, clamped to a zero border (outside the grid is empty space); cubic unless a brick pool
        VolumeStack, ///< `depth` cubic tiles stacked along z with empty gaps (Texture::create3DStack)
        CubeArray, ///< cube map array, `depth` cubes
    };
    enum class Sampling : std::uint8_t {
        Filtered, ///< linear (trilinear over levels); what each kind is made with
        Nearest, ///< texel fetches and nearest lookups only
        DepthComparison, ///< shadow samplers: compare and filter (Texture::setDepthComparison)
    };

    Kind kind = Kind::None;
    GLenum format = 0;
    int width = 0, height = 0;
    int depth = 1; ///< volumes: their side; arrays: layers; cube arrays: cubes; stacks: tiles
    int levels = 1;
    int gapShift = 0; ///< stacks: the gap between tiles is width >> gapShift texels
    Sampling sampling = Sampling::Filtered;
    /// Cleared to zero when made, and that is valid content: the pass's output stays valid through a
    /// reallocation (an emission volume made when a material starts to emit holds no light yet, rightly).
    bool zeroed = false;

    bool operator==(const TextureDesc& other) const = default;
    explicit operator bool() const { return kind != Kind::None; }

    static TextureDesc plane(GLenum format, int width, int height);
    static TextureDesc planeArray(GLenum format, int width, int height, int layers);
    static TextureDesc volume(GLenum format, int size, int levels = 1);
    /** A sparse grid's brick pool (core/BrickPool): one level of width x height x depth texels. */
    static TextureDesc brickPool(GLenum format, int width, int height, int depth);
    static TextureDesc volumeStack(GLenum format, int size, int tiles, int levels, int gapShift);
    static TextureDesc cubeArray(GLenum format, int size, int cubes);
    TextureDesc sampled(Sampling how) const;
    TextureDesc zeroedWhenMade() const;

    /** Bytes of texel storage over all levels, without asking GL (equal to Texture::byteSize once made). */
    std::uint64_t byteSize() const;
};

} // namespace vct::gl
