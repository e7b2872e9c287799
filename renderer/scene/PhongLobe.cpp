#include "scene/PhongLobe.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace vct::render {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kAlbedoSamples = 64; // per axis: the integrand is smooth once the lobe is sampled

/** A unit vector at polar angle acos(cosPolar) and azimuth phi about @p axis. */
glm::dvec3 around(const glm::dvec3& axis, double cosPolar, double phi)
{
    const glm::dvec3 helper = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(helper, axis));
    const glm::dvec3 v = glm::cross(axis, u);
    const double sinPolar = std::sqrt(std::max(0.0, 1.0 - cosPolar * cosPolar));
    return sinPolar * std::cos(phi) * u + sinPolar * std::sin(phi) * v + cosPolar * axis;
}

} // namespace

PhongLobe::PhongLobe(double cosView, double shininess)
    : m_cosView(std::clamp(cosView, 0.0, 1.0))
    , m_shininess(std::max(shininess, 0.0))
{
    const double sinView = std::sqrt(1.0 - m_cosView * m_cosView);
    m_mirror = { -sinView, 0.0, m_cosView };
    // value / samplingDensity = (n + 2) / (n + 1) cos(theta) where both are non-zero: a stratified grid of
    // lobe samples integrates it closely.
    double sum = 0.0;
    for (int i = 0; i < kAlbedoSamples; ++i)
        for (int j = 0; j < kAlbedoSamples; ++j) {
            const glm::dvec3 d = sample((i + 0.5) / kAlbedoSamples, (j + 0.5) / kAlbedoSamples);
            sum += value(d) / samplingDensity(d);
        }
    m_albedo = sum / (kAlbedoSamples * kAlbedoSamples);
}

double PhongLobe::value(const glm::dvec3& direction) const
{
    const double cosMirror = glm::dot(direction, m_mirror);
    if (direction.z <= 0.0 || cosMirror <= 0.0)
        return 0.0;
    return (m_shininess + 2.0) / (2.0 * kPi) * std::pow(cosMirror, m_shininess) * direction.z;
}

glm::dvec3 PhongLobe::sample(double u1, double u2) const
{
    return around(m_mirror, std::pow(1.0 - u1, 1.0 / (m_shininess + 1.0)), 2.0 * kPi * u2);
}

double PhongLobe::samplingDensity(const glm::dvec3& direction) const
{
    const double cosMirror = glm::dot(direction, m_mirror);
    return cosMirror <= 0.0 ? 0.0 : (m_shininess + 1.0) / (2.0 * kPi) * std::pow(cosMirror, m_shininess);
}

} // namespace vct::render
