#include "core/BrickPool.h"

#include "core/TriangleBoxOverlap.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cmath>

namespace vct::render {

namespace {

/// Grows every brick's box a little, so a triangle that touches one only within rounding still allocates
/// it: an extra brick costs a little memory, a missing one loses the light of the voxels it should store.
constexpr double kRoundingSlack = 1e-3;

} // namespace

BrickPool::BrickPool(int resolution)
    : m_resolution(std::max(resolution, 0))
    , m_bricksPerSide(std::max((m_resolution + kBrickVoxels - 1) / kBrickVoxels, 1))
    , m_slots(std::size_t(m_bricksPerSide) * std::size_t(m_bricksPerSide) * std::size_t(m_bricksPerSide), 0u)
{
}

int BrickPool::addTriangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, float reach)
{
    if (!isFinitePoint(a) || !isFinitePoint(b) || !isFinitePoint(c) || !std::isfinite(reach)) {
        ++m_skippedTriangles;
        return 0;
    }
    // Bricks that start inside the grid: none for a pool of resolution 0, whose single table entry exists
    // only so the table is a valid texture.
    const int gridBricks = (m_resolution + kBrickVoxels - 1) / kBrickVoxels;
    const double margin = double(std::max(reach, 0.0f)) + kRoundingSlack;
    const glm::dvec3 lo = glm::min(glm::min(glm::dvec3(a), glm::dvec3(b)), glm::dvec3(c));
    const glm::dvec3 hi = glm::max(glm::max(glm::dvec3(a), glm::dvec3(b)), glm::dvec3(c));
    // Only bricks whose grown box can meet the triangle's bounds; clamped as doubles, since a finite
    // coordinate far outside the grid would overflow an int.
    glm::ivec3 first, last;
    for (int axis = 0; axis < 3; ++axis) {
        const double from = std::ceil((lo[axis] - kBrickTexels - margin) / kBrickVoxels);
        const double to = std::floor((hi[axis] + margin) / kBrickVoxels);
        first[axis] = int(std::clamp(from, 0.0, double(gridBricks)));
        last[axis] = int(std::clamp(to, -1.0, double(gridBricks - 1)));
        if (first[axis] > last[axis])
            return 0;
    }
    int added = 0;
    glm::ivec3 brick;
    for (brick.z = first.z; brick.z <= last.z; ++brick.z)
        for (brick.y = first.y; brick.y <= last.y; ++brick.y)
            for (brick.x = first.x; brick.x <= last.x; ++brick.x) {
                std::uint32_t& slot = m_slots[indexOf(brick)];
                if (slot != 0)
                    continue;
                // The boxes of the voxels the brick stores, border included, grown by the margin; the last
                // brick's border lies outside the grid, where no voxel is written.
                const glm::dvec3 boxLo = glm::dvec3(brick * kBrickVoxels) - margin;
                const glm::dvec3 boxHi
                    = glm::dvec3(glm::min(brick * kBrickVoxels + kBrickTexels, glm::ivec3(m_resolution)))
                    + margin;
                if (!triangleOverlapsBox(glm::dvec3(a), glm::dvec3(b), glm::dvec3(c), boxLo, boxHi))
                    continue;
                slot = std::uint32_t(++m_allocatedBricks);
                ++added;
            }
    return added;
}

int BrickPool::addMesh(const std::vector<glm::vec3>& positions, const std::vector<std::uint32_t>& indices,
    const glm::mat4& toGrid, float reach)
{
    int added = 0;
    m_skippedTriangles += forEachGridTriangle(
        positions, indices, toGrid, [&](const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
            added += addTriangle(a, b, c, reach);
        });
    return added;
}

std::uint32_t BrickPool::slot(const glm::ivec3& brick) const
{
    if (glm::any(glm::lessThan(brick, glm::ivec3(0)))
        || glm::any(glm::greaterThanEqual(brick, glm::ivec3(m_bricksPerSide))))
        return 0;
    return m_slots[indexOf(brick)];
}

void BrickPool::clear()
{
    std::fill(m_slots.begin(), m_slots.end(), 0u);
    m_allocatedBricks = 0;
    m_skippedTriangles = 0;
}

glm::ivec3 BrickPool::poolBricksFor(std::size_t bricks)
{
    const std::size_t maxSide = kMaxPoolBricksPerAxis;
    if (bricks >= maxSide * maxSide * maxSide)
        return glm::ivec3(0);
    const std::size_t needed = bricks + 1;
    // cbrt's rounding corrected both ways, so the side is the smallest whose cube holds them.
    std::size_t side = std::size_t(std::ceil(std::cbrt(double(needed))));
    while (side > 1 && (side - 1) * (side - 1) * (side - 1) >= needed)
        --side;
    while (side * side * side < needed)
        ++side;
    const std::size_t layers = (needed + side * side - 1) / (side * side);
    return glm::ivec3(int(side), int(side), int(layers));
}

glm::ivec3 BrickPool::slotPosition(std::uint32_t slot, const glm::ivec3& poolBricks)
{
    if (glm::any(glm::lessThanEqual(poolBricks, glm::ivec3(0))))
        return glm::ivec3(0);
    const std::uint64_t row = std::uint64_t(poolBricks.x);
    const std::uint64_t layer = row * std::uint64_t(poolBricks.y);
    return glm::ivec3(int(slot % row), int(slot / row % std::uint64_t(poolBricks.y)), int(slot / layer));
}

std::vector<std::uint32_t> BrickPool::table(const glm::ivec3& poolBricks) const
{
    std::vector<std::uint32_t> words(m_slots.size(), 0u);
    const bool encodable = glm::all(glm::greaterThan(poolBricks, glm::ivec3(0)))
        && glm::all(glm::lessThanEqual(poolBricks, glm::ivec3(1 << kPositionBits)));
    if (!encodable)
        return words;
    const std::size_t capacity
        = std::size_t(poolBricks.x) * std::size_t(poolBricks.y) * std::size_t(poolBricks.z);
    for (std::size_t i = 0; i < m_slots.size(); ++i) {
        const std::uint32_t slot = m_slots[i];
        if (slot == 0 || slot >= capacity)
            continue;
        const glm::uvec3 p(slotPosition(slot, poolBricks));
        words[i] = kAllocatedBit | p.x | p.y << kPositionBits | p.z << (2 * kPositionBits);
    }
    return words;
}

std::size_t BrickPool::indexOf(const glm::ivec3& brick) const
{
    const std::size_t side = std::size_t(m_bricksPerSide);
    return std::size_t(brick.x) + side * (std::size_t(brick.y) + side * std::size_t(brick.z));
}

} // namespace vct::render
