#pragma once

#include "scene/VoxelSceneNeeds.h"

#include <cstdint>
#include <string>
#include <vector>

namespace vct::render {

struct RenderSettings;

/** How a texture of clip level @p level (0: the finest, or the dense grid) is named in memory tables. */
std::string clipLevelName(int level, const std::string& name);

/**
 * What the passes will allocate for the voxel grid under some settings, texture by texture, before anything
 * is allocated: the budget check (RenderSettings::validate, which refuses a grid over voxel_budget_mb) and
 * the tests that hold it to what GL reports (tst_VoxelTextureMemory compares every entry by name with the
 * voxel textures of the pipeline's resource table, core/ResourceTable). It is a GL-free mirror of what the
 * passes' textures() ask for because the budget is checked where there is no GL: in the document, the
 * settings dock and the command line, before a grid is accepted. The box levels the inspector makes on
 * demand are not in it.
 */
struct VoxelTextureEstimate {
    std::string name; ///< as the resource table names the texture (core/ResourceNames.h)
    std::uint64_t bytes = 0;

    /** Every texture @p settings call for in a scene with @p scene's needs, with its size. */
    static std::vector<VoxelTextureEstimate> of(const RenderSettings& settings, VoxelSceneNeeds scene);
};

} // namespace vct::render
