#include "cli/BlackImageCheck.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

#include <cstdio>

namespace vct::cli {

namespace {

std::string format(const glm::vec3& v)
{
    char text[96];
    std::snprintf(text, sizeof text, "(%g, %g, %g)", double(v.x), double(v.y), double(v.z));
    return text;
}

} // namespace

std::string blackImageWarning(
    const render::RadianceImage& image, const render::Scene& scene, const render::Camera& camera)
{
    for (const glm::vec3& p : image.pixels)
        if (p.x > 0.0f || p.y > 0.0f || p.z > 0.0f)
            return {};
    const bool lit = !scene.pointLights.empty() || !scene.directionalLights.empty()
        || !scene.surfaceLights.empty() || scene.hasEmissiveMaterial();
    if (!lit)
        return {};
    const render::Aabb bounds = scene.bounds();
    if (bounds.isEmpty() || scene.triangleCount() == 0)
        return "the image is black: the scene has lights but no geometry";
    const glm::vec3 size = bounds.size();
    const glm::vec3 toCentre = bounds.center() - camera.position;
    const glm::vec3 forward = camera.lookAt - camera.position;
    const bool inside = glm::all(glm::greaterThanEqual(camera.position, bounds.min))
        && glm::all(glm::lessThanEqual(camera.position, bounds.max));
    std::string why = "the image is black although the scene has lights or emitters; the camera at "
        + format(camera.position) + " looking at " + format(camera.lookAt) + ", the geometry within "
        + format(bounds.min) + ".." + format(bounds.max) + " (" + format(size) + " across)";
    if (!inside && glm::dot(toCentre, forward) <= 0.0f)
        return why + ": the camera looks away from the scene";
    const float diagonal = glm::length(size);
    // The bounding sphere against a cone around the view direction that holds the whole frame.
    const float distance = glm::length(toCentre);
    if (!inside && distance > 0.5f * diagonal && glm::length(forward) > 0.0f) {
        const float apart
            = std::acos(std::clamp(glm::dot(toCentre / distance, glm::normalize(forward)), -1.0f, 1.0f));
        const float frame
            = std::atan(std::tan(glm::radians(0.5f * camera.fovYDeg)) * 2.0f); // any aspect up to 2:1
        if (apart > frame + std::asin(std::min(0.5f * diagonal / distance, 1.0f)))
            return why + ": the scene lies outside the camera's view";
    }
    if (camera.nearPlane >= glm::length(toCentre) + diagonal)
        return why + ": the near plane (" + std::to_string(camera.nearPlane)
            + ") lies beyond the whole scene";
    return why + ": it may see no geometry, or only surfaces in shadow that reflect no light";
}

} // namespace vct::cli
