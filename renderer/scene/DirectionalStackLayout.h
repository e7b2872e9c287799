#pragma once

#include <cstdint>

namespace vct::render {

/**
 * How the six directional mip chains of a grid share one 3D texture (shaders/common/DirectionalStack.glsl):
 * tiles `size` wide stacked along z with an empty gap of size >> gapShift between them, levels down to tiles
 * whose gap is still one texel. Plain arithmetic, without GL: the voxel memory estimate and the mip builder
 * both take the layout from here.
 */
struct DirectionalStackLayout {
    /// The depth every GL 4.5 implementation allows a 3D texture (GL_MAX_3D_TEXTURE_SIZE's minimum), and
    /// llvmpipe's: the stack must fit it.
    static constexpr int kMaxDepth = 2048;
    static constexpr int kTiles = 6;

    int size = 0; ///< a tile's side at the first level (grid level 1)
    int gapShift = 1; ///< the gap is size >> gapShift: half a tile, or less where half would not fit
    int levels = 0; ///< 0: the grid is too small for chains

    /**
     * The layout for a grid of @p resolution voxels a side (a power of two): half-tile gaps, a quarter (and
     * so on) where the stack would be deeper than kMaxDepth (512^3: 2176 deep with half-tile gaps).
     */
    static DirectionalStackLayout of(int resolution)
    {
        DirectionalStackLayout layout;
        layout.size = resolution / 2;
        while (layout.depth() > kMaxDepth && (layout.size >> layout.gapShift) > 1)
            ++layout.gapShift;
        // Texture level k = grid level k + 1, down to tiles 2^gapShift wide, whose gaps are one texel.
        for (int side = layout.size; side >= (1 << layout.gapShift) && side >= 2; side /= 2)
            ++layout.levels;
        return layout;
    }
    /** Texels of level 0 along z: the tiles and the gaps between them. */
    int depth() const { return kTiles * size + (kTiles - 1) * (size >> gapShift); }
    /** From one tile's start to the next, at texture level @p level. */
    int stride(int level) const { return (size >> level) + ((size >> level) >> gapShift); }
    /** Bytes over every level at @p bytesPerTexel. */
    std::uint64_t bytes(std::uint64_t bytesPerTexel) const
    {
        std::uint64_t total = 0;
        for (int level = 0; level < levels; ++level) {
            const std::uint64_t side = std::uint64_t(size >> level);
            total += side * side * std::uint64_t(depth() >> level) * bytesPerTexel;
        }
        return total;
    }
};

} // namespace vct::render
