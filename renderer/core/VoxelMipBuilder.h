#pragma once

#include "core/OccupiedCellList.h"
#include "gl/Program.h"
#include "gl/Texture.h"

#include <cstdint>
#include <vector>

namespace vct::render {

class ShaderLibrary;

/**
 * Filters a radiance volume into its mip levels: the box chain (each level the 2x2x2 average of the one
 * below) and, for anisotropic mips, six directional chains. Shared by the mipmap pass (first-bounce
 * radiance) and the bounce pass (the volume after a second bounce), so both filter identically.
 *
 * Only the cells above occupied voxels are filtered; the rest of each level is cleared. Most of a grid is
 * empty, and on llvmpipe a clear costs far less than a shader's stores (docs/DESIGN.md, "Measured choices").
 * listCells() finds those cells; build the chains after it.
 */
class VoxelMipBuilder {
public:
    /**
     * Lists the cells of every level above level 0 that lie above the voxels of @p occupied (lists of level-0
     * voxels that together name every voxel holding anything, duplicates allowed; core/OccupiedCellList).
     */
    void listCells(const ShaderLibrary& shaders, int resolution, int levels,
        const std::vector<const OccupiedCellList*>& occupied);
    /**
     * The cells of @p cellVoxels^3 voxels (a power of two from 2 to the grid) that listCells() listed: every
     * one holding a voxel.
     */
    const OccupiedCellList& cellsOfSize(int cellVoxels) const;
    /** Levels @p firstLevel..N of @p volume, each from the one below (the levels below written already). */
    void buildBox(const ShaderLibrary& shaders, gl::Texture& volume, int firstLevel = 1);
    /**
     * Six chains (+x, -x, +y, -y, +z, -z; texture level k = grid level k + 1) composited front to back from
     * level 0 of @p source into the tiles of @p directional, made as directionalDesc() says. With
     * @p backFaceNormals (the voxels' normals) each chain leaves out the voxels of one-sided surfaces that
     * face the way it travels (RenderSettings::dropBackFaces). From texture level @p firstLevel on, when the
     * caller wrote the levels below (after prepareDirectional()).
     */
    void buildDirectional(const ShaderLibrary& shaders, const gl::Texture& source,
        const gl::Texture* backFaceNormals, int resolution, gl::Texture& directional, int firstLevel = 0);
    /**
     * Clears @p directional's levels where a build would need them cleared (a new texture, or cells listed
     * again): before a caller writes a level of its own into it (the bounce solve's reinjection writes the
     * first).
     */
    void prepareDirectional(int resolution, gl::Texture& directional);
    /**
     * The six directional chains of a grid of @p resolution: one stack of tiles from grid level 1 (texture
     * level k = grid level k + 1), laid out by scene/DirectionalStackLayout.h; empty for a grid too small.
     */
    static gl::TextureDesc directionalDesc(int resolution);
    /** The scratch texture listCells() marks listed cells in, for a grid of @p resolution. */
    static gl::TextureDesc marksDesc(int resolution);
    /** Where the marks live: its owner's textures() lists it, so the pipeline makes it as marksDesc() says.
     */
    gl::Texture& marks() { return m_listed; }

private:
    const gl::Program* m_boxProgram = nullptr;
    const gl::Program* m_directionalProgram = nullptr;
    const gl::Program* m_allDirectionsProgram = nullptr;
    const gl::Program* m_allDirectionsDroppingBackFaces = nullptr;
    const gl::Program* m_listParents = nullptr;
    gl::Texture
        m_listed; ///< r32ui over the cells of level 1: bit k set where the cell of level k + 1 is listed
    std::vector<OccupiedCellList> m_levelCells; ///< [k]: the listed cells of grid level k + 1
    std::uint64_t m_listing = 0; ///< how many times listCells() ran
    /// The directional texture whose levels were last cleared (its serial), and for which listing.
    std::uint64_t m_clearedSerial = 0;
    std::uint64_t m_clearedListing = 0;
};

} // namespace vct::render
