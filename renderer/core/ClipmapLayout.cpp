#include "core/ClipmapLayout.h"

#include <algorithm>
#include <cmath>

namespace vct::render {

VoxelGridFrame ClipmapLayout::level(
    const VoxelGridFrame& scene, int levels, int level, const glm::vec3& camera)
{
    const int coarsest = std::max(levels - 1, 0);
    level = std::clamp(level, 0, coarsest);
    if (level == coarsest)
        return scene;
    VoxelGridFrame frame;
    frame.resolution = scene.resolution;
    frame.extent = scene.extent / float(1 << (coarsest - level));
    const float step = 2.0f * frame.voxelSize();
    // Steps of two voxels from the scene's corner; the most that keep the level inside the scene's grid.
    const float stepsAcross = std::round((scene.extent - frame.extent) / step);
    for (int axis = 0; axis < 3; ++axis) {
        const float wanted = (camera[axis] - scene.origin[axis] - 0.5f * frame.extent) / step;
        const float steps = std::isfinite(wanted) ? std::clamp(std::round(wanted), 0.0f, stepsAcross) : 0.0f;
        frame.origin[axis] = scene.origin[axis] + steps * step;
    }
    return frame;
}

} // namespace vct::render
