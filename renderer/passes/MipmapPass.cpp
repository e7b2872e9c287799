#include "passes/MipmapPass.h"

#include "core/FrameContext.h"
#include "core/ResourceNames.h"

namespace vct::render {

PassDeclaration MipmapPass::declare() const
{
    return { { resource::kRadiance },
        { resource::kRadiance, resource::kRadianceDirectional, resource::kMipCellMarks } };
}

std::vector<TextureSlot> MipmapPass::textures(const FrameContext& frame)
{
    // With bounces in the voxels cones trace the bounced volume, which filters its own levels; the
    // first-bounce light is only its source, read at level 0, so its levels would be memory nobody reads.
    VoxelVolume& v = frame.voxels;
    const bool filters = !frame.shape.bounceVolume;
    const bool chains = frame.settings.anisotropicMips && filters;
    return { { resource::kRadianceDirectional, ResourceGroup::Voxels, &v.directional,
                 chains ? VoxelMipBuilder::directionalDesc(v.frame.resolution) : gl::TextureDesc {} },
        { resource::kMipCellMarks, ResourceGroup::Voxels, &m_builder.marks(),
            filters ? VoxelMipBuilder::marksDesc(v.frame.resolution) : gl::TextureDesc {} } };
}

PassDecision MipmapPass::plan(const FrameContext& frame) const
{
    if (frame.voxels.radianceVersion == m_radianceVersion && frame.settings.anisotropicMips == m_anisotropic
        && frame.settings.dropBackFaces == m_dropBackFaces && frame.shape.bounceVolume == m_levelZeroOnly)
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
    m_dropBackFaces = frame.settings.dropBackFaces;
    m_levelZeroOnly = frame.shape.bounceVolume;
    if (m_levelZeroOnly)
        return;
    m_builder.listCells(frame.shaders, v.frame.resolution, v.frame.levelCount(),
        v.occupiedVoxels(frame.scene.hasDynamicMeshes()));
    if (frame.settings.anisotropicMips) {
        m_builder.buildDirectional(frame.shaders, v.radiance,
            frame.settings.dropBackFaces ? &v.normal : nullptr, v.frame.resolution, v.directional);
    } else {
        m_builder.buildBox(frame.shaders, v.radiance);
    }
}

} // namespace vct::render
