#include "CameraController.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace vct::ui {

namespace {

glm::vec3 worldUp(const render::Camera& camera)
{
    return glm::length(camera.up) > 0.0f ? glm::normalize(camera.up) : glm::vec3(0, 1, 0);
}

} // namespace

render::Camera CameraController::orbit(const render::Camera& camera, float yawDeg, float pitchDeg)
{
    render::Camera result = camera;
    const glm::vec3 up = worldUp(camera);
    glm::vec3 offset = camera.position - camera.lookAt;
    const float distance = glm::length(offset);
    if (!(distance > 0.0f))
        return result;
    offset = glm::vec3(glm::rotate(glm::mat4(1.0f), glm::radians(-yawDeg), up) * glm::vec4(offset, 0.0f));
    const glm::vec3 right = glm::normalize(glm::cross(up, offset));
    // Keep away from the poles so the view never flips over.
    const float currentPitch
        = glm::degrees(std::asin(std::clamp(glm::dot(offset / distance, up), -1.0f, 1.0f)));
    const float newPitch = std::clamp(currentPitch + pitchDeg, -88.0f, 88.0f);
    offset = glm::vec3(glm::rotate(glm::mat4(1.0f), glm::radians(newPitch - currentPitch), -right)
        * glm::vec4(offset, 0.0f));
    result.position = camera.lookAt + offset;
    return result;
}

render::Camera CameraController::pan(const render::Camera& camera, float rightFraction, float upFraction)
{
    render::Camera result = camera;
    const glm::vec3 forward = camera.lookAt - camera.position;
    const float distance = glm::length(forward);
    if (!(distance > 0.0f))
        return result;
    const glm::vec3 right = glm::normalize(glm::cross(forward, worldUp(camera)));
    const glm::vec3 up = glm::normalize(glm::cross(right, forward));
    const float visibleHeight = 2.0f * distance * std::tan(glm::radians(camera.fovYDeg) * 0.5f);
    const glm::vec3 delta = (right * rightFraction + up * upFraction) * visibleHeight;
    result.position += delta;
    result.lookAt += delta;
    return result;
}

render::Camera CameraController::zoom(const render::Camera& camera, float steps)
{
    render::Camera result = camera;
    const glm::vec3 offset = camera.position - camera.lookAt;
    const float factor = std::pow(0.85f, steps);
    const glm::vec3 scaled = offset * factor;
    // Never pass through the look-at point or shrink to nothing.
    if (glm::length(scaled) > 1e-3f)
        result.position = camera.lookAt + scaled;
    return result;
}

render::Camera CameraController::fly(const render::Camera& camera, float forward, float right, float up)
{
    render::Camera result = camera;
    const glm::vec3 view = camera.lookAt - camera.position;
    if (!(glm::length(view) > 0.0f))
        return result;
    const glm::vec3 f = glm::normalize(view);
    const glm::vec3 r = glm::normalize(glm::cross(f, worldUp(camera)));
    const glm::vec3 delta = f * forward + r * right + worldUp(camera) * up;
    result.position += delta;
    result.lookAt += delta;
    return result;
}

render::Camera CameraController::frame(const render::Camera& camera, const render::Aabb& box)
{
    render::Camera result = camera;
    if (box.isEmpty())
        return result;
    glm::vec3 direction = camera.position - camera.lookAt;
    direction = glm::length(direction) > 0.0f ? glm::normalize(direction) : glm::vec3(0, 0, 1);
    const float radius = std::max(0.5f * glm::length(box.size()), 1e-3f);
    const float distance = radius / std::sin(glm::radians(camera.fovYDeg) * 0.5f);
    result.lookAt = box.center();
    result.position = box.center() + direction * distance;
    return result;
}

} // namespace vct::ui
