#include "core/AreaLightSet.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
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

glm::vec3 centroid(const std::vector<std::size_t>& members, const std::vector<Triangle>& triangles)
{
    glm::vec3 sum(0.0f);
    for (const std::size_t i : members)
        sum += triangles[i].corners[0] + triangles[i].corners[1] + triangles[i].corners[2];
    return sum / float(3 * members.size());
}

std::size_t distinctMaterials(
    const std::vector<std::vector<std::size_t>>& clusters, const std::vector<Triangle>& triangles)
{
    std::vector<int> materials;
    for (const std::vector<std::size_t>& members : clusters)
        materials.push_back(triangles[members.front()].material);
    std::sort(materials.begin(), materials.end());
    return std::size_t(std::unique(materials.begin(), materials.end()) - materials.begin());
}

/**
 * Merges the nearest clusters of one material (one radiance per light) until at most `room` are left; false
 * when the materials alone are more than that. The light of a cluster stays exact without shadows (its
 * triangles' irradiance is summed), only its visibility is traced toward the cluster as one light.
 */
bool clusterEmitters(
    std::vector<std::vector<std::size_t>>& clusters, const std::vector<Triangle>& triangles, std::size_t room)
{
    if (clusters.size() <= room)
        return true;
    if (distinctMaterials(clusters, triangles) > room)
        return false;
    std::vector<glm::vec3> centres;
    for (const std::vector<std::size_t>& members : clusters)
        centres.push_back(centroid(members, triangles));
    while (clusters.size() > room) {
        std::size_t bestA = 0, bestB = 0;
        float best = std::numeric_limits<float>::max();
        for (std::size_t a = 0; a < clusters.size(); ++a)
            for (std::size_t b = a + 1; b < clusters.size(); ++b) {
                if (triangles[clusters[a].front()].material != triangles[clusters[b].front()].material)
                    continue;
                const glm::vec3 d = centres[a] - centres[b];
                const float distance2 = glm::dot(d, d);
                if (distance2 < best) {
                    best = distance2;
                    bestA = a;
                    bestB = b;
                }
            }
        clusters[bestA].insert(clusters[bestA].end(), clusters[bestB].begin(), clusters[bestB].end());
        centres[bestA] = centroid(clusters[bestA], triangles);
        clusters.erase(clusters.begin() + std::ptrdiff_t(bestB));
        centres.erase(centres.begin() + std::ptrdiff_t(bestB));
    }
    return true;
}

} // namespace

AreaLightSet AreaLightSet::fromScene(const Scene& scene)
{
    AreaLightSet set;
    const Aabb bounds = scene.bounds();
    // Corners closer than this are one: relative to the scene, as every tolerance is (tests/hardcases).
    const float weld = bounds.isEmpty() ? 0.0f : 1e-5f * glm::length(bounds.size());
    set.addSurfaceLights(scene);
    set.addEmitters(scene, weld);
    if (!set.emissiveNote.empty())
        set.note += (set.note.empty() ? "" : "; ") + set.emissiveNote;
    return set;
}

void AreaLightSet::addSurfaceLights(const Scene& scene)
{
    std::size_t beyondLimits = 0;
    for (const SurfaceLight& surface : scene.surfaceLights) {
        Material asMaterial;
        asMaterial.emission = surface.radiance;
        const glm::vec3 radiance = asMaterial.usableEmission();
        if (radiance == glm::vec3(0.0f))
            continue; // dark: nothing to light with, nothing lost
        const std::vector<glm::vec3> corners = surface.triangles();
        if (corners.empty()) {
            ++droppedSurfaceLights;
            continue;
        }
        if (int(lights.size()) >= kMaxLights || triangles.size() / 3 + corners.size() / 3 > kMaxTriangles) {
            ++droppedSurfaceLights;
            ++beyondLimits;
            continue;
        }
        addLight(radiance, corners, 0.0f);
        lights.back().castsShadows = surface.castsShadows;
        ++surfaceLightCount;
    }
    if (droppedSurfaceLights > beyondLimits)
        note = std::to_string(droppedSurfaceLights - beyondLimits)
            + " rectangle or disk lights without a usable size, direction or position light nothing";
    if (beyondLimits > 0)
        note += (note.empty() ? "" : "; ") + std::to_string(beyondLimits)
            + " rectangle or disk lights beyond the " + std::to_string(kMaxLights) + " area lights of "
            + std::to_string(kMaxTriangles) + " triangles light nothing";
}

void AreaLightSet::addEmitters(const Scene& scene, float weld)
{
    std::vector<Triangle> emitting;
    for (const Mesh& mesh : scene.meshes) {
        if (!mesh.visible || mesh.material < 0 || std::size_t(mesh.material) >= scene.materials.size())
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
            ++emissiveTriangles;
            const float area = valid ? 0.5f
                    * glm::length(
                        glm::cross(tri.corners[1] - tri.corners[0], tri.corners[2] - tri.corners[0]))
                                     : 0.0f;
            if (!valid || !(area > weld * weld)) {
                ++droppedTriangles;
                continue;
            }
            emitting.push_back(tri);
        }
    }
    if (emitting.empty())
        return;
    const std::size_t triangleRoom = std::size_t(kMaxTriangles) - triangles.size() / 3;
    if (emitting.size() > triangleRoom) {
        emissiveNote = std::to_string(emitting.size()) + " emissive triangles, more than the "
            + std::to_string(triangleRoom)
            + " lit as area lights: their light reaches surfaces through the voxels only";
        return;
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
    const std::size_t lightRoom = std::size_t(kMaxLights) - lights.size();
    std::vector<std::vector<std::size_t>> clusters;
    for (auto& [root, members] : groups)
        clusters.push_back(std::move(members));
    const std::size_t separate = clusters.size();
    if (!clusterEmitters(clusters, emitting, lightRoom)) {
        emissiveNote = std::to_string(separate) + " separate emitters of "
            + std::to_string(distinctMaterials(clusters, emitting)) + " emissions, more than the "
            + std::to_string(lightRoom)
            + " lit as area lights: their light reaches surfaces through the voxels only";
        return;
    }
    if (clusters.size() < separate)
        clusteredEmitters = separate;
    for (const std::vector<std::size_t>& members : clusters) {
        std::vector<glm::vec3> corners;
        for (const std::size_t i : members)
            corners.insert(corners.end(), std::begin(emitting[i].corners), std::end(emitting[i].corners));
        addLight(
            scene.materials[std::size_t(emitting[members.front()].material)].usableEmission(), corners, weld);
    }
}

void AreaLightSet::addLight(const glm::vec3& radiance, const std::vector<glm::vec3>& corners, float weld)
{
    AreaLight light;
    light.radiance = radiance;
    light.firstTriangle = int(triangles.size() / 3);
    light.triangleCount = int(corners.size() / 3);
    Aabb box;
    for (std::size_t k = 0; k + 2 < corners.size(); k += 3) {
        light.area
            += 0.5f * glm::length(glm::cross(corners[k + 1] - corners[k], corners[k + 2] - corners[k]));
        for (std::size_t c = 0; c < 3; ++c)
            box.extend(corners[k + c]);
    }
    triangles.insert(triangles.end(), corners.begin(), corners.end());
    light.centre = box.center();
    for (const glm::vec3& c : corners)
        light.radius = std::max(light.radius, glm::length(c - light.centre));
    // Planar when every triangle faces the first one's way and every corner lies in its plane.
    const glm::vec3 normal = glm::normalize(glm::cross(corners[1] - corners[0], corners[2] - corners[0]));
    const float offset = glm::dot(normal, corners[0]);
    light.planar = true;
    for (std::size_t k = 0; k + 2 < corners.size(); k += 3) {
        const glm::vec3* t = &corners[k];
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
    lights.push_back(light);
}

} // namespace vct::render
