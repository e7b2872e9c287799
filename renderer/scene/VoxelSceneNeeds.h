#pragma once

namespace vct::render {

/** What a scene adds to the voxel textures (RenderSettings::voxelMemoryBytes). */
struct VoxelSceneNeeds {
    bool emission = true; ///< emissive materials: an emission volume
    bool areaLights = true; ///< an opacity chain for the area lights' shadow cones
    bool lightSources = true; ///< anything to bounce: without light there is no bounced volume
    /// voxel_mode=sparse: the share of the grid's bricks that hold storage (core/BrickPool), once known;
    /// before, 0: the level-0 pools are counted when they are made (passes/VoxelizePass).
    double brickShare = 0.0;
};

} // namespace vct::render
