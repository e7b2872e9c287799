#pragma once

#include "gl/Buffer.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace vct::render {

/**
 * Triangles a compute shader picked out of the runs it went over (GpuScene::dispatchTriangles), for one
 * indirect draw a run (GpuScene::drawListed). Each run has a segment of the index buffer as long as the run
 * and a command (count, instances, first index, base vertex, base instance) whose count the shader raises by
 * three for each triangle it lists: a pass can then draw a part of a scene without the CPU knowing which.
 */
struct ListedTriangles {
    static constexpr std::size_t kCommandWords = 5; ///< as glDrawElementsIndirect reads them

    gl::Buffer indices; ///< the runs' segments, one after the other
    gl::Buffer commands; ///< kCommandWords per run
    std::vector<std::size_t> runMeshes; ///< the mesh each run draws, in order

    /**
     * Starts a listing over runs of these meshes and triangle counts: buffers large enough, every count zero.
     */
    void reset(std::vector<std::size_t> meshes, const std::vector<std::uint32_t>& runTriangles);
};

} // namespace vct::render
