#include "core/ConeSet.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace vct::render {

namespace {

/// The ring's tilt in sets of 4 to 9 cones: of the tilts whose weights can match the lobe's mean cosine (from
/// 48.2 degrees, where the centre's weight reaches 0), the one that measured best on the reference scenes and
/// closed rooms (docs/ACCURACY.md, "The cone set's quadrature"). Sets of 2 and 3, split by Voronoi regions,
/// keep the 45 degrees they were measured with.
constexpr double kRingTiltDeg = 50.0;
constexpr double kVoronoiRingTiltDeg = 45.0;

std::vector<glm::vec3> coneAxes(int count)
{
    std::vector<glm::vec3> axes;
    if (count <= 9) {
        axes.emplace_back(0.0f, 0.0f, 1.0f);
        const float tilt = float(glm::radians(count >= 4 ? kRingTiltDeg : kVoronoiRingTiltDeg));
        for (int i = 0; i < count - 1; ++i) {
            const float phi = glm::two_pi<float>() * float(i) / float(count - 1);
            axes.emplace_back(std::sin(tilt) * std::cos(phi), std::sin(tilt) * std::sin(phi), std::cos(tilt));
        }
        return axes;
    }
    // Points of a Fibonacci spiral mapped to the hemisphere with cosine density: more cones where the lobe
    // weighs more.
    const float golden = glm::pi<float>() * (3.0f - std::sqrt(5.0f));
    for (int i = 0; i < count; ++i) {
        const float r = std::sqrt((float(i) + 0.5f) / float(count));
        const float phi = golden * float(i);
        axes.emplace_back(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - r * r)));
    }
    return axes;
}

} // namespace

ConeSet ConeSet::diffuse(int count)
{
    ConeSet set;
    set.m_directions = coneAxes(count < 1 ? 1 : count);
    const std::size_t cones = set.m_directions.size();
    if (cones >= 4 && cones <= 9) {
        // The normal and a ring of three or more (a ring of one or two cones has too few to share the lobe's
        // directions around the normal): weights that make the estimate exact for light constant over the
        // hemisphere or varying linearly with cos(theta), i.e. summing to one with a mean cosine of 2/3, the
        // cosine lobe's. Voronoi shares (below) gave each ring cone the
        // directions down to the horizon, which its narrow cone never looks at, for light from near the
        // normal: two plates under an emitter gathered 1.26x the path tracer's light (1.04x with these).
        const double ring = (1.0 / 3.0) / (1.0 - std::cos(glm::radians(kRingTiltDeg)));
        set.m_weights.push_back(float(1.0 - ring));
        for (std::size_t i = 1; i < cones; ++i)
            set.m_weights.push_back(float(ring / double(cones - 1)));
        return set;
    }
    // Stratified cosine-weighted quadrature: every sample carries the same share of the lobe, so each cone's
    // weight is the share of samples nearest to it.
    const int n = 384;
    std::vector<double> share(set.m_directions.size(), 0.0);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const float u = (float(i) + 0.5f) / float(n);
            const float v = (float(j) + 0.5f) / float(n);
            const float r = std::sqrt(u);
            const float phi = glm::two_pi<float>() * v;
            const glm::vec3 w(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u)));
            std::size_t best = 0;
            float bestDot = -2.0f;
            for (std::size_t c = 0; c < set.m_directions.size(); ++c) {
                const float d = glm::dot(w, set.m_directions[c]);
                if (d > bestDot) {
                    bestDot = d;
                    best = c;
                }
            }
            share[best] += 1.0;
        }
    for (double s : share)
        set.m_weights.push_back(float(s / (double(n) * double(n))));
    return set;
}

} // namespace vct::render
