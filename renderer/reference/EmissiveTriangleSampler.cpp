#include "reference/EmissiveTriangleSampler.h"

#include <algorithm>
#include <cmath>

namespace vct::render {

namespace {

double luminance(const glm::vec3& c)
{
    return 0.2126 * double(c.r) + 0.7152 * double(c.g) + 0.0722 * double(c.b);
}

} // namespace

EmissiveTriangleSampler::EmissiveTriangleSampler(
    const std::vector<SceneTriangle>& triangles, const std::vector<Material>& materials)
    : m_pdfArea(triangles.size(), 0.0f)
    , m_sceneTriangles(triangles)
{
    double total = 0.0;
    std::vector<double> weights;
    for (unsigned t = 0; t < triangles.size(); ++t) {
        const Material& material = materials[std::size_t(triangles[t].material)];
        // A blue-only emitter still emits: fall back to the channel sum so it is never left unsampled.
        double power = luminance(material.emission);
        if (!(power > 0.0))
            power = double(material.emission.r + material.emission.g + material.emission.b) / 3.0;
        const double weight = double(triangles[t].area) * power;
        if (!(weight > 0.0) || !std::isfinite(weight))
            continue;
        m_triangles.push_back(t);
        weights.push_back(weight);
        total += weight;
        m_cdf.push_back(total);
    }
    for (std::size_t i = 0; i < m_triangles.size(); ++i) {
        const unsigned t = m_triangles[i];
        m_pdfArea[t] = float(weights[i] / total / double(triangles[t].area));
    }
}

EmissiveTriangleSampler::Sample EmissiveTriangleSampler::sample(const glm::vec3& u) const
{
    const double target = double(u.x) * m_cdf.back();
    const auto it = std::upper_bound(m_cdf.begin(), m_cdf.end(), target);
    const std::size_t index = std::min(std::size_t(it - m_cdf.begin()), m_triangles.size() - 1);
    const unsigned t = m_triangles[index];
    const SceneTriangle& triangle = m_sceneTriangles[t];
    // Uniform by area: the square-root warp of the unit square onto the triangle.
    const float root = std::sqrt(u.y);
    const float b1 = 1.0f - root, b2 = u.z * root;
    Sample result;
    result.triangle = t;
    result.position
        = (1.0f - b1 - b2) * triangle.vertices[0] + b1 * triangle.vertices[1] + b2 * triangle.vertices[2];
    result.pdfArea = m_pdfArea[t];
    return result;
}

float EmissiveTriangleSampler::pdfArea(unsigned triangle) const
{
    return triangle < m_pdfArea.size() ? m_pdfArea[triangle] : 0.0f;
}

} // namespace vct::render
