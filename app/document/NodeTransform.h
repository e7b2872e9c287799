#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace vct::doc {

/**
 * The user's placement of a node, applied on top of the transform the model file gave its mesh:
 * world = matrix() * imported. Translation in metres, rotation as XYZ Euler angles in degrees.
 */
struct NodeTransform {
    glm::vec3 translation { 0.0f };
    glm::vec3 rotationDeg { 0.0f };
    glm::vec3 scale { 1.0f };

    /** T * Rz * Ry * Rx * S. */
    glm::mat4 matrix() const;
    bool operator==(const NodeTransform& other) const = default;
};

} // namespace vct::doc
