#include "scene/SurfaceLight.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace vct::render {

namespace {

bool finite(const glm::vec3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The regular polygon's circumradius that gives it the area of a disk of radius 1: pi = n/2 sin(2 pi/n) R^2.
float diskPolygonRadiusScale()
{
    const float n = float(SurfaceLight::kDiskSides);
    return std::sqrt(2.0f * glm::pi<float>() / (n * std::sin(2.0f * glm::pi<float>() / n)));
}

} // namespace

bool SurfaceLight::axes(glm::vec3& widthAxis, glm::vec3& heightAxis, glm::vec3& front) const
{
    const float length = glm::length(direction);
    if (!finite(direction) || !(length > 0.0f) || !std::isfinite(length))
        return false;
    front = direction / length;
    // The horizontal axis across the direction; for a light facing straight up or down, world x.
    glm::vec3 horizontal = glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), front);
    if (glm::length(horizontal) < 1e-4f)
        horizontal = glm::vec3(1.0f, 0.0f, 0.0f);
    horizontal = glm::normalize(horizontal - front * glm::dot(horizontal, front));
    const float angle = std::isfinite(rotationDeg) ? glm::radians(rotationDeg) : 0.0f;
    const glm::vec3 other = glm::cross(front, horizontal);
    widthAxis = std::cos(angle) * horizontal + std::sin(angle) * other;
    heightAxis = glm::cross(front, widthAxis);
    return true;
}

float SurfaceLight::area() const
{
    if (shape == Shape::Disk)
        return glm::pi<float>() * 0.25f * width * width;
    return width * height;
}

std::vector<glm::vec3> SurfaceLight::triangles() const
{
    std::vector<glm::vec3> corners;
    glm::vec3 u, v, front;
    const bool sized = std::isfinite(width) && width > 0.0f
        && (shape == Shape::Disk || (std::isfinite(height) && height > 0.0f));
    if (!sized || !finite(centre) || !axes(u, v, front))
        return corners;
    if (shape == Shape::Rectangle) {
        const glm::vec3 a = centre - 0.5f * width * u - 0.5f * height * v;
        const glm::vec3 b = centre + 0.5f * width * u - 0.5f * height * v;
        const glm::vec3 c = centre + 0.5f * width * u + 0.5f * height * v;
        const glm::vec3 d = centre - 0.5f * width * u + 0.5f * height * v;
        // cross(u, v) = front: a, b, c run counter-clockwise seen from the front.
        corners = { a, b, c, a, c, d };
        return corners;
    }
    const float radius = 0.5f * width * diskPolygonRadiusScale();
    for (int k = 0; k < kDiskSides; ++k) {
        const float a0 = 2.0f * glm::pi<float>() * float(k) / float(kDiskSides);
        const float a1 = 2.0f * glm::pi<float>() * float(k + 1) / float(kDiskSides);
        corners.push_back(centre);
        corners.push_back(centre + radius * (std::cos(a0) * u + std::sin(a0) * v));
        corners.push_back(centre + radius * (std::cos(a1) * u + std::sin(a1) * v));
    }
    return corners;
}

} // namespace vct::render
