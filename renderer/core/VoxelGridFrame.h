#pragma once

#include "scene/Aabb.h"

#include <glm/vec3.hpp>

namespace vct::render {

/**
 * Where the voxel grid sits in the world: a cube of `resolution`^3 cells fitted around the scene bounds.
 * The cube's side is the bounds' largest extent plus one cell of margin on each side, so geometry on the
 * bounds still lies inside after conservative enlargement; it is centred on the bounds.
 */
struct VoxelGridFrame {
    glm::vec3 origin { 0.0f }; ///< World position of the grid's min corner, metres.
    float extent = 1.0f; ///< Side of the cube, metres.
    int resolution = 1;

    bool operator==(const VoxelGridFrame&) const = default;

    float voxelSize() const { return extent / float(resolution); }
    int levelCount() const;
    /** World position to grid coordinates in [0, resolution]. */
    glm::vec3 toGrid(const glm::vec3& world) const { return (world - origin) / voxelSize(); }

    static VoxelGridFrame fit(const Aabb& bounds, int resolution);
};

} // namespace vct::render
