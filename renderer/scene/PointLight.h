#pragma once

#include <glm/vec3.hpp>

namespace vct::render {

/** An isotropic point light. Radiance reflected by a Lambert surface at distance d: albedo/pi * I/d^2 * cos. */
struct PointLight {
    glm::vec3 position{0.0f};   ///< World space, metres.
    glm::vec3 intensity{1.0f};  ///< Radiant intensity, W/sr per channel.
    bool castsShadows = true;
};

} // namespace vct::render
