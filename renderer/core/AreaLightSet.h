#pragma once

#include "scene/Scene.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace vct::render {

/**
 * One area light: a connected set of emissive triangles of one material (a lamp's quad, the six faces of a
 * glowing box). Its unshadowed irradiance is exact, summed over its triangles
 * (shaders/common/AreaLights.glsl); its visibility is one cone traced toward the bounding sphere through the
 * voxel opacity.
 */
struct AreaLight {
    glm::vec3 radiance { 0.0f }; ///< emitted radiance, W/(m^2 sr), front faces only
    glm::vec3 centre { 0.0f }; ///< of the bounding sphere, world metres
    float radius = 0.0f; ///< of the bounding sphere
    float area = 0.0f; ///< m^2
    int firstTriangle = 0; ///< into AreaLightSet::triangles (three corners each)
    int triangleCount = 0;
    /// All triangles in one plane, facing planeNormal (dot(planeNormal, x) = planeOffset): the shadow cone
    /// then stops short of that plane rather than of the bounding sphere.
    bool planar = false;
    glm::vec3 planeNormal { 0.0f };
    float planeOffset = 0.0f;
};

/**
 * The scene's emissive triangles as area lights, for direct light per pixel and per voxel. When they do not
 * fit the limits the set is left incomplete and emission reaches surfaces through the voxels only, as light
 * the cones gather (`analytic()` is false; `note` says why).
 */
struct AreaLightSet {
    static constexpr int kMaxLights = 16;
    static constexpr int kMaxTriangles = 256;

    std::vector<AreaLight> lights;
    std::vector<glm::vec3> triangles; ///< world-space corners, three per triangle, counter-clockwise front
    std::size_t emissiveTriangles = 0; ///< in the scene, with a positive, finite emission
    std::size_t droppedTriangles = 0; ///< of those, degenerate or non-finite (no area to emit from)
    std::string note; ///< empty, or why the set is not used (too many emitters)

    /** True when every emitting triangle of the scene is in the set: the renderer then lights with it. */
    bool analytic() const { return !lights.empty() && note.empty(); }
    /** The set of a scene: emissive materials' triangles, transformed, grouped by connectivity. */
    static AreaLightSet fromScene(const Scene& scene);
};

} // namespace vct::render
