#include "scene/Scene.h"

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

namespace vct::render {

namespace {

Aabb meshBounds(const Mesh& mesh)
{
    Aabb box;
    for (const glm::vec3& p : mesh.positions)
        box.extend(glm::vec3(mesh.transform * glm::vec4(p, 1.0f)));
    return box;
}

} // namespace

Aabb Scene::bounds() const
{
    Aabb box;
    for (const Mesh& mesh : meshes)
        if (mesh.visible)
            box.extend(meshBounds(mesh));
    return box;
}

Aabb Scene::bounds(bool dynamicMeshes) const
{
    Aabb box;
    for (const Mesh& mesh : meshes)
        if (mesh.visible && mesh.dynamic == dynamicMeshes)
            box.extend(meshBounds(mesh));
    return box;
}

std::size_t Scene::triangleCount() const
{
    std::size_t n = 0;
    for (const Mesh& mesh : meshes)
        n += mesh.visible ? mesh.triangleCount() : 0;
    return n;
}

bool Scene::hasEmissiveMaterial() const
{
    for (const Material& m : materials)
        if (m.isEmissive())
            return true;
    return false;
}

bool Scene::hasGlossyMaterial() const
{
    for (const Material& m : materials)
        if (m.isGlossy())
            return true;
    return false;
}

} // namespace vct::render
