#pragma once

#include "core/VoxelRegion.h"
#include "gl/Buffer.h"
#include "gl/Program.h"
#include "gl/Texture.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <vector>

namespace vct::render {

class ShaderLibrary;

/**
 * The cells of a region that hold a surface, listed on the GPU (common/ListOccupied.comp) for a heavy compute
 * pass to run over with an indirect dispatch, so the count never comes back to the CPU. On llvmpipe a shader
 * holding lighting or cone code is several times slower per invocation even where it returns early, and most
 * of a voxel grid is empty; the heavy shader includes common/OccupiedCells.glsl and has local_size_x = 64.
 */
class OccupiedCellList {
public:
    static constexpr unsigned kGroupSize = 64;

    /**
     * Lists the cells of @p cellSize^3 voxels in @p region (in cells) whose voxels have opacity in @p albedo.
     * With @p clearTarget, first clears the region of its level 0 to @p clearValue (one texel per cell): the
     * heavy pass then writes the listed cells only. A clear costs far less on llvmpipe than a shader's
     * stores.
     */
    void build(const ShaderLibrary& shaders, const gl::Texture& albedo, const VoxelRegion& region,
        int cellSize, const gl::Texture* clearTarget = nullptr, glm::vec4 clearValue = glm::vec4(0.0f));
    /**
     * Lists with a pass of the caller's: @p lister (local size 4^3, including common/AppendCell.glsl, its
     * other uniforms and bindings already set) runs over @p region and calls appendCell() for the cells to
     * list.
     */
    void buildWith(const gl::Program& lister, const VoxelRegion& region);
    /**
     * At most @p cells cells from now on, however large the region listed: a sparse grid's voxels all lie in
     * its bricks, where a list as long as a region of a 512^3 grid would take 512 MiB outside the budget.
     */
    void capCapacity(std::size_t cells) { m_capacityCap = cells; }
    /**
     * Empties the list and binds it (storage buffers @p binding and the next) for a shader of the caller's,
     * of any stage, to fill with appendCell() (common/AppendCell.glsl with APPEND_BINDING = @p binding, its
     * uGroupSize set to kGroupSize) with at most @p capacity cells: the voxelizer lists the voxels it reaches
     * this way while it writes them.
     */
    void reset(std::size_t capacity, unsigned binding = 0);
    /** Binds the list as reset() does but keeps what it holds, for a shader to add more cells to it. */
    void bindForAppending(unsigned binding = 0) const;
    /**
     * Replaces the list by @p source's cells moved by -@p shift (the voxels of a grid that stepped by
     * @p shift, core/VolumeShift), leaving out those that fall outside @p kept; room for @p capacity cells.
     */
    void assignShifted(const ShaderLibrary& shaders, const OccupiedCellList& source, const glm::ivec3& shift,
        const VoxelRegion& kept, std::size_t capacity);
    /** Binds the list for the heavy shader (storage buffers 0 and 1) and dispatches it over the listed cells.
     */
    void dispatchOverCells() const;
    /** How many cells are listed: a readback that waits for the listing, for statistics only. */
    std::size_t count() const;
    /** The listed cells: a readback that waits for the listing, for statistics only. */
    std::vector<glm::ivec3> cells() const;

private:
    const gl::Program* m_program = nullptr;
    const gl::Program* m_shiftProgram = nullptr;
    gl::Buffer m_dispatch; ///< DispatchIndirectCommand followed by the count
    gl::Buffer m_cells; ///< packed cell coordinates, 10 bits per axis
    std::size_t m_capacityCap = SIZE_MAX;
};

} // namespace vct::render
