#include "Enclosure.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace vct::doc {

namespace {

constexpr int kSphereRays = 256;
constexpr float kEnclosedShare = 0.95f;
constexpr float kLevel = 0.5f; // sin(30 degrees)

/** Evenly spread unit directions (the Fibonacci sphere). */
std::vector<glm::vec3> sphere()
{
    std::vector<glm::vec3> result;
    const float golden = 3.14159265f * (3.0f - std::sqrt(5.0f));
    for (int i = 0; i < kSphereRays; ++i) {
        const float y = 1.0f - 2.0f * (float(i) + 0.5f) / float(kSphereRays);
        const float r = std::sqrt(std::max(0.0f, 1.0f - y * y));
        const float phi = golden * float(i);
        result.emplace_back(r * std::cos(phi), y, r * std::sin(phi));
    }
    return result;
}

/** Möller–Trumbore, either side of the triangle: whether the ray meets it ahead of its origin. */
bool hits(
    const glm::vec3& origin, const glm::vec3& dir, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c)
{
    const glm::vec3 e1 = b - a, e2 = c - a;
    const glm::vec3 p = glm::cross(dir, e2);
    const float det = glm::dot(e1, p);
    if (!(std::abs(det) > 0.0f))
        return false;
    const float inv = 1.0f / det;
    const glm::vec3 s = origin - a;
    const float u = glm::dot(s, p) * inv;
    if (u < 0.0f || u > 1.0f)
        return false;
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(dir, q) * inv;
    if (v < 0.0f || u + v > 1.0f)
        return false;
    return glm::dot(e2, q) * inv > 0.0f;
}

/** Which of `rays` from `point` meet a triangle of `scene`. */
std::vector<bool> raysMet(
    const render::Scene& scene, const glm::vec3& point, const std::vector<glm::vec3>& rays)
{
    std::vector<bool> met(rays.size(), false);
    std::size_t metCount = 0;
    std::vector<glm::vec3> world;
    for (const render::Mesh& mesh : scene.meshes) {
        world.clear();
        for (const glm::vec3& p : mesh.positions)
            world.push_back(glm::vec3(mesh.transform * glm::vec4(p, 1.0f)));
        for (std::size_t t = 0; t + 2 < mesh.indices.size() && metCount < rays.size(); t += 3) {
            const std::uint32_t ia = mesh.indices[t], ib = mesh.indices[t + 1], ic = mesh.indices[t + 2];
            if (ia >= world.size() || ib >= world.size() || ic >= world.size())
                continue;
            for (std::size_t r = 0; r < rays.size(); ++r)
                if (!met[r] && hits(point, rays[r], world[ia], world[ib], world[ic])) {
                    met[r] = true;
                    ++metCount;
                }
        }
    }
    return met;
}

/** The sphere's rays with a y component in [minY, maxY]. */
std::vector<glm::vec3> band(float minY, float maxY)
{
    static const std::vector<glm::vec3> kSphere = sphere();
    std::vector<glm::vec3> rays;
    for (const glm::vec3& d : kSphere)
        if (d.y >= minY && d.y <= maxY)
            rays.push_back(d);
    return rays;
}

/** The share of `met` among the rays with a y component in [minY, maxY]; 0 without any. */
float shareOf(const std::vector<glm::vec3>& rays, const std::vector<bool>& met, float minY, float maxY)
{
    int inBand = 0, hit = 0;
    for (std::size_t r = 0; r < rays.size(); ++r)
        if (rays[r].y >= minY && rays[r].y <= maxY) {
            ++inBand;
            hit += met[r] ? 1 : 0;
        }
    return inBand > 0 ? float(hit) / float(inBand) : 0.0f;
}

} // namespace

float Enclosure::hitShare(const render::Scene& scene, const glm::vec3& point, float minY, float maxY)
{
    const std::vector<glm::vec3> rays = band(minY, maxY);
    return shareOf(rays, raysMet(scene, point, rays), minY, maxY);
}

bool Enclosure::insideRoom(const render::Scene& scene, const glm::vec3& point)
{
    const std::vector<glm::vec3> rays = band(-kLevel, 1.0f);
    const std::vector<bool> met = raysMet(scene, point, rays);
    return shareOf(rays, met, -kLevel, kLevel) >= kEnclosedShare
        && shareOf(rays, met, kLevel, 1.0f) >= kEnclosedShare;
}

bool Enclosure::encloses(const render::Scene& scene, const glm::vec3& point)
{
    return hitShare(scene, point, -kLevel, kLevel) >= kEnclosedShare;
}

bool Enclosure::roofed(const render::Scene& scene, const glm::vec3& point)
{
    return hitShare(scene, point, kLevel, 1.0f) >= kEnclosedShare;
}

} // namespace vct::doc
