#include "reference/PhongBsdf.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vct::render {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

float luminance(const glm::vec3& c)
{
    return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
}

/** @p local (z along @p axis) turned into world space, with the branchless basis of Duff et al. (JCGT 2017).
 */
glm::vec3 aroundAxis(const glm::vec3& axis, const glm::vec3& local)
{
    const float sign = std::copysign(1.0f, axis.z);
    const float a = -1.0f / (sign + axis.z);
    const float b = axis.x * axis.y * a;
    const glm::vec3 t(1.0f + sign * axis.x * axis.x * a, sign * b, -sign * axis.x);
    const glm::vec3 s(b, sign + axis.y * axis.y * a, -axis.y);
    return local.x * t + local.y * s + local.z * axis;
}

glm::vec3 directionAround(const glm::vec3& axis, float cosTheta, float phi)
{
    const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    return glm::normalize(aroundAxis(axis, { sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta }));
}

} // namespace

PhongBsdf::PhongBsdf(const glm::vec3& albedo, const glm::vec3& specular, float shininess,
    const glm::vec3& normal, const glm::vec3& toViewer)
    : m_albedo(albedo)
    , m_specular(specular)
    , m_shininess(shininess)
    , m_normal(normal)
    , m_mirror(glm::normalize(2.0f * glm::dot(normal, toViewer) * normal - toViewer))
    , m_glossy(shininess > 0.0f && std::max({ specular.r, specular.g, specular.b }) > 0.0f)
{
    const float diffuseWeight = std::max(luminance(albedo), 0.0f);
    const float glossyWeight = m_glossy ? std::max(luminance(specular), 1e-6f) : 0.0f;
    m_diffuseProbability
        = diffuseWeight + glossyWeight > 0.0f ? diffuseWeight / (diffuseWeight + glossyWeight) : 0.0f;
}

glm::vec3 PhongBsdf::evaluate(const glm::vec3& toLight) const
{
    if (glm::dot(m_normal, toLight) <= 0.0f)
        return glm::vec3(0.0f);
    glm::vec3 f = m_albedo / kPi;
    if (m_glossy) {
        const float cosMirror = std::max(glm::dot(m_mirror, toLight), 0.0f);
        f += m_specular * ((m_shininess + 2.0f) / (2.0f * kPi) * std::pow(cosMirror, m_shininess));
    }
    return f;
}

float PhongBsdf::pdf(const glm::vec3& toLight) const
{
    const float cosNormal = glm::dot(m_normal, toLight);
    if (cosNormal <= 0.0f)
        return 0.0f;
    float density = m_diffuseProbability * cosNormal / kPi;
    if (m_glossy) {
        const float cosMirror = std::max(glm::dot(m_mirror, toLight), 0.0f);
        density += (1.0f - m_diffuseProbability) * (m_shininess + 1.0f) / (2.0f * kPi)
            * std::pow(cosMirror, m_shininess);
    }
    return density;
}

glm::vec3 PhongBsdf::sample(float lobeChoice, const glm::vec2& u) const
{
    const float phi = 2.0f * kPi * u.y;
    if (lobeChoice < m_diffuseProbability)
        return directionAround(m_normal, std::sqrt(1.0f - u.x), phi); // cosine-weighted hemisphere
    return directionAround(m_mirror, std::pow(1.0f - u.x, 1.0f / (m_shininess + 1.0f)), phi);
}

} // namespace vct::render
