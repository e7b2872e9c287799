#include "passes/VoxelMipBuilder.h"

#include "core/ShaderLibrary.h"

#include <algorithm>

namespace vct::render {

void VoxelMipBuilder::buildBox(const ShaderLibrary& shaders, gl::Texture& volume, int resolution)
{
    if (!m_boxProgram)
        m_boxProgram = shaders.build({"downsample", {"mipmap/Downsample.comp"}, {}});
    m_boxProgram.use();
    volume.bindUnit(0);
    for (int level = 1; level < volume.levels(); ++level) {
        const int size = std::max(1, resolution >> level);
        m_boxProgram.set("uSourceLevel", level - 1);
        volume.bindImage(0, level, GL_WRITE_ONLY);
        const GLuint groups = GLuint((size + 3) / 4);
        glDispatchCompute(groups, groups, groups);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
}

void VoxelMipBuilder::buildDirectional(const ShaderLibrary& shaders, const gl::Texture& source, int resolution,
    std::array<gl::Texture, 6>& directional)
{
    if (!m_directionalProgram) {
        m_directionalProgram = shaders.build({"directional downsample", {"mipmap/DownsampleDirectional.comp"}, {}});
        m_allDirectionsProgram = shaders.build({"directional downsample, first level", {"mipmap/DownsampleAllDirections.comp"}, {}});
    }
    const int levels = source.levels() - 1;
    if (levels < 1)
        return;
    for (gl::Texture& target : directional)
        if (!target || target.width() != resolution / 2)
            target = gl::Texture::create3D(GL_RGBA16F, resolution / 2, levels);
    // Level 1 of every chain from the isotropic level 0, in one pass over its shared children.
    m_allDirectionsProgram.use();
    source.bindUnit(0);
    for (std::size_t d = 0; d < 6; ++d)
        directional[d].bindImage(GLuint(d), 0, GL_WRITE_ONLY);
    const GLuint firstGroups = GLuint((std::max(1, resolution / 2) + 3) / 4);
    glDispatchCompute(firstGroups, firstGroups, firstGroups);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);

    // Later levels from the same direction's previous one.
    m_directionalProgram.use();
    for (int d = 0; d < 6; ++d) {
        gl::Texture& target = directional[std::size_t(d)];
        m_directionalProgram.set("uAxis", d / 2);
        m_directionalProgram.set("uAxisSign", d % 2 == 0 ? 1 : -1);
        for (int level = 1; level < levels; ++level) {
            target.bindUnit(0);
            m_directionalProgram.set("uSourceLevel", level - 1);
            target.bindImage(0, level, GL_WRITE_ONLY);
            const GLuint groups = GLuint((std::max(1, resolution >> (level + 1)) + 3) / 4);
            glDispatchCompute(groups, groups, groups);
            glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        }
    }
}

} // namespace vct::render
