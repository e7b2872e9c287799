#pragma once

#include "reference/SceneTriangle.h"
#include "scene/Material.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace vct::render {

/**
 * Picks points on emissive triangles for next-event estimation, each triangle with probability proportional
 * to area x luminance of its emission, then uniformly by area, so bright and large emitters get the samples.
 */
class EmissiveTriangleSampler {
public:
    /** A point on an emitter. */
    struct Sample {
        unsigned triangle = 0;
        glm::vec3 position { 0.0f };
        float pdfArea = 0.0f; ///< Density of picking this point, per m^2 of emitter area.
    };

    /** Keeps a reference to @p triangles, which must outlive the sampler (EmbreeScene owns them). */
    EmissiveTriangleSampler(
        const std::vector<SceneTriangle>& triangles, const std::vector<Material>& materials);

    bool isEmpty() const { return m_triangles.empty(); }
    /** @p u in [0,1)^3: the first number picks the triangle, the other two the point on it. */
    Sample sample(const glm::vec3& u) const;
    /** The area density sample() has at any point of @p triangle (zero when it does not emit). */
    float pdfArea(unsigned triangle) const;

private:
    std::vector<unsigned> m_triangles; ///< Indices of emissive triangles.
    std::vector<double> m_cdf; ///< Running weight sums, last = total.
    std::vector<float> m_pdfArea; ///< Per scene triangle: selection probability / area.
    const std::vector<SceneTriangle>& m_sceneTriangles;
};

} // namespace vct::render
