#pragma once

#include <glm/vec3.hpp>

namespace vct::render {

/** A light at infinity, such as the sun. */
struct DirectionalLight {
    glm::vec3 direction { 0.0f, -1.0f, 0.0f }; ///< The way the light travels (need not be normalised).
    glm::vec3 irradiance { 1.0f }; ///< W/m^2 on a surface facing the light, per channel.
    bool castsShadows = true;
    /// Degrees: the disk the light comes from (the sun's is about 0.53), which softens its shadows; the
    /// irradiance stays the same. 0 is a hard shadow filtered to the shadow map's texel.
    float angularDiameterDeg = 0.0f;

    bool operator==(const DirectionalLight& other) const = default;
};

} // namespace vct::render
