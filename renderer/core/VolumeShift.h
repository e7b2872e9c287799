#pragma once

#include "core/VoxelGridFrame.h"
#include "core/VoxelRegion.h"

#include <glm/vec3.hpp>

#include <optional>
#include <vector>

namespace vct::gl {
class Texture;
}

namespace vct::render {

/**
 * Moves what a voxel volume holds with its grid, for a grid that stepped by whole voxels (a clip level
 * following the camera, core/ClipmapLayout): each voxel the old and the new place share keeps its value at
 * its new coordinates, and the slabs only the new place covers take another volume's (say, the first-bounce
 * light). Copies within the texture, slab by slab in an order that never reads what it already wrote, so no
 * second volume is needed.
 */
struct VolumeShift {
    /**
     * The whole voxels grid @p to lies from grid @p from (new index = old index - shift), or nothing when
     * the two are not the same lattice (another size or resolution, a fractional offset) or share no voxel.
     */
    static std::optional<glm::ivec3> between(const VoxelGridFrame& from, const VoxelGridFrame& to);
    /**
     * Level 0 of @p volume (a cube) moved by @p shift voxels as between() gives it; the newly covered slabs
     * copied from level 0 of @p fill, a cube of the same size and a copy-compatible format, or without
     * @p fill left holding what they held (for a caller that rewrites them).
     */
    static void apply(const gl::Texture& volume, const gl::Texture* fill, const glm::ivec3& shift);
    /** The voxels of a grid of @p resolution that a move by @p shift keeps (in the new place's indices). */
    static VoxelRegion kept(const glm::ivec3& shift, int resolution);
    /**
     * The rest of the grid, which a move by @p shift newly covers, as at most three disjoint slabs, one per
     * axis that moved, each without the ones before it.
     */
    static std::vector<VoxelRegion> newSlabs(const glm::ivec3& shift, int resolution);
};

} // namespace vct::render
