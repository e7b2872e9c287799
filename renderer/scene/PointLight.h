#pragma once

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace vct::render {

/**
 * A point light, isotropic or a spot. Radiance reflected by a Lambert surface at distance d: albedo/pi *
 * I/d^2
 * * cos, times spotFactor(). A spot keeps its full intensity within spotInnerDeg of its axis, none beyond
 * spotOuterDeg, and a smoothstep in the cosine between (the angles are from the axis, as glTF's).
 */
struct PointLight {
    glm::vec3 position { 0.0f }; ///< World space, metres.
    glm::vec3 intensity { 1.0f }; ///< Radiant intensity on the axis, W/sr per channel.
    bool castsShadows = true;
    glm::vec3 spotDirection { 0.0f, -1.0f, 0.0f }; ///< The way the spot points (unit length).
    float spotInnerDeg = 180.0f; ///< 180 and 180: an isotropic point light.
    float spotOuterDeg = 180.0f;
    /// Metres: a sphere of this radius with the same intensity (radiance I / (pi r^2)), whose shadows are
    /// soft. 0 is a point with a hard shadow filtered to the shadow map's texel. Its unshadowed light stays
    /// the point's (I/d^2), exact while the receiver is a few radii away.
    float radius = 0.0f;

    bool operator==(const PointLight& other) const = default;
    bool isSpot() const { return spotOuterDeg < 180.0f; }
    float cosOuter() const { return isSpot() ? std::cos(glm::radians(spotOuterDeg)) : -2.0f; }
    float cosInner() const
    {
        return isSpot() ? std::cos(glm::radians(std::min(spotInnerDeg, spotOuterDeg))) : -1.0f;
    }
    /** The share of the intensity sent toward unit direction @p out (from the light). */
    float spotFactor(const glm::vec3& out) const
    {
        if (!isSpot())
            return 1.0f;
        const float inner = cosInner(), outer = cosOuter();
        const float c = glm::dot(out, spotDirection);
        if (inner - outer <= 1e-6f)
            return c >= outer ? 1.0f : 0.0f;
        const float t = std::clamp((c - outer) / (inner - outer), 0.0f, 1.0f);
        return t * t * (3.0f - 2.0f * t);
    }
};

} // namespace vct::render
