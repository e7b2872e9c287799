#pragma once

#include "scene/RenderSettings.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace vct::render {

/**
 * Which empty cells of a grid no light can leave: those that no path of empty cells, face to face, joins to
 * the grid's faces. A cone traced from such a cell must end on a surface, so what it does not see after
 * crossing the voxels is light the voxels let through (a wall one voxel thick seen at a coarse level), not
 * light that left the scene: the diffuse gathers scale it back (common/ConeTracing.glsl, docs/DESIGN.md,
 * "Enclosed space"). Cells are marked occupied by an exact triangle/box test, so a watertight surface
 * separates the cells on its two sides. An opening is seen only where whole cells lie in it: one narrower
 * than a cell is always closed, one narrower than two may be, as it falls on the cells. Plain arithmetic,
 * without GL.
 *
 * Grid space is in cells: cell k spans [k, k + 1) on each axis, the grid [0, resolution]^3.
 */
class EnclosedSpace {
public:
    /// Largest resolution built: a byte per cell on the CPU and in the texture.
    static constexpr int kMaxResolution = RenderSettings::kMaxEnclosureResolution;

    /** An empty grid of @p resolution^3 cells (clamped to 1..kMaxResolution); nothing enclosed until solve().
     */
    explicit EnclosedSpace(int resolution);

    int resolution() const { return m_resolution; }
    /** Marks the cells triangle @p a, @p b, @p c (grid space) meets as occupied. A triangle with a non-finite
     * coordinate marks nothing and counts in skippedTriangles(). */
    void addTriangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);
    /** addTriangle() for each triangle of a mesh: @p positions in object space, taken to grid space by the
     * affine @p toGrid; @p indices three per triangle (a triangle with an index out of range is skipped and
     * counted; a trailing one or two indices are ignored, as the renderer's draws ignore them). */
    void addMesh(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices,
        const glm::mat4& toGrid);
    /** Floods the empty cells joined to the grid's faces; every other empty cell is then enclosed. */
    void solve();

    bool occupied(const glm::ivec3& cell) const;
    /** Whether @p cell is empty and closed in (after solve()); false outside the grid. */
    bool enclosed(const glm::ivec3& cell) const;
    std::size_t occupiedCells() const { return m_occupiedCells; }
    std::size_t enclosedCells() const { return m_enclosedCells; }
    std::size_t skippedTriangles() const { return m_skippedTriangles; }
    /** A byte per cell, x fastest: 255 where enclosed, 0 elsewhere (an r8 texture's texels). */
    std::vector<std::uint8_t> texels() const;

private:
    enum Cell : std::uint8_t { Empty, Occupied, Enclosed }; ///< after solve(), open cells stay Empty
    std::size_t indexOf(const glm::ivec3& cell) const;
    /** The cell's state, nothing outside the grid. */
    std::optional<std::uint8_t> stateOf(const glm::ivec3& cell) const;

    int m_resolution = 1;
    std::vector<std::uint8_t> m_cells;
    std::size_t m_occupiedCells = 0;
    std::size_t m_enclosedCells = 0;
    std::size_t m_skippedTriangles = 0;
};

} // namespace vct::render
