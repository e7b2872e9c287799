#include "core/LightUniforms.h"

#include "core/ConeTracingSetup.h"
#include "core/FrameContext.h"

#include <glm/geometric.hpp>

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace vct::render {

namespace {

float pointRadius(const PointLight& light)
{
    return std::isfinite(light.radius) ? std::max(light.radius, 0.0f) : 0.0f;
}

float directionalTanHalf(const DirectionalLight& light)
{
    const float diameter
        = std::isfinite(light.angularDiameterDeg) ? std::clamp(light.angularDiameterDeg, 0.0f, 179.0f) : 0.0f;
    return std::tan(glm::radians(0.5f * diameter));
}

} // namespace

bool softShadowsUsed(const Scene& scene)
{
    const int points = std::min<int>(int(scene.pointLights.size()), kMaxPointLights);
    const int directionals = std::min<int>(int(scene.directionalLights.size()), kMaxDirectionalLights);
    for (int i = 0; i < points; ++i)
        if (scene.pointLights[std::size_t(i)].castsShadows
            && pointRadius(scene.pointLights[std::size_t(i)]) > 0.0f)
            return true;
    for (int i = 0; i < directionals; ++i)
        if (scene.directionalLights[std::size_t(i)].castsShadows
            && directionalTanHalf(scene.directionalLights[std::size_t(i)]) > 0.0f)
            return true;
    return false;
}

void applyLightUniforms(const gl::Program& program, const Scene& scene, const ShadowMaps& shadows)
{
    const int points = std::min<int>(int(scene.pointLights.size()), kMaxPointLights);
    const int directionals = std::min<int>(int(scene.directionalLights.size()), kMaxDirectionalLights);
    std::vector<glm::vec4> positions, intensities, spots, directions, irradiances;
    std::vector<float> radii, tanHalves;
    for (int i = 0; i < points; ++i) {
        const PointLight& light = scene.pointLights[std::size_t(i)];
        positions.emplace_back(light.position, light.castsShadows && shadows.pointDepth ? 1.0f : 0.0f);
        intensities.emplace_back(light.intensity, light.cosInner());
        spots.emplace_back(light.spotDirection, light.cosOuter());
        radii.push_back(pointRadius(light));
    }
    for (int i = 0; i < directionals; ++i) {
        const DirectionalLight& light = scene.directionalLights[std::size_t(i)];
        const bool shadowed = light.castsShadows && shadows.directionalDepth
            && std::size_t(i) < shadows.directionalMatrices.size();
        directions.emplace_back(light.direction, shadowed ? 1.0f : 0.0f);
        irradiances.emplace_back(light.irradiance, 0.0f);
        tanHalves.push_back(directionalTanHalf(light));
        if (shadowed)
            glProgramUniformMatrix4fv(program.id(),
                program.location(("uDirectionalLightMatrix[" + std::to_string(i) + "]").c_str()), 1, GL_FALSE,
                &shadows.directionalMatrices[std::size_t(i)][0][0]);
    }
    program.set("uPointLightPosition", positions);
    program.set("uPointLightIntensity", intensities);
    program.set("uPointLightSpot", spots);
    program.set("uPointShadowNear", shadows.pointNear);
    program.set("uPointShadowFar", shadows.pointFar);
    program.set("uDirectionalLightDirection", directions);
    program.set("uDirectionalLightIrradiance", irradiances);
    program.set("uPointLightRadius", radii);
    program.set("uDirectionalLightTanHalf", tanHalves);
    // Samplers must always see a texture of their type, even with no light of that kind.
    if (shadows.pointDepth) {
        shadows.pointDepth.bindUnit(kPointShadowUnit);
        shadows.pointDepth.bindUnit(kPointDepthUnit);
    }
    if (shadows.directionalDepth) {
        shadows.directionalDepth.bindUnit(kDirectionalShadowUnit);
        shadows.directionalDepth.bindUnit(kDirectionalDepthUnit);
    }
    // The same maps again, read through a sampler without comparison (common/Lights.glsl).
    if (shadows.rawDepth) {
        shadows.rawDepth.bindUnit(kPointDepthUnit);
        shadows.rawDepth.bindUnit(kDirectionalDepthUnit);
    }
}

void applyAreaLightUniforms(const gl::Program& program, const FrameContext& frame)
{
    const VoxelVolume& v = frame.voxels;
    program.set("uOpacityOrigin", v.frame.origin);
    program.set("uOpacityExtent", v.frame.extent);
    program.set("uOpacityVoxel", v.frame.voxelSize());
    program.set("uOpacityMaxLevel", float(std::max(v.opacity.levels() - 1, 0)));
    frame.scene.bindAreaLightTable(kAreaLightTableUnit);
    if (v.opacity)
        v.opacity.bindUnit(kOpacityUnit);
    // A clipmap's shadow cones start in the finest grid holding the receiver and go on into the coarser
    // levels (the finer ones end a few metres out, and an occluder beyond them must still cast a shadow).
    if (frame.coarserLevels.empty())
        return;
    // The opacity chains have the levels' mip counts (InjectLightPass), as the radiance's.
    std::vector<glm::vec4> boxes, grids;
    ConeTracingSetup::clipLevelFrames(frame, boxes, grids);
    for (std::size_t k = 0; k < frame.coarserLevels.size(); ++k)
        if (frame.coarserLevels[k]->opacity)
            frame.coarserLevels[k]->opacity.bindUnit(GLuint(CLIP_RADIANCE_UNIT + int(k)));
    program.set("uClipOpacityBox", boxes);
    program.set("uClipOpacityGrid", grids);
}

void addAreaShadowDefines(std::vector<std::string>& defines, const FrameContext& frame)
{
    if (!frame.coarserLevels.empty())
        defines.push_back("SHADOW_CLIP_LEVELS " + std::to_string(frame.coarserLevels.size()));
}

} // namespace vct::render
