#pragma once

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <span>

namespace vct::render {

/**
 * A linearly transformed cosine (Heitz, Dupuy, Hill and Neubelt 2016): the clamped cosine distribution
 * cos(theta) / pi about +z, its directions mapped by a matrix M and renormalised. Its integral over a polygon
 * is the cosine's over the polygon mapped back by M^-1, which Lambert's contour formula gives exactly; this
 * is the CPU twin of shaders/common/AreaLights.glsl's glossy lobe, for the fit and the tests.
 */
class LinearlyTransformedCosine {
public:
    /** @p power 1: the clamped cosine (Heitz et al.); 3: its cube, cos^3(theta) 2 / pi, whose lighter tails
     * fit narrow lobes better at twice the cost per edge. */
    explicit LinearlyTransformedCosine(const glm::dmat3& m, int power = 1);

    const glm::dmat3& matrix() const { return m_matrix; }
    const glm::dmat3& inverse() const { return m_inverse; }

    /** The density per steradian toward @p direction (unit). */
    double density(const glm::dvec3& direction) const;
    /** A direction drawn from the density for @p u in [0, 1)^2. */
    glm::dvec3 sample(double u1, double u2) const;
    /** The density's integral over triangle (a, b, c), given relative to the origin (either winding). */
    double triangleIntegral(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) const;
    /** The same over a convex polygon of up to kMaxCorners corners whose edges are great circles as seen from
     * the origin (either winding), after clipping it to the receiver's side, z >= 0, where the lobe lives. */
    double polygonIntegral(std::span<const glm::dvec3> corners) const;

    /**
     * The clamped cosine's integral over triangle (a, b, c) after clipping it to z >= 0: its form factor, the
     * cosine-weighted solid angle over pi.
     */
    static double clampedCosineIntegral(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);
    /** The same for the normalised cos^power (1 or 3) over a polygon. */
    static double clampedCosineIntegral(std::span<const glm::dvec3> corners, int power);

    static constexpr int kMaxCorners = 16;

    int power() const { return m_power; }

private:
    /** The part of the polygon with z >= 0 into @p clipped; its corner count, 0 when nothing is left. */
    static std::size_t clipToUpperHalf(
        std::span<const glm::dvec3> corners, std::array<glm::dvec3, kMaxCorners + 2>& clipped);

    int m_power;
    glm::dmat3 m_matrix;
    glm::dmat3 m_inverse;
    double m_inverseDeterminant;
};

} // namespace vct::render
