#include "sync/NodePicker.h"

#include "document/Document.h"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include <limits>

namespace vct::sync {

namespace {

// Moeller-Trumbore; returns the distance or a negative value on a miss.
float intersect(
    const glm::vec3& o, const glm::vec3& d, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c)
{
    const glm::vec3 e1 = b - a, e2 = c - a;
    const glm::vec3 p = glm::cross(d, e2);
    const float det = glm::dot(e1, p);
    if (std::abs(det) < 1e-12f)
        return -1.0f;
    const float inv = 1.0f / det;
    const glm::vec3 s = o - a;
    const float u = glm::dot(s, p) * inv;
    if (u < 0.0f || u > 1.0f)
        return -1.0f;
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(d, q) * inv;
    if (v < 0.0f || u + v > 1.0f)
        return -1.0f;
    return glm::dot(e2, q) * inv;
}

bool hitsBox(const glm::vec3& o, const glm::vec3& d, const render::Aabb& box, float maxDistance)
{
    float t0 = 0.0f, t1 = maxDistance;
    for (int axis = 0; axis < 3; ++axis) {
        const float inv = 1.0f / d[axis];
        float near = (box.min[axis] - o[axis]) * inv, far = (box.max[axis] - o[axis]) * inv;
        if (near > far)
            std::swap(near, far);
        t0 = std::max(t0, near);
        t1 = std::min(t1, far);
        if (t0 > t1)
            return false;
    }
    return true;
}

} // namespace

PickResult pickNode(const doc::Document& document, const glm::vec3& origin, const glm::vec3& direction)
{
    PickResult best;
    float bestDistance = std::numeric_limits<float>::max();
    const glm::vec3 dir = glm::normalize(direction);
    const auto& nodes = document.state().nodes;
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        if (!nodes[n].visible)
            continue;
        const render::Scene& source = document.sourceScene(nodes[n].source);
        if (nodes[n].mesh < 0 || std::size_t(nodes[n].mesh) >= source.meshes.size())
            continue;
        const render::Mesh& mesh = source.meshes[std::size_t(nodes[n].mesh)];
        const glm::mat4 world = document.nodeWorldTransform(int(n));
        std::vector<glm::vec3> positions(mesh.positions.size());
        render::Aabb box;
        for (std::size_t i = 0; i < positions.size(); ++i) {
            positions[i] = glm::vec3(world * glm::vec4(mesh.positions[i], 1.0f));
            box.extend(positions[i]);
        }
        if (box.isEmpty() || !hitsBox(origin, dir, box, bestDistance))
            continue;
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            const float t = intersect(origin, dir, positions[mesh.indices[i]], positions[mesh.indices[i + 1]],
                positions[mesh.indices[i + 2]]);
            if (t > 0.0f && t < bestDistance) {
                bestDistance = t;
                best = { int(n), t, origin + dir * t };
            }
        }
    }
    return best;
}

} // namespace vct::sync
