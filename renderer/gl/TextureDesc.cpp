#include "gl/TextureDesc.h"

#include "gl/Texture.h"

#include <algorithm>

namespace vct::gl {

TextureDesc TextureDesc::plane(GLenum format, int width, int height)
{
    return { Kind::Plane, format, width, height, 1, 1 };
}

TextureDesc TextureDesc::planeArray(GLenum format, int width, int height, int layers)
{
    return { Kind::PlaneArray, format, width, height, layers, 1, 0, Sampling::Nearest };
}

TextureDesc TextureDesc::volume(GLenum format, int size, int levels)
{
    return { Kind::Volume, format, size, size, size, levels };
}

TextureDesc TextureDesc::brickPool(GLenum format, int width, int height, int depth)
{
    return { Kind::Volume, format, width, height, depth, 1 };
}

TextureDesc TextureDesc::volumeStack(GLenum format, int size, int tiles, int levels, int gapShift)
{
    return { Kind::VolumeStack, format, size, size, tiles, levels, gapShift };
}

TextureDesc TextureDesc::cubeArray(GLenum format, int size, int cubes)
{
    return { Kind::CubeArray, format, size, size, cubes, 1, 0, Sampling::Nearest };
}

TextureDesc TextureDesc::sampled(Sampling how) const
{
    TextureDesc d = *this;
    d.sampling = how;
    return d;
}

TextureDesc TextureDesc::zeroedWhenMade() const
{
    TextureDesc d = *this;
    d.zeroed = true;
    return d;
}

std::uint64_t TextureDesc::byteSize() const
{
    if (kind == Kind::None)
        return 0;
    // Texel depth of level 0: stacks keep an empty gap between tiles, cube arrays six faces per cube.
    std::uint64_t d = kind == Kind::VolumeStack ? std::uint64_t(depth) * std::uint64_t(width)
            + std::uint64_t(depth - 1) * std::uint64_t(width >> gapShift)
        : kind == Kind::CubeArray ? 6 * std::uint64_t(depth)
                                  : std::uint64_t(depth);
    const bool volumetric = kind == Kind::Volume || kind == Kind::VolumeStack;
    std::uint64_t w = std::uint64_t(width), h = std::uint64_t(height), total = 0;
    for (int level = 0; level < levels; ++level) {
        total += w * h * d * bytesPerTexel(format);
        w = std::max<std::uint64_t>(1, w / 2);
        h = std::max<std::uint64_t>(1, h / 2);
        if (volumetric)
            d = std::max<std::uint64_t>(1, d / 2);
    }
    return total;
}

} // namespace vct::gl
