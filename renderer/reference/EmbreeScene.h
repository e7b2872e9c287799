#pragma once

#include "reference/SceneTriangle.h"
#include "scene/Material.h"
#include "scene/Scene.h"

#include <embree3/rtcore.h>

#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

namespace vct::render {

/**
 * The scene as one Embree triangle geometry: every mesh flattened into world space with its transform, with
 * per-triangle material and shading data kept beside it. Owns the Embree device and scene (released in the
 * destructor). Degenerate and non-finite triangles are dropped. Queries are thread-safe once constructed.
 */
class EmbreeScene {
public:
    /** The closest surface a ray meets. */
    struct Hit {
        unsigned triangle = 0; ///< Index into triangles().
        float distance = 0.0f; ///< Along the (unit) ray direction, metres.
        float u = 0.0f; ///< Barycentrics, see SceneTriangle::interpolate.
        float v = 0.0f;
    };

    /** Throws std::runtime_error when Embree cannot create its device or build the scene. */
    explicit EmbreeScene(const Scene& scene);
    ~EmbreeScene();
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    /** Closest hit with distance in [0, maxDistance); @p direction must be unit length. */
    std::optional<Hit> intersect(const glm::vec3& origin, const glm::vec3& direction,
        float maxDistance = std::numeric_limits<float>::infinity()) const;
    /** True when anything lies between origin and origin + maxDistance * direction. */
    bool occluded(const glm::vec3& origin, const glm::vec3& direction,
        float maxDistance = std::numeric_limits<float>::infinity()) const;

    const std::vector<SceneTriangle>& triangles() const { return m_triangles; }
    /** The scene's materials followed by one default material, which meshes with a bad index get. */
    const std::vector<Material>& materials() const { return m_materials; }
    std::size_t droppedTriangles() const { return m_droppedTriangles; }

private:
    void flatten(const Scene& scene);

    std::vector<SceneTriangle> m_triangles;
    std::vector<Material> m_materials;
    std::size_t m_droppedTriangles = 0;
    RTCDevice m_device = nullptr;
    RTCScene m_scene = nullptr;
};

} // namespace vct::render
