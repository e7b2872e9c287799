#include "passes/MipmapPass.h"

#include "core/FrameContext.h"

#include <algorithm>

namespace vct::render {

PassDecision MipmapPass::plan(const FrameContext& frame)
{
    if (frame.voxels.radianceVersion == m_radianceVersion && frame.settings.anisotropicMips == m_anisotropic)
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
    if (frame.settings.anisotropicMips)
        buildDirectional(frame);
    else
        for (gl::Texture& t : v.directional)
            t = gl::Texture();
    m_radianceVersion = v.radianceVersion;
    m_anisotropic = frame.settings.anisotropicMips;
}

void MipmapPass::buildDirectional(FrameContext& frame)
{
    if (!m_directionalProgram)
        m_directionalProgram = frame.shaders.build({"directional downsample", {"mipmap/DownsampleDirectional.comp"}, {}});
    VoxelVolume& v = frame.voxels;
    const int levels = v.radiance.levels() - 1;
    if (levels < 1)
        return;
    m_directionalProgram.use();
    for (int d = 0; d < 6; ++d) {
        gl::Texture& target = v.directional[std::size_t(d)];
        if (!target || target.width() != v.frame.resolution / 2)
            target = gl::Texture::create3D(GL_RGBA16F, v.frame.resolution / 2, levels);
        m_directionalProgram.set("uAxis", d / 2);
        m_directionalProgram.set("uAxisSign", d % 2 == 0 ? 1 : -1);
        for (int level = 0; level < levels; ++level) {
            // Level 1 comes from the isotropic level 0; later levels from the same direction's previous one.
            (level == 0 ? v.radiance : target).bindUnit(0);
            m_directionalProgram.set("uSourceLevel", level == 0 ? 0 : level - 1);
            target.bindImage(0, level, GL_WRITE_ONLY);
            const GLuint groups = GLuint((std::max(1, v.frame.resolution >> (level + 1)) + 3) / 4);
            glDispatchCompute(groups, groups, groups);
            glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        }
    }
}

} // namespace vct::render
