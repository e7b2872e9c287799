#pragma once

#include <glm/vec3.hpp>

namespace vct::doc {
class Document;
}

namespace vct::sync {

/** What a ray from the camera hits first. */
struct PickResult {
    int node = -1; ///< -1: nothing
    float distance = 0; ///< metres along the ray
    glm::vec3 point { 0.0f };
};

/**
 * Picks visible nodes by ray casting on the CPU against the document's meshes: no GL readback, so a click
 * never waits for the GPU. Bounding boxes reject most meshes before any triangle is tested.
 */
PickResult pickNode(const doc::Document& document, const glm::vec3& origin, const glm::vec3& direction);

} // namespace vct::sync
