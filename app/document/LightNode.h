#pragma once

#include "scene/DirectionalLight.h"
#include "scene/PointLight.h"
#include "scene/SurfaceLight.h"

#include <glm/vec3.hpp>

#include <QString>

namespace vct::doc {

enum class LightType { Point, Directional, Spot, Rect, Disk };

/**
 * A light as the user edits it: colour times a scalar intensity. Units: point and spot lights W/sr (radiant
 * intensity; a spot's on its axis), directional lights W/m^2 (irradiance on a surface facing the light),
 * rect and disk lights W/(m^2 sr) (the radiance their front face emits).
 */
struct LightNode {
    quint64 id = 0;
    QString name;
    LightType type = LightType::Point;
    glm::vec3 position { 0.0f, 1.0f, 0.0f }; ///< Point and spot lights, metres; rects and disks: the centre.
    /// Directional lights: the way the light travels; spots: their axis; rects and disks: the way the front
    /// face looks.
    glm::vec3 direction { 0.0f, -1.0f, 0.0f };
    glm::vec3 color { 1.0f }; ///< Linear RGB, each in [0, 1] by convention.
    /// W/sr, W/m^2 or W/(m^2 sr) by type; the emitted value per channel is color * intensity.
    float intensity = 1.0f;
    bool castsShadows = true;
    float spotInnerDeg = 30.0f; ///< Spots: full intensity within this angle of the axis, degrees.
    float spotOuterDeg = 45.0f; ///< Spots: none beyond this angle (at most 90).
    float areaWidth = 1.0f; ///< Rects: metres along the width axis; disks: the diameter.
    float areaHeight = 1.0f; ///< Rects: metres along the height axis; unused by disks.
    float areaRotationDeg = 0.0f; ///< Rects: turn about the direction, degrees (SurfaceLight::rotationDeg).
    /// Point and spot lights: metres, a sphere of the same intensity whose shadows are soft; 0 is a point.
    float radius = 0.0f;
    /// Directional lights: degrees across the disk the light comes from (the sun's is about 0.53), which
    /// softens the shadows without changing the irradiance; 0 is a light from one direction. Below 90.
    float angularDiameterDeg = 0.0f;

    bool operator==(const LightNode& other) const = default;
    /** Point and spot lights are point lights to the renderers. */
    bool isPointLike() const { return type == LightType::Point || type == LightType::Spot; }
    /** Rect and disk lights are surface lights to the renderers. */
    bool isSurface() const { return type == LightType::Rect || type == LightType::Disk; }
    render::PointLight pointLight() const
    {
        render::PointLight p { position, color * intensity, castsShadows };
        p.radius = radius;
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
        render::DirectionalLight d { direction, color * intensity, castsShadows };
        d.angularDiameterDeg = angularDiameterDeg;
        return d;
    }
    render::SurfaceLight surfaceLight() const
    {
        render::SurfaceLight s;
        s.shape = type == LightType::Disk ? render::SurfaceLight::Shape::Disk
                                          : render::SurfaceLight::Shape::Rectangle;
        s.centre = position;
        s.direction = direction; // unnormalised, as stored: the conversion back is then exact
        s.width = areaWidth;
        s.height = areaHeight;
        s.rotationDeg = areaRotationDeg;
        s.radiance = color * intensity;
        s.castsShadows = castsShadows;
        return s;
    }
};

} // namespace vct::doc
