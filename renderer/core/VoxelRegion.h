#pragma once

#include "core/VoxelGridFrame.h"
#include "scene/Aabb.h"

#include <glm/vec3.hpp>

#include <algorithm>

namespace vct::render {

/** A box of voxels [lo, hi) at level 0; empty when any hi <= lo. */
struct VoxelRegion {
    glm::ivec3 lo { 0 };
    glm::ivec3 hi { 0 };

    bool isEmpty() const { return hi.x <= lo.x || hi.y <= lo.y || hi.z <= lo.z; }
    glm::ivec3 size() const { return glm::max(hi - lo, glm::ivec3(0)); }
    static VoxelRegion whole(int resolution) { return { glm::ivec3(0), glm::ivec3(resolution) }; }
    /** The voxels a world box touches, grown by `margin` voxels, clipped to the grid. */
    static VoxelRegion around(const Aabb& box, const VoxelGridFrame& frame, int margin)
    {
        if (box.isEmpty())
            return {};
        const glm::ivec3 lo = glm::ivec3(glm::floor(frame.toGrid(box.min))) - margin;
        const glm::ivec3 hi = glm::ivec3(glm::floor(frame.toGrid(box.max))) + 1 + margin;
        return { glm::clamp(lo, glm::ivec3(0), glm::ivec3(frame.resolution)),
            glm::clamp(hi, glm::ivec3(0), glm::ivec3(frame.resolution)) };
    }
    VoxelRegion united(const VoxelRegion& other) const
    {
        if (isEmpty())
            return other;
        if (other.isEmpty())
            return *this;
        return { glm::min(lo, other.lo), glm::max(hi, other.hi) };
    }
};

} // namespace vct::render
