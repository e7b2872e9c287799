#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace vct::render {

class ResourceTable;

/** Storage of one 3D texture of the voxel grid, mip level by mip level (for benchmarks and the stats panel).
 */
struct VoxelTextureMemory {
    std::string name; ///< "radiance", "albedo", "radiance, directional (+x -x +y -y +z -z)", ...
    std::string format; ///< "rgba16f", "rgba8", "r32f"
    int width = 0, height = 0, depth = 0; ///< texels of level 0
    std::vector<std::size_t> levelBytes; ///< one entry per mip level, level 0 first
    /// The same storage from GL's own description of each level (its size and the bits of each component,
    /// glGetTextureLevelParameter), as a check on levelBytes: a driver may pad, but must not store less.
    std::size_t glBytes = 0;

    std::size_t totalBytes() const;
};

/** Every allocated voxel texture of the table, in its order; their totals add up to
 * ResourceTable::byteSize(ResourceGroup::Voxels). */
std::vector<VoxelTextureMemory> describeVoxelMemory(const ResourceTable& resources);

} // namespace vct::render
