#pragma once

#include "core/FrameContext.h"

namespace vct::render {

/**
 * What the scene and settings call for this frame. The plan skips a pass whose effect nobody needs, and the
 * shaders skip the work inside a pass the same way, so both agree by construction. Evaluated once per frame
 * into FrameContext::shape (FrameShape::of), which the passes read.
 */
struct FrameRules {
    /** Something emits light: an enabled light, or an emissive material with emission on. */
    static bool hasLightSources(const FrameContext& frame)
    {
        const Scene& scene = frame.scene.scene();
        const bool lights = frame.settings.direct
            && (!scene.pointLights.empty() || !scene.directionalLights.empty()
                || frame.scene.areaLights().surfaceLightCount > 0);
        return lights || emissionNeeded(frame);
    }
    static bool emissionNeeded(const FrameContext& frame)
    {
        return frame.settings.emission && frame.scene.scene().hasEmissiveMaterial();
    }
    /**
     * Emitters light surfaces as area lights, per pixel and per voxel (core/AreaLightSet), when they fit its
     * limits and direct light is on; their emission then stays out of the voxels' radiance, where cones would
     * gather the same light a second time.
     */
    static bool emittersAsAreaLights(const FrameContext& frame)
    {
        return emissionNeeded(frame) && frame.settings.direct
            && frame.scene.areaLights().meshEmittersAnalytic();
    }
    /**
     * The area lights this frame lights with: a prefix of the table, the rectangle and disk lights (on with
     * direct light) and then the emitters when they are lit as area lights.
     */
    static int areaLightCount(const FrameContext& frame)
    {
        const AreaLightSet& set = frame.scene.areaLights();
        if (!frame.settings.direct)
            return 0;
        return set.surfaceLightCount + (emittersAsAreaLights(frame) ? set.emitterLightCount() : 0);
    }
    static bool areaLightsUsed(const FrameContext& frame) { return areaLightCount(frame) > 0; }
    /** Emission goes into the voxels for the cones to gather: when it is not lit as area lights. */
    static bool voxelEmissionNeeded(const FrameContext& frame)
    {
        return emissionNeeded(frame) && !emittersAsAreaLights(frame);
    }
    /**
     * Bounces past the first are carried by the voxels (passes/VoxelBouncePass): cones then trace the bounced
     * volume, and the first-bounce radiance is kept at level 0 only, as the iteration's source.
     */
    static bool bounceVolumeUsed(const FrameContext& frame)
    {
        return frame.settings.bounces != 1 && hasLightSources(frame);
    }
    /**
     * Mip levels of the volume cones trace. With anisotropic mips cones read its level 0 and the directional
     * chains only (common/ConeTracing.glsl), so the box levels are not kept (the inspector makes its own:
     * VoxelVolume::inspectionMips).
     */
    static int coneVolumeLevels(const FrameContext& frame)
    {
        return frame.settings.anisotropicMips ? 1 : frame.voxels.frame.levelCount();
    }
    /** Mip levels of the first-bounce radiance: level 0 alone when it is only the bounce iteration's source.
     */
    static int radianceLevels(const FrameContext& frame)
    {
        return bounceVolumeUsed(frame) ? 1 : coneVolumeLevels(frame);
    }
    /** Ambient occlusion is only ever shown by its debug view; it is not part of the physical image. */
    static bool ambientOcclusionNeeded(const FrameContext& frame)
    {
        return frame.settings.ambientOcclusion && frame.settings.view == DebugView::AmbientOcclusion;
    }
    static bool diffuseConesNeeded(const FrameContext& frame)
    {
        return (frame.settings.indirectDiffuse && hasLightSources(frame)) || ambientOcclusionNeeded(frame);
    }
    static bool specularConesNeeded(const FrameContext& frame)
    {
        return frame.settings.indirectSpecular && frame.scene.scene().hasGlossyMaterial()
            && hasLightSources(frame);
    }
};

} // namespace vct::render
