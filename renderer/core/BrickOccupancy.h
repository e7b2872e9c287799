#pragma once

#include <cstddef>

namespace vct::render {

/**
 * How many bricks of brickSize^3 voxels of one grid hold a surface: what a sparse pool of bricks would
 * allocate for that grid's level 0 where a dense texture allocates every cell (Renderer::brickOccupancy).
 */
struct BrickOccupancy {
    int grid = 0; ///< 0: the grid around the scene or a clipmap's finest level; k: its k-th coarser level
    int resolution = 0; ///< voxels per side
    int brickSize = 0; ///< voxels per brick side
    std::size_t occupiedVoxels = 0;
    std::size_t occupiedBricks = 0;
    std::size_t totalBricks = 0;
    /// voxel_mode=sparse, bricks of 8^3: the bricks its pools store (core/BrickPool: every brick a triangle
    /// can reach, the border's and a moving object's past bricks included), and the pool's slots; 0
    /// otherwise.
    std::size_t storedBricks = 0;
    std::size_t poolSlots = 0;

    double share() const { return totalBricks > 0 ? double(occupiedBricks) / double(totalBricks) : 0.0; }
    /**
     * A pool of the occupied bricks, each with a one-voxel border for trilinear lookups, over the dense
     * level: the share of level-0 memory such a pool would take.
     */
    double borderedPoolShare() const
    {
        const double bordered = double(brickSize + 2) * double(brickSize + 2) * double(brickSize + 2);
        const double cells = double(resolution) * double(resolution) * double(resolution);
        return cells > 0.0 ? double(occupiedBricks) * bordered / cells : 0.0;
    }
};

} // namespace vct::render
