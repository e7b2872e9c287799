#pragma once

#include "scene/Aabb.h"
#include "scene/Camera.h"
#include "scene/DirectionalLight.h"
#include "scene/Material.h"
#include "scene/Mesh.h"
#include "scene/PointLight.h"
#include "scene/SurfaceLight.h"
#include "scene/TextureImage.h"

#include <glm/ext/vector_double3.hpp>

#include <vector>

namespace vct::render {

/** Everything the renderer draws: plain data, no GL. */
struct Scene {
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<TextureImage> textures;
    std::vector<PointLight> pointLights;
    std::vector<DirectionalLight> directionalLights;
    std::vector<SurfaceLight> surfaceLights; ///< Rectangle and disk area lights (no geometry).
    Camera camera; ///< The scene's suggested view.
    /**
     * Where the scene's coordinate origin lies in the world the files describe, in metres. Zero unless a
     * scene far from the world's origin was rebased on loading (doc::SceneRebase), so that its float
     * coordinates stay small.
     */
    glm::dvec3 origin { 0.0 };

    /** World-space bounds of all meshes (transforms applied). */
    Aabb bounds() const;
    /** World-space bounds of the static meshes only, or of the dynamic ones. */
    Aabb bounds(bool dynamicMeshes) const;
    std::size_t triangleCount() const;
    bool hasEmissiveMaterial() const;
    bool hasGlossyMaterial() const;
};

} // namespace vct::render
