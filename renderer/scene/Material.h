#pragma once

#include <glm/vec3.hpp>

#include <string>

namespace vct::render {

/**
 * Surface description shared by the VCT renderer and, later, the reference renderer.
 * BRDF = albedo/pi + specular * (shininess + 2)/(2 pi) * cos^shininess(angle to mirror direction)
 * (normalised modified Phong). All colours are linear RGB.
 */
struct Material {
    std::string name;
    glm::vec3 albedo { 0.8f }; ///< Lambertian albedo (OBJ Kd), in [0,1].
    glm::vec3 emission { 0.0f }; ///< Emitted radiance, W/(m^2 sr), front face only (OBJ Ke).
    glm::vec3 specular { 0.0f }; ///< Specular reflectance (OBJ Ks); albedo + specular <= 1.
    float shininess = 0.0f; ///< Phong exponent (OBJ Ns); 0 means not glossy.
    int albedoTexture = -1; ///< Index into Scene::textures (sRGB, multiplies albedo), or -1.
    /// Seen from both sides: a back face is drawn and shaded from the side it is seen from. Off, the surface
    /// shows its front faces only (glTF's doubleSided false): the g-buffer and the shadow maps leave its back
    /// faces out, which costs no pixels on closed models seen from outside and spares their rasterisation.
    bool doubleSided = true;

    /** The emission a renderer may use: negative and non-finite channels emit nothing (docs/STABILITY.md). */
    glm::vec3 usableEmission() const
    {
        glm::vec3 e = emission;
        for (int c = 0; c < 3; ++c)
            e[c] = e[c] > 0.0f && e[c] <= 3.0e38f ? e[c] : 0.0f; // false for NaN too
        return e;
    }
    bool isEmissive() const { return emission.x > 0.0f || emission.y > 0.0f || emission.z > 0.0f; }
    bool isGlossy() const
    {
        return shininess > 0.0f && (specular.x > 0.0f || specular.y > 0.0f || specular.z > 0.0f);
    }
};

} // namespace vct::render
