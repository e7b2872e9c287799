#include "reference/CameraRays.h"

#include "scene/CameraBasis.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace vct::render {

CameraRays::CameraRays(const Camera& camera, int width, int height, const Aabb& sceneBounds)
    : m_position(camera.position)
    , m_width(float(std::max(1, width)))
    , m_height(float(std::max(1, height)))
{
    const CameraBasis basis = CameraBasis::of(camera);
    m_forward = basis.forward;
    m_right = basis.right * (basis.tanHalfFovY * m_width / m_height);
    m_up = basis.up * basis.tanHalfFovY;
    // Renderer.cpp's cameraMatrices(): the near plane follows the far plane, which follows the scene.
    const float sceneRadius = std::max(0.5f * glm::length(sceneBounds.size()), 1e-3f);
    const float farPlane = glm::length(camera.position - sceneBounds.center()) + 2.0f * sceneRadius;
    m_nearPlane = std::max(camera.nearPlane, farPlane * 1e-5f);
}

CameraRays::Ray CameraRays::ray(int x, int y, const glm::vec2& offset) const
{
    const float ndcX = 2.0f * (float(x) + offset.x) / m_width - 1.0f;
    const float ndcY = 1.0f - 2.0f * (float(y) + offset.y) / m_height;
    const glm::vec3 throughImagePlane = m_forward + ndcX * m_right + ndcY * m_up; // at unit view depth
    Ray result;
    result.direction = glm::normalize(throughImagePlane);
    result.origin = m_position + m_nearPlane * throughImagePlane;
    return result;
}

} // namespace vct::render
