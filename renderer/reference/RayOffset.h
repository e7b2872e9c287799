#pragma once

#include <glm/vec3.hpp>

namespace vct::render {

/**
 * Moves a surface point off its surface along @p normal (the side the new ray leaves from), so a ray starting
 * there does not hit the surface it starts on. The step is a fixed number of float ULPs of each coordinate,
 * hence proportional to the coordinate's magnitude: it works at any scene scale without a tuned epsilon
 * (Waechter and Binder, "A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing Gems, 2019).
 */
glm::vec3 offsetRayOrigin(const glm::vec3& point, const glm::vec3& normal);

} // namespace vct::render
