#include "SceneRebase.h"

#include <glm/ext/matrix_double3x3.hpp>
#include <glm/ext/matrix_double4x4.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <limits>

namespace vct::doc {

namespace {

glm::vec3 moved(const glm::vec3& p, const glm::dvec3& origin)
{
    return glm::vec3(glm::dvec3(p) - origin);
}

} // namespace

glm::dvec3 SceneRebase::originFor(const render::Scene& scene)
{
    glm::dvec3 low(std::numeric_limits<double>::max());
    glm::dvec3 high(-std::numeric_limits<double>::max());
    for (const render::Mesh& mesh : scene.meshes) {
        const glm::dmat4 transform(mesh.transform);
        for (const glm::vec3& p : mesh.positions) {
            const glm::dvec3 world(transform * glm::dvec4(glm::dvec3(p), 1.0));
            low = glm::min(low, world);
            high = glm::max(high, world);
        }
    }
    if (!(low.x <= high.x))
        return glm::dvec3(0.0);
    const glm::dvec3 centre = 0.5 * (low + high);
    return glm::length(centre) > glm::length(high - low) ? centre : glm::dvec3(0.0);
}

void SceneRebase::rebase(render::Scene& scene, const glm::dvec3& origin)
{
    if (origin == glm::dvec3(0.0))
        return;
    for (render::Mesh& mesh : scene.meshes) {
        if (mesh.dynamic) {
            mesh.transform[3] = glm::vec4(moved(glm::vec3(mesh.transform[3]), origin), 1.0f);
            continue;
        }
        const glm::dmat4 transform(mesh.transform);
        for (glm::vec3& p : mesh.positions)
            p = glm::vec3(glm::dvec3(transform * glm::dvec4(glm::dvec3(p), 1.0)) - origin);
        const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(transform)));
        for (glm::vec3& n : mesh.normals) {
            const glm::dvec3 turned = normalMatrix * glm::dvec3(n);
            const double length = glm::length(turned);
            // A singular transform has flattened the mesh to zero area: its normals no longer matter.
            if (std::isfinite(length) && length > 0.0)
                n = glm::vec3(turned / length);
        }
        mesh.transform = glm::mat4(1.0f);
    }
    for (render::PointLight& light : scene.pointLights)
        light.position = moved(light.position, origin);
    for (render::SurfaceLight& light : scene.surfaceLights)
        light.centre = moved(light.centre, origin);
    scene.camera.position = moved(scene.camera.position, origin);
    scene.camera.lookAt = moved(scene.camera.lookAt, origin);
    scene.origin += origin;
}

} // namespace vct::doc
