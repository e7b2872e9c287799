#include "core/VoxelGridFrame.h"

#include <algorithm>
#include <cmath>

namespace vct::render {

int VoxelGridFrame::levelCount() const
{
    int levels = 1;
    for (int r = resolution; r > 1; r /= 2)
        ++levels;
    return levels;
}

VoxelGridFrame VoxelGridFrame::fit(const Aabb& bounds, int resolution)
{
    VoxelGridFrame frame;
    frame.resolution = std::max(1, resolution);
    const glm::vec3 size = bounds.isEmpty() ? glm::vec3(1.0f) : bounds.size();
    float largest = std::max({ size.x, size.y, size.z });
    if (!(largest > 0.0f) || !std::isfinite(largest))
        largest = 1.0f;
    // extent = largest + 2 cells, with cell = extent / resolution.
    const float margin = resolution > 4 ? 2.0f / float(resolution - 2) : 0.5f;
    frame.extent = largest * (1.0f + margin);
    const glm::vec3 center = bounds.isEmpty() ? glm::vec3(0.0f) : bounds.center();
    frame.origin = center - glm::vec3(frame.extent * 0.5f);
    return frame;
}

} // namespace vct::render
