#pragma once

#include "reference/CameraRays.h"
#include "reference/EmbreeScene.h"
#include "reference/EmissiveTriangleSampler.h"
#include "reference/LinearTexture.h"
#include "reference/Pcg32.h"
#include "reference/ReferenceSettings.h"
#include "scene/DirectionalLight.h"
#include "scene/PointLight.h"
#include "scene/Scene.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <vector>

namespace vct::render {

/**
 * Unidirectional path tracing of one camera ray: next-event estimation towards point, directional and
 * emissive triangle lights with shadow rays, BSDF sampling of the Phong mixture, multiple importance sampling
 * (power heuristic) between the two for emissive triangles (point and directional lights are reached by
 * next-event estimation only), and Russian roulette with survival probability from the path throughput.
 *
 * Conventions (those of the GL renderer and of the Cycles references in tests/data/reference): emission is
 * radiance leaving the front face only (counter-clockwise winding) and the back of an emitter only reflects;
 * surfaces are shaded two-sided from the side the ray arrives on; lights that do not cast shadows light
 * through geometry. Holds references to nothing: it copies the scene data it needs. Thread-safe: radiance()
 * may run on many threads at once.
 */
class PathTracer {
public:
    PathTracer(const Scene& scene, const ReferenceSettings& settings);

    /**
     * One sample of the radiance arriving along @p ray, W/(m^2 sr) per channel. @p rayCount is increased by
     * the number of rays traced (closest-hit and shadow).
     */
    glm::vec3 radiance(const CameraRays::Ray& ray, Pcg32& random, std::uint64_t& rayCount) const;

    const EmbreeScene& geometry() const { return m_geometry; }

private:
    glm::vec3 albedoAt(const Material& material, const SceneTriangle& triangle, float u, float v) const;

    /** Next-event estimation from a point light with a radius: a direction uniform over the sphere's cone. */
    glm::vec3 sphereLightSample(const PointLight& light, const glm::vec3& position, const glm::vec3& origin,
        Pcg32& random, std::uint64_t& rayCount,
        const std::function<glm::vec3(const glm::vec3&)>& reflected) const;
    /** Next-event estimation from the rectangle and disk lights, which no ray can hit: weight one, no MIS. */
    glm::vec3 surfaceLightSample(const glm::vec3& position, const glm::vec3& origin, Pcg32& random,
        std::uint64_t& rayCount, const std::function<glm::vec3(const glm::vec3&)>& reflected) const;

    EmbreeScene m_geometry;
    EmissiveTriangleSampler m_emitters;
    std::vector<SceneTriangle>
        m_surfaceTriangles; ///< the surface lights' triangles: sampled, never intersected
    std::vector<Material> m_surfaceMaterials; ///< one per surface light, its radiance as emission
    std::vector<bool> m_surfaceShadows; ///< per surface light: whether it casts shadows
    EmissiveTriangleSampler m_surfaceEmitters;
    std::vector<LinearTexture> m_textures;
    std::vector<PointLight> m_pointLights;
    std::vector<DirectionalLight> m_directionalLights;
    std::vector<float> m_sunCosHalf; ///< per directional light: the cosine of its angular radius
    int m_maxBounces;
    int m_rouletteStartBounce;
};

} // namespace vct::render
