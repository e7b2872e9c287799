#include "core/VoxelMipBuilder.h"

#include "core/FrameResources.h"
#include "core/ShaderLibrary.h"
#include "scene/DirectionalStackLayout.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace vct::render {

gl::TextureDesc VoxelMipBuilder::directionalDesc(int resolution)
{
    const DirectionalStackLayout layout = DirectionalStackLayout::of(resolution);
    if (layout.levels < 1)
        return {};
    return gl::TextureDesc::volumeStack(
        GL_RGBA16F, layout.size, kDirectionalTiles, layout.levels, layout.gapShift);
}

gl::TextureDesc VoxelMipBuilder::marksDesc(int resolution)
{
    return gl::TextureDesc::volume(GL_R32UI, std::max(1, resolution / 2));
}

void VoxelMipBuilder::listCells(const ShaderLibrary& shaders, int resolution, int levels,
    const std::vector<const OccupiedCellList*>& occupied)
{
    if (!m_listParents)
        m_listParents = &shaders.program({ "list parent cells", { "mipmap/ListParents.comp" }, {} });
    const int size = std::max(1, resolution / 2);
    if (m_listed.desc() != marksDesc(resolution))
        throw std::logic_error("the cell marks are not made for this grid");
    const GLuint none = 0;
    glClearTexImage(m_listed.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &none);
    ++m_listing;
    m_levelCells.resize(std::size_t(std::max(levels - 1, 0)));
    m_listParents->use();
    m_listParents->set("uGroupSize", OccupiedCellList::kGroupSize);
    m_listed.bindImage(0, 0, GL_READ_WRITE);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    for (std::size_t k = 0; k < m_levelCells.size(); ++k) {
        // Level k + 1's cells: the parents of the listed voxels, or of level k's cells.
        const std::size_t side = std::size_t(std::max(1, size >> k));
        m_levelCells[k].reset(side * side * side, 2);
        m_listParents->set("uLevelBit", 1u << unsigned(k));
        if (k == 0) {
            for (const OccupiedCellList* voxels : occupied)
                voxels->dispatchOverCells(); // read at storage buffers 0 and 1, appended at 2 and 3
        } else {
            m_levelCells[k - 1].dispatchOverCells();
        }
        glMemoryBarrier(
            GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
}

const OccupiedCellList& VoxelMipBuilder::cellsOfSize(int cellVoxels) const
{
    int level = 0;
    while ((1 << level) < cellVoxels)
        ++level;
    if ((1 << level) != cellVoxels || level < 1 || std::size_t(level) > m_levelCells.size())
        throw std::logic_error("no cells of " + std::to_string(cellVoxels) + " voxels were listed");
    return m_levelCells[std::size_t(level - 1)];
}

void VoxelMipBuilder::buildBox(const ShaderLibrary& shaders, gl::Texture& volume, int firstLevel)
{
    if (!m_boxProgram)
        m_boxProgram = &shaders.program({ "downsample", { "mipmap/Downsample.comp" }, {} });
    m_boxProgram->use();
    volume.bindUnit(0);
    const int levels = std::min(volume.levels(), int(m_levelCells.size()) + 1);
    for (int level = std::max(firstLevel, 1); level < levels; ++level) {
        glClearTexImage(volume.id(), level, GL_RGBA, GL_FLOAT, nullptr);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
        m_boxProgram->set("uSourceLevel", level - 1);
        volume.bindImage(0, level, GL_WRITE_ONLY);
        m_levelCells[std::size_t(level - 1)].dispatchOverCells();
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
}

void VoxelMipBuilder::prepareDirectional(int resolution, gl::Texture& directional)
{
    const gl::TextureDesc wanted = directionalDesc(resolution);
    if (!wanted)
        return;
    if (directional.desc() != wanted)
        throw std::logic_error("the directional chains are not made for this grid");
    // Every build writes all six chains of every listed cell, so what a build leaves unwritten (the cells
    // above no voxel, the gaps between tiles, which must read empty) stays as cleared until the cells are
    // listed again or the texture is new. The bounce solve builds these chains four times or more over the
    // same cells, and the clears of a grid's whole levels took about a third of each build.
    if (directional.serial() == m_clearedSerial && m_listing == m_clearedListing)
        return;
    m_clearedSerial = directional.serial();
    m_clearedListing = m_listing;
    for (int level = 0; level < wanted.levels; ++level)
        glClearTexImage(directional.id(), level, GL_RGBA, GL_FLOAT, nullptr);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

void VoxelMipBuilder::buildDirectional(const ShaderLibrary& shaders, const gl::Texture& source,
    const gl::Texture* backFaceNormals, int resolution, gl::Texture& directional, int firstLevel)
{
    if (!m_directionalProgram) {
        m_directionalProgram
            = &shaders.program({ "directional downsample", { "mipmap/DownsampleDirectional.comp" }, {} });
        m_allDirectionsProgram = &shaders.program(
            { "directional downsample, first level", { "mipmap/DownsampleAllDirections.comp" }, {} });
        m_allDirectionsDroppingBackFaces
            = &shaders.program({ "directional downsample, first level, no back faces",
                { "mipmap/DownsampleAllDirections.comp" }, { "DROP_BACK_FACES" } });
    }
    // The chains start at grid level 1, from the source's level 0 alone: a source without box levels will do.
    // They stop where their tiles' gaps are one texel (directionalDesc).
    const gl::TextureDesc wanted = directionalDesc(resolution);
    if (!wanted)
        return;
    prepareDirectional(resolution, directional);
    for (int level = firstLevel; level < wanted.levels; ++level) {
        // Level 1 of every chain from the isotropic level 0, in one pass over its shared children; later
        // levels of all six chains at once, each tile from the same tile one level finer.
        const gl::Program& first
            = backFaceNormals ? *m_allDirectionsDroppingBackFaces : *m_allDirectionsProgram;
        const gl::Program& filter = level == 0 ? first : *m_directionalProgram;
        filter.use();
        if (level == 0) {
            source.bindUnit(0);
            if (backFaceNormals)
                backFaceNormals->bindUnit(1);
        } else {
            directional.bindUnit(0);
            filter.set("uSourceLevel", level - 1);
        }
        // From one tile's start to the next at the level written (the source's is twice that).
        filter.set("uTileStride", DirectionalStackLayout::of(resolution).stride(level));
        directional.bindImage(0, level, GL_WRITE_ONLY);
        m_levelCells[std::size_t(level)].dispatchOverCells();
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
}

} // namespace vct::render
