#pragma once

namespace vct::render {

struct FrameContext;

/**
 * What this frame calls for, decided once before the passes plan (Renderer::renderFrame, from the rules in
 * core/FrameRules.h): every pass's plan, execute and shader variants read the same answers.
 */
struct FrameShape {
    bool lightSources = false; ///< an enabled light, or an emissive material with emission on
    bool emission = false; ///< emissive materials with emission on
    bool emittersAsAreaLights = false; ///< emitters lit as area lights, per pixel and per voxel
    bool voxelEmission = false; ///< emission goes into the voxels for the cones to gather
    int areaLights = 0; ///< the area lights lit with: a prefix of the table
    bool ambientOcclusion = false; ///< only ever shown by its debug view
    bool diffuseCones = false;
    bool specularCones = false;
    bool irradianceCache = false; ///< the cone pass looks diffuse light up in the cache
    bool bounceVolume = false; ///< bounces past the first are carried by the voxels
    int coneVolumeLevels = 1; ///< mip levels of the volume cones trace
    int radianceLevels = 1; ///< mip levels of the first-bounce radiance

    static FrameShape of(const FrameContext& frame);
};

} // namespace vct::render
