#pragma once

#include "core/FrameResources.h"
#include "core/ShaderLibrary.h"
#include "core/VoxelChannel.h"
#include "gl/Buffer.h"
#include "gl/VertexArray.h"
#include "scene/Camera.h"

#include <array>
#include <cstdint>

namespace vct::render {

/**
 * Lists the non-empty voxels of a level on the GPU (compaction with an atomic counter) and draws them as
 * instanced cubes, one instance per voxel. The list is rebuilt only when the level, channel or the voxels
 * change, and read back once per rebuild for hover queries; drawing needs no readback.
 */
class VoxelInspector {
public:
    /** Lists level @p level of @p volume, grid @p grid of a clipmap (0 for a dense grid). */
    const VoxelListing& list(
        const ShaderLibrary& shaders, const VoxelVolume& volume, int level, VoxelChannel channel, int grid);
    /** Draws the current list with the given view; returns how many cubes were drawn. */
    std::size_t draw(const ShaderLibrary& shaders, const glm::mat4& viewProjection, float exposure);

private:
    const gl::Program* m_compact = nullptr;
    const gl::Program* m_cubes = nullptr;
    gl::Buffer m_entries;
    gl::Buffer m_counter;
    gl::VertexArray m_emptyVao;
    VoxelListing m_listing;
    /// grid, level, channel, materials version, radiance version, bounced version, resolution, and the
    /// grid's corner (a clip level moves with the camera)
    std::array<std::uint64_t, 10> m_key {};
    bool m_valid = false;
};

} // namespace vct::render
