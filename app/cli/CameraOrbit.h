#pragma once

#include "scene/Camera.h"

#include <glm/gtc/matrix_transform.hpp>

namespace vct::cli {

/**
 * Turns the camera about its look-at point and up axis: the benchmarks' camera-only frames, small enough
 * (they use 0.5 degrees) that every frame sees nearly the same pixels as the full frames.
 */
inline void orbitCamera(render::Camera& camera, float degrees)
{
    const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(degrees), camera.up);
    camera.position = camera.lookAt + glm::vec3(turn * glm::vec4(camera.position - camera.lookAt, 0.0f));
}

} // namespace vct::cli
