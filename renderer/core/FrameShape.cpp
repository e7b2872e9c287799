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
    // In a clipmap the cache's cells are the finest level's: pixels beyond it find no cell and trace their
    // own cones across the levels. (A clip level's own pipeline has no cache.)
    shape.irradianceCache = frame.settings.irradianceCache && shape.diffuseCones;
    shape.bounceVolume = FrameRules::bounceVolumeUsed(frame);
    shape.coneVolumeLevels = FrameRules::coneVolumeLevels(frame);
    shape.radianceLevels = FrameRules::radianceLevels(frame);
    return shape;
}

} // namespace vct::render
