#include "scene/LinearlyTransformedCosine.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace vct::render {

namespace {

constexpr double kPi = 3.14159265358979323846;

/** theta times the z-part of the unit normal of the plane through the origin, a and b (unit): one edge of
 * Lambert's contour integral. */
double edgeTerm(const glm::dvec3& a, const glm::dvec3& b)
{
    const glm::dvec3 c = glm::cross(a, b);
    const double s = glm::length(c);
    return s > 1e-15 ? std::atan2(s, glm::dot(a, b)) * c.z / s : 0.0;
}

} // namespace

LinearlyTransformedCosine::LinearlyTransformedCosine(const glm::dmat3& m)
    : m_matrix(m)
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
    return cosine / kPi * m_inverseDeterminant / (length * length * length);
}

glm::dvec3 LinearlyTransformedCosine::sample(double u1, double u2) const
{
    const double radius = std::sqrt(u1), phi = 2.0 * kPi * u2;
    const glm::dvec3 cosine { radius * std::cos(phi), radius * std::sin(phi),
        std::sqrt(std::max(0.0, 1.0 - u1)) };
    return glm::normalize(m_matrix * cosine);
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
    return clampedCosineIntegral(std::span<const glm::dvec3>(aboveHorizon.data(), count));
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
    return clampedCosineIntegral(corners);
}

double LinearlyTransformedCosine::clampedCosineIntegral(std::span<const glm::dvec3> corners)
{
    std::array<glm::dvec3, kMaxCorners + 2> clipped;
    const std::size_t count = clipToUpperHalf(corners, clipped);
    double sum = 0.0;
    for (std::size_t i = 0; i < count; ++i)
        sum += edgeTerm(glm::normalize(clipped[i]), glm::normalize(clipped[(i + 1) % count]));
    return std::abs(sum) / (2.0 * kPi);
}

} // namespace vct::render
