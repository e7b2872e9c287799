#include "core/FrameShape.h"

#include "core/FrameRules.h"

namespace vct::render {

FrameShape FrameShape::of(const FrameContext& frame)
{
    FrameShape shape;
    shape.lightSources = FrameRules::hasLightSources(frame);
    shape.emission = FrameRules::emissionNeeded(frame);
    shape.emittersAsAreaLights = FrameRules::emittersAsAreaLights(frame);
    shape.voxelEmission = FrameRules::voxelEmissionNeeded(frame);
    shape.areaLights = FrameRules::areaLightCount(frame);
    shape.ambientOcclusion = FrameRules::ambientOcclusionNeeded(frame);
    shape.diffuseCones = FrameRules::diffuseConesNeeded(frame);
    shape.specularCones = FrameRules::specularConesNeeded(frame);
    // The cache's cells belong to one grid; a clipmap's pixels trace their own cones across its levels.
    shape.irradianceCache = frame.settings.irradianceCache && shape.diffuseCones
        && frame.coarserLevels.empty() && frame.settings.gridLevels() == 1;
    shape.bounceVolume = FrameRules::bounceVolumeUsed(frame);
    shape.coneVolumeLevels = FrameRules::coneVolumeLevels(frame);
    shape.radianceLevels = FrameRules::radianceLevels(frame);
    return shape;
}

} // namespace vct::render
