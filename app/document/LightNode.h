#pragma once

#include "scene/DirectionalLight.h"
#include "scene/PointLight.h"

#include <glm/vec3.hpp>

#include <QString>

namespace vct::doc {

enum class LightType { Point, Directional, Spot };

/**
 * A light as the user edits it: colour times a scalar intensity. Units: point and spot lights W/sr (radiant
 * intensity; a spot's on its axis), directional lights W/m^2 (irradiance on a surface facing the light).
 */
struct LightNode {
    quint64 id = 0;
    QString name;
    LightType type = LightType::Point;
    glm::vec3 position { 0.0f, 1.0f, 0.0f }; ///< Point lights, metres.
    glm::vec3 direction { 0.0f, -1.0f,
        0.0f }; ///< Directional lights: the way the light travels; spots: their axis.
    glm::vec3 color { 1.0f }; ///< Linear RGB, each in [0, 1] by convention.
    float intensity = 1.0f; ///< W/sr or W/m^2; the emitted value per channel is color * intensity.
    bool castsShadows = true;
    float spotInnerDeg = 30.0f; ///< Spots: full intensity within this angle of the axis, degrees.
    float spotOuterDeg = 45.0f; ///< Spots: none beyond this angle (at most 90).

    bool operator==(const LightNode& other) const = default;
    /** Point and spot lights are point lights to the renderers. */
    bool isPointLike() const { return type != LightType::Directional; }
    render::PointLight pointLight() const
    {
        render::PointLight p { position, color * intensity, castsShadows };
        if (type == LightType::Spot) {
            p.spotDirection
                = glm::length(direction) > 0.0f ? glm::normalize(direction) : glm::vec3(0.0f, -1.0f, 0.0f);
            p.spotInnerDeg = spotInnerDeg;
            p.spotOuterDeg = spotOuterDeg;
        }
        return p;
    }
    render::DirectionalLight directionalLight() const
    {
        return { direction, color * intensity, castsShadows };
    }
};

} // namespace vct::doc
