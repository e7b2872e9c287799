#pragma once

#include "core/VoxelGridFrame.h"
#include "gl/Texture.h"

#include <cstdint>
#include <future>
#include <vector>

namespace vct::render {

/**
 * Where the grid around the scene is closed in (core/EnclosedSpace): r8, 1 in empty cells no light can leave,
 * 0 elsewhere, made by EnclosurePass from the static meshes. The diffuse gathers that start in such a cell
 * scale what each cone saw over what the voxels let through (common/ConeTracing.glsl).
 *
 * The pass builds the cells on a worker thread while the GL voxelizes; the first reader takes the result with
 * finish(), which uploads it (ConeTracingSetup, and Renderer::renderFrame before the frame ends, so a build
 * never outlives the scene it reads).
 */
struct EnclosureMap {
    /** What a build made: a byte per cell (EnclosedSpace::texels) and how many cells are closed in. */
    struct Build {
        std::vector<std::uint8_t> texels;
        std::size_t enclosedCells = 0;
    };

    gl::Texture texture;
    VoxelGridFrame grid; ///< the cells of `texture`
    std::uint64_t version = 0; ///< grows with each rebuild, when it starts
    std::size_t enclosedCells = 0; ///< valid after finish()
    bool inUse = false; ///< built for the current frame's settings (enclosed_space=on)
    std::future<Build> pending; ///< a build not taken yet

    /** Waits for a pending build and uploads it; nothing when none is pending. */
    void finish();
    /** Waits for a pending build and drops it. */
    void abandon();
};

} // namespace vct::render
