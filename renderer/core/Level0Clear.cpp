#include "core/Level0Clear.h"

#include "core/FrameResources.h"

namespace vct::render {

namespace {

void clearBox(const gl::Texture& texture, const glm::ivec3& lo, const glm::ivec3& size)
{
    const float zero[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
    const GLenum format = texture.format() == GL_R11F_G11F_B10F ? GL_RGB : GL_RGBA;
    glClearTexSubImage(texture.id(), 0, lo.x, lo.y, lo.z, size.x, size.y, size.z, format, GL_FLOAT, zero);
}

} // namespace

void clearLevel0(const VoxelVolume& volume, const gl::Texture& texture, const VoxelRegion& region)
{
    if (!texture || region.isEmpty())
        return;
    if (!volume.sparse) {
        clearBox(texture, region.lo, region.size());
        return;
    }
    const int resolution = volume.bricks.resolution();
    if (region.lo == glm::ivec3(0) && region.hi == glm::ivec3(resolution)) {
        const float zero[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
        glClearTexImage(
            texture.id(), 0, texture.format() == GL_R11F_G11F_B10F ? GL_RGB : GL_RGBA, GL_FLOAT, zero);
        return;
    }
    // Brick b stores voxels [8b, 8b + 8] (its border the next brick's first layer): the bricks below the
    // region's low corner keep copies of it too.
    constexpr int kVoxels = BrickPool::kBrickVoxels;
    const glm::ivec3 first = glm::max((region.lo - 1) / kVoxels, glm::ivec3(0));
    const glm::ivec3 last
        = glm::min((region.hi - 1) / kVoxels, glm::ivec3(volume.bricks.bricksPerSide() - 1));
    for (int z = first.z; z <= last.z; ++z)
        for (int y = first.y; y <= last.y; ++y)
            for (int x = first.x; x <= last.x; ++x) {
                const glm::ivec3 brick(x, y, z);
                const std::uint32_t slot = volume.bricks.slot(brick);
                if (slot == 0)
                    continue;
                const glm::ivec3 stored = brick * kVoxels;
                const glm::ivec3 lo = glm::max(region.lo, stored);
                const glm::ivec3 hi = glm::min(region.hi, stored + kVoxels + 1);
                if (glm::any(glm::lessThanEqual(hi, lo)))
                    continue;
                const glm::ivec3 corner
                    = BrickPool::slotPosition(slot, volume.poolBricks) * BrickPool::kBrickTexels;
                clearBox(texture, corner + lo - stored, hi - lo);
            }
}

} // namespace vct::render
