#include "NewLight.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace vct::doc {

namespace {

float brightest(const glm::vec3& c)
{
    return std::max({ c.r, c.g, c.b, 0.0f });
}

/** Emitting area of a rect or disk, m². */
float areaOf(const LightNode& light)
{
    if (light.type == LightType::Disk)
        return 0.25f * glm::pi<float>() * light.areaWidth * light.areaWidth;
    return light.areaWidth * light.areaHeight;
}

/** A rect or disk of `light`'s size: a quarter of the scene's narrower horizontal extent (at most 1 m)
 * across, above its middle just under its top. Under the top, as a ceiling light: a closed room's ceiling
 * would shadow a light above it. */
void placeSurfaceLight(LightNode& light, const render::Aabb& bounds, const glm::vec3& lookAt)
{
    light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    if (bounds.isEmpty()) {
        light.position = lookAt + glm::vec3(0.0f, 1.0f, 0.0f);
        return;
    }
    const glm::vec3 extent = bounds.size();
    const float horizontal = std::min(extent.x, extent.z);
    const float across = horizontal > 0.0f ? horizontal : std::max({ extent.x, extent.y, extent.z });
    const float side = across > 0.0f ? std::min(1.0f, 0.25f * across) : 1.0f;
    light.areaWidth = side;
    light.areaHeight = side;
    const glm::vec3 centre = bounds.center();
    light.position = { centre.x, bounds.max.y - std::min(1.0f, 0.05f * extent.y), centre.z };
}

} // namespace

float NewLight::irradianceAt(const LightNode& light, const glm::vec3& point)
{
    const float strength = brightest(light.color) * light.intensity;
    if (light.type == LightType::Directional)
        return strength;
    const glm::vec3 toPoint = point - light.position;
    const float distanceSquared = glm::dot(toPoint, toPoint);
    if (light.isSurface()) {
        // On the axis of a disk of the same area, facing it: E = π L A / (π d² + A); zero behind it.
        const float area = areaOf(light);
        const float facing = glm::length(light.direction) > 0.0f && distanceSquared > 0.0f
            ? glm::dot(glm::normalize(light.direction), toPoint) / std::sqrt(distanceSquared)
            : 1.0f;
        return facing > 0.0f
            ? glm::pi<float>() * strength * area / (glm::pi<float>() * distanceSquared + area) * facing
            : 0.0f;
    }
    float irradiance = strength / std::max(distanceSquared, 1e-12f);
    if (light.type == LightType::Spot && distanceSquared > 0.0f)
        irradiance *= light.pointLight().spotFactor(toPoint / std::sqrt(distanceSquared));
    return irradiance;
}

LightNode NewLight::make(LightType type, const render::Aabb& bounds, const glm::vec3& lookAt,
    const std::vector<LightNode>& existing)
{
    LightNode light;
    light.type = type;
    if (type == LightType::Directional)
        light.direction = glm::vec3(-0.3f, -1.0f, -0.2f);
    else if (light.isSurface())
        placeSurfaceLight(light, bounds, lookAt);
    else
        // Where the user is looking is inside the scene more often than any fixed point.
        light.position = lookAt;

    float wanted = 0.0f;
    int counted = 0;
    for (const LightNode& other : existing) {
        const float e = irradianceAt(other, lookAt);
        if (std::isfinite(e)) {
            wanted += e;
            ++counted;
        }
    }
    wanted = counted > 0 && wanted > 0.0f ? wanted / float(counted) : glm::pi<float>();
    const float diagonal = bounds.isEmpty() ? 0.0f : glm::length(bounds.size());
    const float distance = diagonal > 0.0f ? 0.25f * diagonal : 1.0f;
    if (type == LightType::Directional) {
        light.intensity = wanted;
    } else if (light.isSurface()) {
        const float area = areaOf(light);
        light.intensity
            = wanted * (glm::pi<float>() * distance * distance + area) / (glm::pi<float>() * area);
    } else {
        light.intensity = wanted * distance * distance;
    }
    if (!std::isfinite(light.intensity) || !(light.intensity > 0.0f))
        light.intensity = 1.0f;
    // Two significant digits: a value a person would type, and one the panel shows as it is.
    const float unit = std::pow(10.0f, std::floor(std::log10(light.intensity)) - 1.0f);
    light.intensity = std::round(light.intensity / unit) * unit;
    return light;
}

} // namespace vct::doc
