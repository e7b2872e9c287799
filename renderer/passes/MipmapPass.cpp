#include "passes/MipmapPass.h"

#include "core/FrameContext.h"

namespace vct::render {

PassDecision MipmapPass::plan(const FrameContext& frame)
{
    if (frame.voxels.radianceVersion == m_radianceVersion && frame.settings.anisotropicMips == m_anisotropic)
        return { PassDecision::Action::Reuse, "radiance unchanged" };
    return { PassDecision::Action::Run, "radiance was re-injected" };
}

void MipmapPass::execute(FrameContext& frame)
{
    VoxelVolume& v = frame.voxels;
    m_builder.listCells(frame.shaders, v.frame.resolution, v.radiance.levels(),
        v.occupiedVoxels(frame.scene.hasDynamicMeshes()));
    if (frame.settings.anisotropicMips) {
        m_builder.buildDirectional(frame.shaders, v.radiance, v.frame.resolution, v.directional);
    } else {
        m_builder.buildBox(frame.shaders, v.radiance);
        v.boxMipsVersion = v.radianceVersion;
        v.directional = gl::Texture();
    }
    m_radianceVersion = v.radianceVersion;
    m_anisotropic = frame.settings.anisotropicMips;
}

} // namespace vct::render
