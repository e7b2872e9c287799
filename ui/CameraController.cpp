#include "CameraController.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vector_relational.hpp>

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
    return orbitAbout(camera, camera.lookAt, yawDeg, pitchDeg);
}

render::Camera CameraController::orbitAbout(
    const render::Camera& camera, const glm::vec3& pivot, float yawDeg, float pitchDeg)
{
    render::Camera result = camera;
    const glm::vec3 view = camera.lookAt - camera.position;
    if (!(glm::length(view) > 0.0f))
        return result;
    const glm::vec3 up = worldUp(camera);
    const glm::mat4 yaw = glm::rotate(glm::mat4(1.0f), glm::radians(-yawDeg), up);
    const glm::vec3 forward = glm::normalize(glm::vec3(yaw * glm::vec4(view, 0.0f)));
    const glm::vec3 side = glm::cross(forward, up);
    if (!(glm::length(side) > 1e-6f))
        return result;
    const glm::vec3 right = glm::normalize(side);
    // Pitch counts as the camera rising above the pivot (the view looking down), as orbit() always did. Kept
    // away from the poles, where the right axis and with it the whole view would flip.
    const float currentPitch = glm::degrees(std::asin(std::clamp(-glm::dot(forward, up), -1.0f, 1.0f)));
    const float newPitch = std::clamp(currentPitch + pitchDeg, -88.0f, 88.0f);
    const glm::mat4 pitch = glm::rotate(glm::mat4(1.0f), glm::radians(newPitch - currentPitch), -right);
    // One rotation for position and look-at point alike: the camera turns as a rigid body about the pivot,
    // so the pivot keeps its place in the image.
    const glm::mat4 turn = pitch * yaw;
    result.position = pivot + glm::vec3(turn * glm::vec4(camera.position - pivot, 0.0f));
    result.lookAt = pivot + glm::vec3(turn * glm::vec4(camera.lookAt - pivot, 0.0f));
    return result;
}

render::Camera CameraController::focusAtDepth(const render::Camera& camera, const glm::vec3& point)
{
    render::Camera result = camera;
    const glm::vec3 view = camera.lookAt - camera.position;
    if (!(glm::length(view) > 0.0f))
        return result;
    const glm::vec3 forward = glm::normalize(view);
    const float depth = glm::dot(point - camera.position, forward);
    // Behind or at the camera there is no depth to move to.
    if (depth > std::max(camera.nearPlane, 1e-3f))
        result.lookAt = camera.position + forward * depth;
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

render::Camera CameraController::frameAll(const render::Camera& camera, const render::Aabb& sceneBounds)
{
    if (sceneBounds.isEmpty())
        return camera;
    const bool inside = glm::all(glm::greaterThanEqual(camera.position, sceneBounds.min))
        && glm::all(glm::lessThanEqual(camera.position, sceneBounds.max));
    if (!inside)
        return frame(camera, sceneBounds);
    render::Camera result = camera;
    const glm::vec3 toCentre = sceneBounds.center() - camera.position;
    const float distance = glm::length(toCentre);
    // At the centre itself, or straight above or below it, there is no direction to turn to that keeps the
    // up axis usable: the view stays as it is.
    if (!(distance > 1e-3f) || std::abs(glm::dot(toCentre / distance, worldUp(camera))) > 0.999f)
        return result;
    result.lookAt = sceneBounds.center();
    return result;
}

} // namespace vct::ui
