#pragma once

namespace vct::render {

/** What a scene adds to the voxel textures (RenderSettings::voxelMemoryBytes). */
struct VoxelSceneNeeds {
    bool emission = true; ///< emissive materials: an emission volume
    bool areaLights = true; ///< an opacity chain for the area lights' shadow cones
    bool lightSources = true; ///< anything to bounce: without light there is no bounced volume
};

} // namespace vct::render
