#include "core/ConeSet.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace vct::render {

namespace {

std::vector<glm::vec3> coneAxes(int count)
{
    std::vector<glm::vec3> axes;
    if (count <= 9) {
        axes.emplace_back(0.0f, 0.0f, 1.0f);
        const float tilt = glm::radians(45.0f);
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
