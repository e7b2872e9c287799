#include "passes/MipmapPass.h"

#include "core/FrameContext.h"

#include <algorithm>

namespace vct::render {

PassDecision MipmapPass::plan(const FrameContext& frame)
{
    if (frame.voxels.radianceVersion == m_radianceVersion)
        return {PassDecision::Action::Reuse, "radiance unchanged"};
    return {PassDecision::Action::Run, "radiance was re-injected"};
}

void MipmapPass::execute(FrameContext& frame)
{
    if (!m_program)
        m_program = frame.shaders.build({"downsample", {"mipmap/Downsample.comp"}, {}});
    VoxelVolume& v = frame.voxels;
    m_program.use();
    v.radiance.bindUnit(0);
    for (int level = 1; level < v.radiance.levels(); ++level) {
        const int size = std::max(1, v.frame.resolution >> level);
        m_program.set("uSourceLevel", level - 1);
        v.radiance.bindImage(0, level, GL_WRITE_ONLY);
        const GLuint groups = GLuint((size + 3) / 4);
        glDispatchCompute(groups, groups, groups);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
    m_radianceVersion = v.radianceVersion;
}

} // namespace vct::render
