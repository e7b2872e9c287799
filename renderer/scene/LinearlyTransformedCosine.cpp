#include "scene/LinearlyTransformedCosine.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace vct::render {

namespace {

constexpr double kPi = 3.14159265358979323846;

} // namespace

LinearlyTransformedCosine::LinearlyTransformedCosine(const glm::dmat3& m, int power)
    : m_power(power == 3 ? 3 : 1)
    , m_matrix(m)
    , m_inverse(glm::inverse(m))
    , m_inverseDeterminant(std::abs(glm::determinant(m_inverse)))
{
}

double LinearlyTransformedCosine::density(const glm::dvec3& direction) const
{
    const glm::dvec3 original = m_inverse * direction;
    const double length = glm::length(original);
    const double cosine = original.z / length;
    if (cosine <= 0.0)
        return 0.0;
    const double base = (m_power + 1) / (2.0 * kPi) * std::pow(cosine, m_power);
    return base * m_inverseDeterminant / (length * length * length);
}

glm::dvec3 LinearlyTransformedCosine::sample(double u1, double u2) const
{
    const double cosTheta = std::pow(1.0 - u1, 1.0 / (m_power + 1)), phi = 2.0 * kPi * u2;
    const double radius = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    const glm::dvec3 base { radius * std::cos(phi), radius * std::sin(phi), cosTheta };
    return glm::normalize(m_matrix * base);
}

double LinearlyTransformedCosine::triangleIntegral(
    const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) const
{
    const std::array<glm::dvec3, 3> corners { a, b, c };
    return polygonIntegral(corners);
}

double LinearlyTransformedCosine::polygonIntegral(std::span<const glm::dvec3> corners) const
{
    // Below the receiver's horizon the lobe is zero; the fitted density need not be, so the polygon is
    // clipped there first, then mapped, then clipped again to the cosine's own hemisphere.
    std::array<glm::dvec3, kMaxCorners + 2> aboveHorizon;
    const std::size_t count = clipToUpperHalf(corners, aboveHorizon);
    for (std::size_t i = 0; i < count; ++i)
        aboveHorizon[i] = m_inverse * aboveHorizon[i];
    return clampedCosineIntegral(std::span<const glm::dvec3>(aboveHorizon.data(), count), m_power);
}

std::size_t LinearlyTransformedCosine::clipToUpperHalf(
    std::span<const glm::dvec3> corners, std::array<glm::dvec3, kMaxCorners + 2>& clipped)
{
    const std::size_t n = std::min<std::size_t>(corners.size(), kMaxCorners + 1);
    std::size_t count = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3& p0 = corners[i];
        const glm::dvec3& p1 = corners[(i + 1) % n];
        if (p0.z >= 0.0)
            clipped[count++] = p0;
        if ((p0.z >= 0.0) != (p1.z >= 0.0) && count <= kMaxCorners + 1)
            clipped[count++] = p0 + (p1 - p0) * (p0.z / (p0.z - p1.z));
    }
    return count < 3 ? 0 : count;
}

double LinearlyTransformedCosine::clampedCosineIntegral(
    const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
{
    const std::array<glm::dvec3, 3> corners { a, b, c };
    return clampedCosineIntegral(corners, 1);
}

double LinearlyTransformedCosine::clampedCosineIntegral(std::span<const glm::dvec3> corners, int power)
{
    std::array<glm::dvec3, kMaxCorners + 2> clipped;
    const std::size_t count = clipToUpperHalf(corners, clipped);
    // Over the polygon's great-circle edges: theta n_z (Lambert's contour integral, twice the cosine's
    // integral) and n_z times the integral of z^2 along the edge, which the cube's integral needs (the
    // surface divergence theorem on the sphere with the field z^2 times z's tangential part gives int z^3 =
    // (2 int z - sum over edges of conormal_z int z^2 ds) / 4; Arvo 1995's axial moments).
    double lambert = 0.0, cubic = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        const glm::dvec3 a = glm::normalize(clipped[i]), b = glm::normalize(clipped[(i + 1) % count]);
        const glm::dvec3 c = glm::cross(a, b);
        const double s = glm::length(c);
        if (s <= 1e-15)
            continue;
        const double theta = std::atan2(s, glm::dot(a, b)), nz = c.z / s;
        lambert += theta * nz;
        if (power == 3) {
            // u(t) = a cos t + along sin t for t in [0, theta], `along` the unit tangent toward b.
            const double za = a.z, zt = (b.z - glm::dot(a, b) * a.z) / s;
            const double sin2 = std::sin(2.0 * theta);
            const double squares = za * za * (0.5 * theta + 0.25 * sin2)
                + zt * zt * (0.5 * theta - 0.25 * sin2) + za * zt * std::sin(theta) * std::sin(theta);
            cubic += nz * squares;
        }
    }
    const double side
        = lambert >= 0.0 ? 1.0 : -1.0; // the conormals point out of the polygon for either winding
    const double cosineIntegral = 0.5 * side * lambert; // of cos over the polygon
    if (power != 3)
        return cosineIntegral / kPi;
    return (2.0 * cosineIntegral + side * cubic) / 4.0 / (0.5 * kPi);
}

} // namespace vct::render
