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
    bool castsShadows = true; ///< false: lights through everything (a surface light may say so)
    /// All triangles in one plane, facing planeNormal (dot(planeNormal, x) = planeOffset): the shadow cone
    /// then stops short of that plane rather than of the bounding sphere.
    bool planar = false;
    glm::vec3 planeNormal { 0.0f };
    float planeOffset = 0.0f;
};

/**
 * The scene's area lights, for direct light per pixel and per voxel: first its surface lights (rectangles and
 * disks, which are lights, on with direct light), then its emissive triangles (emission, on with emission).
 * That order lets a frame use a prefix of the table. When the emissive triangles do not fit the limits they
 * are left out and their emission reaches surfaces through the voxels only, as light the cones gather
 * (`meshEmittersAnalytic()` is false; `note` says why).
 */
struct AreaLightSet {
    static constexpr int kMaxLights = 16;
    static constexpr int kMaxTriangles = 256;

    std::vector<AreaLight> lights; ///< the surface lights' first, then the emitters'
    std::vector<glm::vec3> triangles; ///< world-space corners, three per triangle, counter-clockwise front
    int surfaceLightCount = 0; ///< the first lights: the scene's surface lights that can emit
    std::size_t emissiveTriangles = 0; ///< in the scene, with a positive, finite emission
    std::size_t droppedTriangles = 0; ///< of those, degenerate or non-finite (no area to emit from)
    std::size_t droppedSurfaceLights = 0; ///< zero-sized, non-finite or beyond the limits
    /// 0, or how many separate emitters were merged into fewer lights (nearest first, one material each) to
    /// fit kMaxLights: their light stays exact, their shadows are traced toward each cluster as one light.
    std::size_t clusteredEmitters = 0;
    std::string note; ///< empty, or what is not lit as an area light, and why
    std::string emissiveNote; ///< empty, or why the emissive triangles are not in the set

    int emitterLightCount() const { return int(lights.size()) - surfaceLightCount; }
    /** True when every emitting triangle of the scene is in the set: its emission stays out of the voxels. */
    bool meshEmittersAnalytic() const { return emitterLightCount() > 0 && emissiveNote.empty(); }
    /** The set of a scene: surface lights, then emissive materials' triangles grouped by connectivity. */
    static AreaLightSet fromScene(const Scene& scene);

private:
    void addSurfaceLights(const Scene& scene);
    void addEmitters(const Scene& scene, float weld);
    /** Appends a light made of `corners` (three per triangle), with its bounds and plane. */
    void addLight(const glm::vec3& radiance, const std::vector<glm::vec3>& corners, float weld);
};

} // namespace vct::render
