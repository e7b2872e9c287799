#include "passes/MipmapPass.h"

#include "core/FrameContext.h"

namespace vct::render {

namespace {

/** Gives @p texture @p levels mip levels, keeping level 0. */
void setLevelCount(gl::Texture& texture, int levels)
{
    if (texture.levels() == levels)
        return;
    const int side = texture.width();
    gl::Texture resized = gl::Texture::create3D(texture.format(), side, levels);
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glCopyImageSubData(
        texture.id(), GL_TEXTURE_3D, 0, 0, 0, 0, resized.id(), GL_TEXTURE_3D, 0, 0, 0, 0, side, side, side);
    texture = std::move(resized);
}

} // namespace

PassDecision MipmapPass::plan(const FrameContext& frame) const
{
    if (frame.voxels.radianceVersion == m_radianceVersion && frame.settings.anisotropicMips == m_anisotropic
        && frame.shape.bounceVolume == m_levelZeroOnly)
        return { PassDecision::Action::Reuse, "radiance unchanged" };
    if (frame.shape.bounceVolume)
        return { PassDecision::Action::Run, "level 0 only: cones trace the bounced volume's levels" };
    return { PassDecision::Action::Run, "radiance was re-injected" };
}

void MipmapPass::execute(FrameContext& frame)
{
    VoxelVolume& v = frame.voxels;
    m_radianceVersion = v.radianceVersion;
    m_anisotropic = frame.settings.anisotropicMips;
    m_levelZeroOnly = frame.shape.bounceVolume;
    // With bounces in the voxels cones trace the bounced volume, which filters its own levels; the
    // first-bounce light is only its source, read at level 0, so its levels would be memory nobody reads.
    setLevelCount(v.radiance, frame.shape.radianceLevels);
    if (m_levelZeroOnly) {
        v.directional = gl::Texture();
        return;
    }
    m_builder.listCells(frame.shaders, v.frame.resolution, v.frame.levelCount(),
        v.occupiedVoxels(frame.scene.hasDynamicMeshes()));
    if (frame.settings.anisotropicMips) {
        m_builder.buildDirectional(frame.shaders, v.radiance, v.frame.resolution, v.directional);
    } else {
        m_builder.buildBox(frame.shaders, v.radiance);
        v.directional = gl::Texture();
    }
}

} // namespace vct::render
