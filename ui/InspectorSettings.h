#pragma once

#include "core/VoxelChannel.h"

namespace vct::ui {

/** What the voxel inspector shows beside the cone-traced image. */
struct InspectorSettings {
    bool enabled = false;
    int level = 0;
    render::VoxelChannel channel = render::VoxelChannel::Radiance;

    bool operator==(const InspectorSettings& other) const = default;
};

} // namespace vct::ui
