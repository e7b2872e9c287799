#include "core/FrameResources.h"

#include "core/VoxelTextureMemory.h"

namespace vct::render {

std::size_t VoxelVolume::byteSize() const
{
    std::size_t total = 0;
    for (const VoxelTextureMemory& texture : describeVoxelMemory(*this))
        total += texture.totalBytes();
    return total;
}

} // namespace vct::render
