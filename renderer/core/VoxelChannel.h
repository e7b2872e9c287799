#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace vct::render {

/** What the voxel inspector shows; the numbers match shaders/inspector/CompactVoxels.comp. */
enum class VoxelChannel { Albedo = 0, Radiance = 1, Opacity = 2, Normal = 3, Emission = 4 };

/** One non-empty voxel of an inspected level. */
struct VoxelSample {
    glm::ivec3 coord; ///< Cell at the inspected level.
    glm::vec4 value; ///< Channel value (radiance un-premultiplied, W/(m^2 sr)); a = opacity.
};

/** The non-empty voxels of one level and channel, with where its cells sit in the world. */
struct VoxelListing {
    int grid = 0; ///< Which grid of a clipmap (0 = the finest); 0 for a dense grid.
    int level = 0;
    VoxelChannel channel = VoxelChannel::Radiance;
    glm::vec3 origin { 0.0f }; ///< Grid min corner, metres.
    float cellSize = 1.0f; ///< Side of a cell at this level, metres.
    std::vector<VoxelSample> samples;
};

} // namespace vct::render
