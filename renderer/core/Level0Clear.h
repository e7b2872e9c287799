#pragma once

#include "core/VoxelRegion.h"
#include "gl/Texture.h"

namespace vct::render {

struct VoxelVolume;

/**
 * Empties a region of level 0 of one of the grid's voxel textures (albedo, normal, emission, radiance,
 * bounced): the texels themselves in a dense grid; in a sparse one (common/VoxelBricks.glsl) the pool texels
 * of every brick that stores a voxel of the region, its border copies included. A clear costs far less on
 * llvmpipe than a shader writing each voxel.
 */
void clearLevel0(const VoxelVolume& volume, const gl::Texture& texture, const VoxelRegion& region);

} // namespace vct::render
