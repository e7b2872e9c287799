#include "core/AreaLightSet.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>

namespace vct::render {

namespace {

int findRoot(std::vector<int>& parent, int i)
{
    while (parent[std::size_t(i)] != i) {
        parent[std::size_t(i)] = parent[std::size_t(parent[std::size_t(i)])];
        i = parent[std::size_t(i)];
    }
    return i;
}

struct Triangle {
    glm::vec3 corners[3];
    int material = 0;
};

} // namespace

AreaLightSet AreaLightSet::fromScene(const Scene& scene)
{
    AreaLightSet set;
    const Aabb bounds = scene.bounds();
    // Corners closer than this are one: relative to the scene, as every tolerance is (tests/hardcases).
    const float weld = bounds.isEmpty() ? 0.0f : 1e-5f * glm::length(bounds.size());
    std::vector<Triangle> emitting;
    for (const Mesh& mesh : scene.meshes) {
        if (mesh.material < 0 || std::size_t(mesh.material) >= scene.materials.size())
            continue;
        const glm::vec3 emission = scene.materials[std::size_t(mesh.material)].usableEmission();
        if (emission == glm::vec3(0.0f))
            continue;
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            Triangle tri;
            tri.material = mesh.material;
            bool valid = true;
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t index = mesh.indices[t + std::size_t(k)];
                if (index >= mesh.positions.size()) {
                    valid = false;
                    break;
                }
                tri.corners[k] = glm::vec3(mesh.transform * glm::vec4(mesh.positions[index], 1.0f));
                valid = valid && std::isfinite(tri.corners[k].x) && std::isfinite(tri.corners[k].y)
                    && std::isfinite(tri.corners[k].z);
            }
            ++set.emissiveTriangles;
            const float area = valid ? 0.5f
                    * glm::length(
                        glm::cross(tri.corners[1] - tri.corners[0], tri.corners[2] - tri.corners[0]))
                                     : 0.0f;
            if (!valid || !(area > weld * weld)) {
                ++set.droppedTriangles;
                continue;
            }
            emitting.push_back(tri);
        }
    }
    if (emitting.empty())
        return set;
    if (emitting.size() > std::size_t(kMaxTriangles)) {
        set.note = std::to_string(emitting.size()) + " emissive triangles, more than the "
            + std::to_string(kMaxTriangles)
            + " lit as area lights: their light reaches surfaces through the voxels only";
        return set;
    }

    // Triangles of one material that share a corner form one light.
    std::vector<int> parent(emitting.size());
    std::iota(parent.begin(), parent.end(), 0);
    const auto key = [&](const glm::vec3& p, int material) {
        const glm::vec3 q = weld > 0.0f ? glm::floor(p / weld + 0.5f) : p;
        return std::tuple<int, float, float, float>(material, q.x, q.y, q.z);
    };
    std::map<std::tuple<int, float, float, float>, int> firstAt;
    for (std::size_t i = 0; i < emitting.size(); ++i)
        for (const glm::vec3& corner : emitting[i].corners) {
            const auto [it, inserted] = firstAt.emplace(key(corner, emitting[i].material), int(i));
            if (!inserted)
                parent[std::size_t(findRoot(parent, int(i)))] = findRoot(parent, it->second);
        }
    std::map<int, std::vector<std::size_t>> groups;
    for (std::size_t i = 0; i < emitting.size(); ++i)
        groups[findRoot(parent, int(i))].push_back(i);
    if (groups.size() > std::size_t(kMaxLights)) {
        set.note = std::to_string(groups.size()) + " separate emitters, more than the "
            + std::to_string(kMaxLights)
            + " lit as area lights: their light reaches surfaces through the voxels only";
        return set;
    }
    for (const auto& [root, members] : groups) {
        AreaLight light;
        light.radiance = scene.materials[std::size_t(emitting[members.front()].material)].usableEmission();
        light.firstTriangle = int(set.triangles.size() / 3);
        light.triangleCount = int(members.size());
        Aabb box;
        for (const std::size_t i : members) {
            const Triangle& tri = emitting[i];
            for (const glm::vec3& c : tri.corners) {
                set.triangles.push_back(c);
                box.extend(c);
            }
            light.area += 0.5f
                * glm::length(glm::cross(tri.corners[1] - tri.corners[0], tri.corners[2] - tri.corners[0]));
        }
        light.centre = box.center();
        for (std::size_t k = std::size_t(light.firstTriangle) * 3; k < set.triangles.size(); ++k)
            light.radius = std::max(light.radius, glm::length(set.triangles[k] - light.centre));
        // Planar when every triangle faces the first one's way and every corner lies in its plane.
        const glm::vec3* first = &set.triangles[std::size_t(light.firstTriangle) * 3];
        const glm::vec3 normal = glm::normalize(glm::cross(first[1] - first[0], first[2] - first[0]));
        const float offset = glm::dot(normal, first[0]);
        light.planar = true;
        for (std::size_t k = std::size_t(light.firstTriangle) * 3; k < set.triangles.size(); k += 3) {
            const glm::vec3* t = &set.triangles[k];
            const glm::vec3 n = glm::normalize(glm::cross(t[1] - t[0], t[2] - t[0]));
            for (int c = 0; c < 3; ++c)
                light.planar = light.planar
                    && std::abs(glm::dot(normal, t[c]) - offset) <= 1e-4f * std::max(light.radius, weld);
            light.planar = light.planar && glm::dot(n, normal) > 0.9999f;
        }
        if (light.planar) {
            light.planeNormal = normal;
            light.planeOffset = offset;
        }
        set.lights.push_back(light);
    }
    return set;
}

} // namespace vct::render
