#pragma once

#include <glm/vec3.hpp>

#include <vector>

namespace vct::render {

/**
 * The diffuse cones around a surface normal, in tangent space (+z = normal), with weights summing to one, so
 * the estimate is ρ * Σ w_i L_i with no fudge factor and a uniform environment of radiance L reflects exactly
 * ρ L. A normal and a ring (4 to 9 cones) weigh so that light varying linearly with cos(theta) is integrated
 * exactly too (mean cosine Σ w_i cos θ_i = 2/3, the cosine lobe's); other sets split the lobe:
 * weight_i = (1/pi) * integral of cos(theta) over the directions closer to cone i's axis than to any other.
 */
class ConeSet {
public:
    /** count 1..32: 1 = the normal; 2..9 = normal plus a ring tilted 50° (45° for 2 and 3); more = a
     * cosine-weighted spiral. */
    static ConeSet diffuse(int count);

    const std::vector<glm::vec3>& directions() const { return m_directions; }
    const std::vector<float>& weights() const { return m_weights; }
    int size() const { return int(m_directions.size()); }

private:
    std::vector<glm::vec3> m_directions;
    std::vector<float> m_weights;
};

} // namespace vct::render
