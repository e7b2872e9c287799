#pragma once

#include <glm/vec3.hpp>

namespace vct::render {

/**
 * The glossy lobe of our materials (normalised modified Phong, as the composite and the path tracer's
 * PhongBsdf evaluate it) times the receiver's cosine, per unit specular colour: (n + 2) / (2 pi) cos^n(alpha)
 * cos(theta), alpha the angle to the mirror direction, theta to the normal. Expressed in the frame where the
 * normal is +z and the viewer lies in the xz-plane on the +x side, which is all an isotropic lobe depends on.
 * Plain double arithmetic: it is what the linearly transformed cosines are fitted to (PhongLtcFitter) and
 * what tests integrate by brute force.
 */
class PhongLobe {
public:
    PhongLobe(double cosView, double shininess);

    double cosView() const { return m_cosView; }
    double shininess() const { return m_shininess; }
    glm::dvec3 mirror() const { return m_mirror; }

    /** The lobe times the cosine toward @p direction (unit), per steradian; 0 below the horizon. */
    double value(const glm::dvec3& direction) const;
    /** A direction drawn from cos^n about the mirror (below the horizon too) for @p u in [0, 1)^2 ... */
    glm::dvec3 sample(double u1, double u2) const;
    /** ... and its density per steradian. */
    double samplingDensity(const glm::dvec3& direction) const;
    /** The integral of value() over the sphere: the share of light the lobe reflects (below 1, as the
     * cosine and the horizon take their part). */
    double albedo() const { return m_albedo; }

private:
    double m_cosView;
    double m_shininess;
    glm::dvec3 m_mirror;
    double m_albedo = 0.0;
};

} // namespace vct::render
