#pragma once

#include <glm/vec3.hpp>

#include <QString>

namespace vct::doc {

enum class LightType { Point, Directional };

/**
 * A light as the user edits it: colour times a scalar intensity. Units: point lights W/sr (radiant
 * intensity), directional lights W/m^2 (irradiance on a surface facing the light).
 */
struct LightNode {
    quint64 id = 0;
    QString name;
    LightType type = LightType::Point;
    glm::vec3 position{0.0f, 1.0f, 0.0f};   ///< Point lights, metres.
    glm::vec3 direction{0.0f, -1.0f, 0.0f}; ///< Directional lights: the way the light travels.
    glm::vec3 color{1.0f};                  ///< Linear RGB, each in [0, 1] by convention.
    float intensity = 1.0f;                 ///< W/sr or W/m^2; the emitted value per channel is color * intensity.
    bool castsShadows = true;

    bool operator==(const LightNode& other) const = default;
};

} // namespace vct::doc
