#include "passes/VoxelMipBuilder.h"

#include "core/FrameResources.h"
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
    gl::Texture& directional)
{
    if (!m_directionalProgram) {
        m_directionalProgram = shaders.build({"directional downsample", {"mipmap/DownsampleDirectional.comp"}, {}});
        m_allDirectionsProgram = shaders.build({"directional downsample, first level", {"mipmap/DownsampleAllDirections.comp"}, {}});
    }
    const int levels = source.levels() - 1;
    if (levels < 1)
        return;
    const int size = std::max(1, resolution / 2);
    if (!directional || directional.width() != size || directional.levels() != levels)
        directional = gl::Texture::create3DStack(GL_RGBA16F, size, kDirectionalTiles, levels);
    // Level 1 of every chain from the isotropic level 0, in one pass over its shared children.
    m_allDirectionsProgram.use();
    source.bindUnit(0);
    directional.bindImage(0, 0, GL_WRITE_ONLY);
    const GLuint firstGroups = GLuint((size + 3) / 4);
    glDispatchCompute(firstGroups, firstGroups, firstGroups);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);

    // Later levels of all six chains at once, each tile from the same tile one level finer.
    m_directionalProgram.use();
    directional.bindUnit(0);
    for (int level = 1; level < levels; ++level) {
        m_directionalProgram.set("uSourceLevel", level - 1);
        directional.bindImage(0, level, GL_WRITE_ONLY);
        const GLuint groups = GLuint((std::max(1, size >> level) + 3) / 4);
        glDispatchCompute(groups, groups, groups * GLuint(kDirectionalTiles));
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
}

} // namespace vct::render
