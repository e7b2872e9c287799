#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace vct::render {

/**
 * The BRDF of Material at one shading point: albedo/pi + specular (n+2)/(2 pi) cos^n(angle to the mirror
 * direction), the normalised modified Phong model the GL renderer shades with. Sampling mixes a cosine lobe
 * and the Phong lobe in proportion to the luminance of albedo and specular. Directions are unit vectors
 * pointing away from the surface; the normal faces the viewer.
 */
class PhongBsdf {
public:
    /** @p specular counts only when @p shininess > 0, as Material::isGlossy() says. */
    PhongBsdf(const glm::vec3& albedo, const glm::vec3& specular, float shininess, const glm::vec3& normal,
        const glm::vec3& toViewer);

    /** BRDF value for light arriving from @p toLight, 1/sr per channel (the cosine is not included). */
    glm::vec3 evaluate(const glm::vec3& toLight) const;
    /** Solid-angle density with which sample() returns @p toLight. */
    float pdf(const glm::vec3& toLight) const;
    /** A direction drawn from the lobe mixture; @p lobeChoice in [0,1) picks the lobe, @p u the direction. */
    glm::vec3 sample(float lobeChoice, const glm::vec2& u) const;
    /** False for a black surface: nothing to sample, the path ends. */
    bool reflects() const { return m_diffuseProbability > 0.0f || m_glossy; }
    const glm::vec3& normal() const { return m_normal; }

private:
    glm::vec3 m_albedo;
    glm::vec3 m_specular;
    float m_shininess;
    glm::vec3 m_normal;
    glm::vec3 m_mirror; ///< The viewer direction reflected about the normal.
    bool m_glossy;
    float m_diffuseProbability; ///< Chance of sampling the cosine lobe; the Phong lobe gets the rest.
};

} // namespace vct::render
