#pragma once

#include "core/VoxelGridFrame.h"

#include <glm/vec3.hpp>

namespace vct::render {

/**
 * Where the levels of a clipmap sit (RenderSettings::voxelMode): level `levels - 1`, the coarsest, is the
 * dense grid fitted around the scene; each finer level is half as wide, with as many cells, and centred on
 * the camera. A level's corner snaps to twice its own voxel, so its cells line up with the coarser level's
 * and it moves in steps of two voxels: a camera that moves less than that leaves it where it is, and then
 * nothing of that level is redone. A level stays inside the scene's grid, so near the scene's edge it is
 * off-centre rather than half empty. Plain arithmetic, without GL.
 */
struct ClipmapLayout {
    /** Level @p level (0 = finest) of @p levels around @p camera, in the scene's grid @p scene. */
    static VoxelGridFrame level(const VoxelGridFrame& scene, int levels, int level, const glm::vec3& camera);
};

} // namespace vct::render
