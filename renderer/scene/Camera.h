#pragma once

#include <glm/vec3.hpp>

namespace vct::render {

/** A pinhole camera, as in the shared reference camera files (NAME.camera.json). */
struct Camera {
    glm::vec3 position { 0.0f, 0.0f, 3.8f };
    glm::vec3 lookAt { 0.0f };
    glm::vec3 up { 0.0f, 1.0f, 0.0f };
    float fovYDeg = 40.0f; ///< Vertical field of view, degrees.
    float nearPlane = 0.01f; ///< Metres; far plane is derived from the scene bounds.
};

} // namespace vct::render
