#include "ViewProjection.h"

#include "scene/CameraBasis.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace vct::ui {

std::optional<QPointF> ViewProjection::toScreen(const glm::vec3& world) const
{
    if (image.isEmpty())
        return std::nullopt;
    const render::CameraBasis basis = render::CameraBasis::of(camera);
    const glm::vec3 offset = world - camera.position;
    const float depth = glm::dot(offset, basis.forward);
    if (!(depth > 0.0f))
        return std::nullopt;
    // CameraBasis::through() backwards: view depth 1 spans tanHalfFovY up and that times the aspect across.
    const float aspect = float(image.width() / image.height());
    const float x = glm::dot(offset, basis.right) / (depth * basis.tanHalfFovY * aspect);
    const float y = glm::dot(offset, basis.up) / (depth * basis.tanHalfFovY);
    if (!std::isfinite(x) || !std::isfinite(y))
        return std::nullopt;
    return QPointF(image.x() + (0.5 * x + 0.5) * image.width(), image.y() + (0.5 - 0.5 * y) * image.height());
}

float ViewProjection::metresPerPixel(const glm::vec3& world) const
{
    if (image.isEmpty())
        return 0.0f;
    const render::CameraBasis basis = render::CameraBasis::of(camera);
    const float depth = glm::dot(world - camera.position, basis.forward);
    return depth > 0.0f ? 2.0f * depth * basis.tanHalfFovY / float(image.height()) : 0.0f;
}

} // namespace vct::ui
