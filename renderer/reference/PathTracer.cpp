#include "reference/PathTracer.h"

#include "reference/PhongBsdf.h"
#include "reference/RayOffset.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vct::render {

namespace {

/** Veach's power heuristic (beta = 2) for one sample of each of two strategies. */
float powerHeuristic(float pdf, float otherPdf)
{
    const float a = pdf * pdf, b = otherPdf * otherPdf;
    if (!std::isfinite(a))
        return 1.0f;
    return a + b > 0.0f ? a / (a + b) : 0.0f;
}

float maxComponent(const glm::vec3& v)
{
    return std::max({ v.x, v.y, v.z });
}

/** Shadow rays stop this fraction short of their target, so they never reach the surface they aim at. */
constexpr float kShadowRayShortening = 1.0f - 1e-5f;

/**
 * A direction uniform in solid angle within the cone about unit @p axis whose half-angle has cosine @p
 * cosHalf (pdf 1 / (2 pi (1 - cosHalf))).
 */
glm::vec3 directionWithinCone(const glm::vec3& axis, float cosHalf, float u1, float u2)
{
    const float cosTheta = 1.0f - u1 * (1.0f - cosHalf);
    const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    const float phi = 2.0f * glm::pi<float>() * u2;
    const glm::vec3 t = glm::normalize(std::abs(axis.x) < 0.9f ? glm::cross(axis, glm::vec3(1, 0, 0))
                                                               : glm::cross(axis, glm::vec3(0, 1, 0)));
    const glm::vec3 b = glm::cross(axis, t);
    return glm::normalize(cosTheta * axis + sinTheta * (std::cos(phi) * t + std::sin(phi) * b));
}

std::vector<SceneTriangle> surfaceLightTriangles(const std::vector<SurfaceLight>& lights)
{
    std::vector<SceneTriangle> triangles;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const std::vector<glm::vec3> corners = lights[i].triangles();
        for (std::size_t k = 0; k + 2 < corners.size(); k += 3) {
            SceneTriangle t;
            t.vertices = { corners[k], corners[k + 1], corners[k + 2] };
            const glm::vec3 cross = glm::cross(corners[k + 1] - corners[k], corners[k + 2] - corners[k]);
            t.area = 0.5f * glm::length(cross);
            if (!(t.area > 0.0f) || !std::isfinite(t.area))
                continue;
            t.geometricNormal = cross / (2.0f * t.area);
            t.normals = { t.geometricNormal, t.geometricNormal, t.geometricNormal };
            t.material = int(i);
            triangles.push_back(t);
        }
    }
    return triangles;
}

std::vector<Material> surfaceLightMaterials(const std::vector<SurfaceLight>& lights)
{
    std::vector<Material> materials(lights.size());
    for (std::size_t i = 0; i < lights.size(); ++i) {
        materials[i].emission = lights[i].radiance;
        materials[i].emission = materials[i].usableEmission();
    }
    return materials;
}

} // namespace

PathTracer::PathTracer(const Scene& scene, const ReferenceSettings& settings)
    : m_geometry(scene)
    , m_emitters(m_geometry.triangles(), m_geometry.materials())
    , m_surfaceTriangles(surfaceLightTriangles(scene.surfaceLights))
    , m_surfaceMaterials(surfaceLightMaterials(scene.surfaceLights))
    , m_surfaceEmitters(m_surfaceTriangles, m_surfaceMaterials)
    , m_pointLights(scene.pointLights)
    , m_maxBounces(std::max(0, settings.maxBounces))
    , m_rouletteStartBounce(std::max(1, settings.rouletteStartBounce))
{
    for (const SurfaceLight& light : scene.surfaceLights)
        m_surfaceShadows.push_back(light.castsShadows);
    m_textures.reserve(scene.textures.size());
    for (const TextureImage& image : scene.textures)
        m_textures.emplace_back(image);
    for (DirectionalLight light : scene.directionalLights) {
        light.direction = glm::normalize(light.direction);
        if (std::isfinite(light.direction.x) && std::isfinite(light.direction.y)
            && std::isfinite(light.direction.z)) {
            m_directionalLights.push_back(light); // a zero direction points nowhere: no light
            const float diameter = std::isfinite(light.angularDiameterDeg)
                ? std::clamp(light.angularDiameterDeg, 0.0f, 179.0f)
                : 0.0f;
            m_directionalLights.back().angularDiameterDeg = diameter;
            m_sunCosHalf.push_back(std::cos(glm::radians(0.5f * diameter)));
        }
    }
}

glm::vec3 PathTracer::albedoAt(
    const Material& material, const SceneTriangle& triangle, float u, float v) const
{
    if (material.albedoTexture < 0 || std::size_t(material.albedoTexture) >= m_textures.size())
        return material.albedo;
    return material.albedo
        * m_textures[std::size_t(material.albedoTexture)].sample(
            SceneTriangle::interpolate(triangle.uvs, u, v));
}

glm::vec3 PathTracer::radiance(const CameraRays::Ray& ray, Pcg32& random, std::uint64_t& rayCount) const
{
    const std::vector<SceneTriangle>& triangles = m_geometry.triangles();
    const std::vector<Material>& materials = m_geometry.materials();
    glm::vec3 result(0.0f);
    glm::vec3 throughput(1.0f);
    glm::vec3 origin = ray.origin;
    glm::vec3 direction = ray.direction;
    float bsdfPdf = 0.0f; // solid-angle density of the BSDF sample that chose `direction`
    for (int bounce = 0;; ++bounce) {
        ++rayCount;
        const std::optional<EmbreeScene::Hit> hit = m_geometry.intersect(origin, direction);
        if (!hit)
            break; // the background is black
        const SceneTriangle& triangle = triangles[hit->triangle];
        const Material& material = materials[std::size_t(triangle.material)];
        const float cosAtHit = -glm::dot(triangle.geometricNormal, direction);
        const bool frontFace = cosAtHit > 0.0f;
        if (frontFace && material.isEmissive()) {
            // A camera ray has no other way to find the emitter; later ones share it with next-event
            // estimation.
            float weight = 1.0f;
            if (bounce > 0) {
                const float lightPdf
                    = m_emitters.pdfArea(hit->triangle) * hit->distance * hit->distance / cosAtHit;
                weight = powerHeuristic(bsdfPdf, lightPdf);
            }
            result += throughput * material.emission * weight;
        }
        if (bounce >= m_maxBounces)
            break;

        const glm::vec3 position = SceneTriangle::interpolate(triangle.vertices, hit->u, hit->v);
        const glm::vec3 toViewer = -direction;
        const glm::vec3 facingNormal = frontFace ? triangle.geometricNormal : -triangle.geometricNormal;
        // Shaded from the side the ray arrives on, as the G-buffer pass flips normals of back faces.
        glm::vec3 shadingNormal
            = glm::normalize(SceneTriangle::interpolate(triangle.normals, hit->u, hit->v));
        if (!frontFace)
            shadingNormal = -shadingNormal;
        if (!std::isfinite(shadingNormal.x))
            shadingNormal = facingNormal;
        const PhongBsdf bsdf(albedoAt(material, triangle, hit->u, hit->v), material.specular,
            material.shininess, shadingNormal, toViewer);
        if (!bsdf.reflects())
            break;
        origin = offsetRayOrigin(position, facingNormal);

        // Light arriving from behind the geometric surface would have to pass through it.
        auto lightContribution = [&](const glm::vec3& toLight) {
            if (glm::dot(toLight, facingNormal) <= 0.0f)
                return glm::vec3(0.0f);
            return bsdf.evaluate(toLight) * std::max(glm::dot(shadingNormal, toLight), 0.0f);
        };
        for (const PointLight& light : m_pointLights) {
            if (light.radius > 0.0f) {
                result += throughput
                    * sphereLightSample(light, position, origin, random, rayCount, lightContribution);
                continue;
            }
            const glm::vec3 toLight = light.position - position;
            const float distanceSquared = glm::dot(toLight, toLight);
            if (!(distanceSquared > 0.0f))
                continue;
            const glm::vec3 toLightUnit = toLight / std::sqrt(distanceSquared);
            const glm::vec3 reflected = lightContribution(toLightUnit);
            if (maxComponent(reflected) <= 0.0f)
                continue;
            if (light.castsShadows) {
                ++rayCount;
                if (m_geometry.occluded(
                        origin, toLightUnit, glm::length(light.position - origin) * kShadowRayShortening))
                    continue;
            }
            result += throughput * reflected * light.intensity * light.spotFactor(-toLightUnit)
                / distanceSquared;
        }
        for (std::size_t i = 0; i < m_directionalLights.size(); ++i) {
            const DirectionalLight& light = m_directionalLights[i];
            const glm::vec3 toLight = light.angularDiameterDeg > 0.0f ? directionWithinCone(-light.direction,
                                          m_sunCosHalf[i], random.nextFloat(), random.nextFloat())
                                                                      : -light.direction;
            const glm::vec3 reflected = lightContribution(toLight);
            if (maxComponent(reflected) <= 0.0f)
                continue;
            if (light.castsShadows) {
                ++rayCount;
                if (m_geometry.occluded(origin, toLight))
                    continue;
            }
            result += throughput * reflected * light.irradiance;
        }
        if (!m_emitters.isEmpty()) {
            const glm::vec3 u(random.nextFloat(), random.nextFloat(), random.nextFloat());
            const EmissiveTriangleSampler::Sample sample = m_emitters.sample(u);
            const SceneTriangle& emitter = triangles[sample.triangle];
            const glm::vec3 toLight = sample.position - position;
            const float distanceSquared = glm::dot(toLight, toLight);
            const glm::vec3 toLightUnit = toLight / std::sqrt(distanceSquared);
            const float cosAtLight = -glm::dot(emitter.geometricNormal, toLightUnit);
            const glm::vec3 reflected = cosAtLight > 0.0f ? lightContribution(toLightUnit) : glm::vec3(0.0f);
            if (maxComponent(reflected) > 0.0f && distanceSquared > 0.0f) {
                const float lightPdf = sample.pdfArea * distanceSquared / cosAtLight;
                const glm::vec3 target = offsetRayOrigin(sample.position, emitter.geometricNormal);
                const glm::vec3 toTarget = target - origin;
                const float targetDistance = glm::length(toTarget);
                ++rayCount;
                if (!m_geometry.occluded(
                        origin, toTarget / targetDistance, targetDistance * kShadowRayShortening)) {
                    const float weight = powerHeuristic(lightPdf, bsdf.pdf(toLightUnit));
                    result += throughput * reflected * materials[std::size_t(emitter.material)].emission
                        * (weight / lightPdf);
                }
            }
        }

        if (!m_surfaceEmitters.isEmpty())
            result += throughput * surfaceLightSample(position, origin, random, rayCount, lightContribution);

        const float lobeChoice = random.nextFloat();
        const glm::vec2 u(random.nextFloat(), random.nextFloat());
        const glm::vec3 next = bsdf.sample(lobeChoice, u);
        if (glm::dot(next, facingNormal) <= 0.0f)
            break;
        bsdfPdf = bsdf.pdf(next);
        if (!(bsdfPdf > 0.0f))
            break;
        throughput *= bsdf.evaluate(next) * (std::max(glm::dot(shadingNormal, next), 0.0f) / bsdfPdf);
        if (bounce + 1 >= m_rouletteStartBounce) {
            // Survival in proportion to throughput; dividing by it keeps the estimate unbiased.
            const float survival = std::min(1.0f, maxComponent(throughput));
            if (!(survival > 0.0f) || random.nextFloat() >= survival)
                break;
            throughput /= survival;
        }
        direction = next;
    }
    return result;
}

glm::vec3 PathTracer::sphereLightSample(const PointLight& light, const glm::vec3& position,
    const glm::vec3& origin, Pcg32& random, std::uint64_t& rayCount,
    const std::function<glm::vec3(const glm::vec3&)>& reflected) const
{
    const glm::vec3 toCentre = light.position - position;
    const float distance2 = glm::dot(toCentre, toCentre);
    const float radius2 = light.radius * light.radius;
    if (!(distance2 > radius2))
        return glm::vec3(0.0f); // inside the light: no surface of it faces this point
    const float distance = std::sqrt(distance2);
    const glm::vec3 axis = toCentre / distance;
    // 1 - cos(theta_max) without the cancellation of two nearly equal numbers for a small, far light.
    const float sin2Max = radius2 / distance2;
    const float cosMax = std::sqrt(std::max(0.0f, 1.0f - sin2Max));
    const float oneMinusCosMax = sin2Max / (1.0f + cosMax);
    const glm::vec3 toLight = directionWithinCone(axis, cosMax, random.nextFloat(), random.nextFloat());
    const glm::vec3 bsdfCos = reflected(toLight);
    if (maxComponent(bsdfCos) <= 0.0f)
        return glm::vec3(0.0f);
    if (light.castsShadows) {
        // Where the sampled ray meets the sphere.
        const float along = glm::dot(toLight, toCentre);
        const float hit = along - std::sqrt(std::max(0.0f, radius2 - (distance2 - along * along)));
        ++rayCount;
        if (m_geometry.occluded(origin, toLight, std::max(hit, 0.0f) * kShadowRayShortening))
            return glm::vec3(0.0f);
    }
    // The sphere's radiance I / (pi r^2) over the cone's solid angle 2 pi (1 - cos theta_max).
    const glm::vec3 radiance = light.intensity * light.spotFactor(-axis) / (glm::pi<float>() * radius2);
    return bsdfCos * radiance * (2.0f * glm::pi<float>() * oneMinusCosMax);
}

glm::vec3 PathTracer::surfaceLightSample(const glm::vec3& position, const glm::vec3& origin, Pcg32& random,
    std::uint64_t& rayCount, const std::function<glm::vec3(const glm::vec3&)>& reflected) const
{
    const glm::vec3 u(random.nextFloat(), random.nextFloat(), random.nextFloat());
    const EmissiveTriangleSampler::Sample sample = m_surfaceEmitters.sample(u);
    const SceneTriangle& emitter = m_surfaceTriangles[sample.triangle];
    const glm::vec3 toLight = sample.position - position;
    const float distanceSquared = glm::dot(toLight, toLight);
    if (!(distanceSquared > 0.0f))
        return glm::vec3(0.0f);
    const glm::vec3 toLightUnit = toLight / std::sqrt(distanceSquared);
    const float cosAtLight = -glm::dot(emitter.geometricNormal, toLightUnit);
    if (!(cosAtLight > 0.0f))
        return glm::vec3(0.0f); // emission is one-sided
    const glm::vec3 bsdfCos = reflected(toLightUnit);
    if (maxComponent(bsdfCos) <= 0.0f)
        return glm::vec3(0.0f);
    if (m_surfaceShadows[std::size_t(emitter.material)]) {
        // The light is no surface: nothing at its sample stops the ray, so it need not stop short of it.
        const glm::vec3 toTarget = sample.position - origin;
        const float targetDistance = glm::length(toTarget);
        ++rayCount;
        if (targetDistance > 0.0f
            && m_geometry.occluded(origin, toTarget / targetDistance, targetDistance * kShadowRayShortening))
            return glm::vec3(0.0f);
    }
    const float lightPdf = sample.pdfArea * distanceSquared / cosAtLight;
    return bsdfCos * m_surfaceMaterials[std::size_t(emitter.material)].emission / lightPdf;
}

} // namespace vct::render
