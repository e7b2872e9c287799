#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace vct::render {

/**
 * The CPU side of a sparse voxel grid: which bricks of kBrickVoxels^3 voxels geometry can reach, and where
 * each sits in the pool texture that stores only those. A brick is stored as kBrickTexels^3 texels: its
 * voxels plus, on the high side of each axis, a copy of the next brick's first voxel layer, so a trilinear
 * lookup never reads across two bricks. Pool slot 0 is a brick that stays zero, for lookups of empty space;
 * real bricks take slots 1, 2, 3, ... in the order they are first reached, and keep them, so bricks a moving
 * object adds later go after the others and nothing already in the pool has to move. Plain arithmetic,
 * without GL.
 *
 * Grid space is in voxels: voxel k spans [k, k + 1) on each axis, the grid [0, resolution]^3, and brick b
 * the voxels [8b, 8b + 8), storing [8b, 8b + 8] with its border.
 */
class BrickPool {
public:
    static constexpr int kBrickVoxels = 8;
    static constexpr int kBrickTexels = kBrickVoxels + 1;
    /// Voxels a brick stores, and the pool texels it takes with its border: what a sparse grid holds and
    /// costs per brick.
    static constexpr std::size_t kVoxelsPerBrick = std::size_t(kBrickVoxels) * kBrickVoxels * kBrickVoxels;
    static constexpr std::size_t kTexelsPerBrick = std::size_t(kBrickTexels) * kBrickTexels * kBrickTexels;
    /// GL_MAX_3D_TEXTURE_SIZE's minimum, 2048 texels (what llvmpipe allows too), in whole bricks.
    static constexpr int kMaxPoolBricksPerAxis = 2048 / kBrickTexels;
    /// In a table() word, marks an allocated brick, so that slot 0 at pool position (0, 0, 0) differs from
    /// an empty brick's 0.
    static constexpr std::uint32_t kAllocatedBit = 1u << 31;
    /// Bits per axis of the pool position in a table() word.
    static constexpr int kPositionBits = 10;

    /** A pool without a grid, allocating nothing; not explicit, so a struct holding one can be `= {}`. */
    BrickPool()
        : BrickPool(0)
    {
    }
    /** An empty pool for a grid of @p resolution^3 voxels (a power of two, 8 to 1024). */
    explicit BrickPool(int resolution);

    int resolution() const { return m_resolution; }
    /** Bricks along each axis of the grid, at least 1 so that table() is always a valid texture. */
    int bricksPerSide() const { return m_bricksPerSide; }

    /**
     * Allocates the bricks triangle @p a, @p b, @p c (grid space) can write: the voxelizer writes every
     * voxel whose box lies within @p reach voxels of the triangle, so brick b is needed when the triangle
     * meets [8b - reach, 8b + 9 + reach] on every axis, its stored voxels' boxes grown by the reach (the
     * last brick's ending at the grid's edge, as its border has no voxel to copy).
     * Degenerate triangles (a point, a segment) allocate what they touch; one with a non-finite coordinate
     * (or a non-finite @p reach) allocates nothing and counts in skippedTriangles(). Returns how many bricks
     * were newly allocated.
     */
    int addTriangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, float reach = 1.0f);
    /**
     * addTriangle() for each triangle of a mesh: @p positions in object space, taken to grid space by the
     * affine @p toGrid; @p indices three per triangle (a trailing one or two are ignored, a triangle with an
     * index past @p positions is skipped and counted). Returns how many bricks were newly allocated.
     */
    int addMesh(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices,
        const glm::mat4& toGrid, float reach = 1.0f);

    /** False also for a brick outside the grid. */
    bool allocated(const glm::ivec3& brick) const { return slot(brick) != 0; }
    /** Real bricks, not counting the zero slot. */
    std::size_t allocatedBricks() const { return m_allocatedBricks; }
    /** Triangles left out for non-finite coordinates or bad indices since construction or clear(). */
    std::size_t skippedTriangles() const { return m_skippedTriangles; }
    /** The pool slot (1, 2, ...) of @p brick, 0 for an empty brick or one outside the grid. */
    std::uint32_t slot(const glm::ivec3& brick) const;
    /** Forgets every brick and skipped triangle, for a rebuild from scratch. */
    void clear();

    /**
     * The pool's size in bricks per axis with room for @p bricks and the zero slot: x = y = s, the smallest
     * side whose cube holds them, and z the fewest layers of s * s that do; a near cube keeps each axis of
     * the texture short. (0, 0, 0) when even kMaxPoolBricksPerAxis^3 cannot hold them.
     */
    static glm::ivec3 poolBricksFor(std::size_t bricks);
    /** Where @p slot sits in a pool of @p poolBricks bricks per axis: x fastest, then y, then z. */
    static glm::ivec3 slotPosition(std::uint32_t slot, const glm::ivec3& poolBricks);
    /**
     * The indirection table, uploaded as an r32ui 3D texture of bricksPerSide()^3 words, x fastest: 0 for an
     * empty brick, else kAllocatedBit | px | py << 10 | pz << 20 with (px, py, pz) = slotPosition(slot,
     * @p poolBricks). A brick whose slot @p poolBricks cannot hold reads as empty rather than as a position
     * outside the pool texture.
     */
    std::vector<std::uint32_t> table(const glm::ivec3& poolBricks) const;

private:
    std::size_t indexOf(const glm::ivec3& brick) const;

    int m_resolution = 0;
    int m_bricksPerSide = 1;
    std::vector<std::uint32_t> m_slots; ///< per brick, x fastest; 0 = empty
    std::size_t m_allocatedBricks = 0;
    std::size_t m_skippedTriangles = 0;
};

} // namespace vct::render
