#pragma once

#include "core/VoxelChannel.h"

namespace vct::ui {

/** What the voxel inspector shows beside the cone-traced image. */
struct InspectorSettings {
    bool enabled = false;
    int level = 0;
    render::VoxelChannel channel = render::VoxelChannel::Radiance;
    int grid = 0; ///< a clipmap's level (Renderer::gridCount(); 0 the finest), 0 for a dense grid

    bool operator==(const InspectorSettings& other) const = default;
};

} // namespace vct::ui
