#include "core/EnclosedSpace.h"

#include "core/TriangleBoxOverlap.h"

#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cmath>

namespace vct::render {

namespace {

/// Grows every cell a little, so a surface through a cell's face or edge marks the cells on both sides: the
/// flood must never slip between two triangles that meet there.
constexpr double kRoundingSlack = 1e-4;

} // namespace

EnclosedSpace::EnclosedSpace(int resolution)
    : m_resolution(std::clamp(resolution, 1, kMaxResolution))
    , m_cells(std::size_t(m_resolution) * std::size_t(m_resolution) * std::size_t(m_resolution), Empty)
{
}

void EnclosedSpace::addTriangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c)
{
    if (!isFinitePoint(a) || !isFinitePoint(b) || !isFinitePoint(c)) {
        ++m_skippedTriangles;
        return;
    }
    const glm::dvec3 lo = glm::min(glm::min(glm::dvec3(a), glm::dvec3(b)), glm::dvec3(c));
    const glm::dvec3 hi = glm::max(glm::max(glm::dvec3(a), glm::dvec3(b)), glm::dvec3(c));
    glm::ivec3 first, last;
    bool oneCell = true;
    for (int axis = 0; axis < 3; ++axis) {
        const double from = std::floor(lo[axis] - kRoundingSlack), to = std::floor(hi[axis] + kRoundingSlack);
        oneCell = oneCell && from == to;
        // Clamped as doubles: a finite coordinate far outside the grid would overflow an int.
        first[axis] = int(std::clamp(from, 0.0, double(m_resolution)));
        last[axis] = int(std::clamp(to, -1.0, double(m_resolution - 1)));
        if (first[axis] > last[axis])
            return;
    }
    // Most triangles of a detailed model lie within one cell: no test needed. (Only where the triangle's own
    // bounds are one cell: clamped to the grid, a large triangle's may be one cell it misses.)
    if (oneCell) {
        std::uint8_t& state = m_cells[indexOf(first)];
        m_occupiedCells += state == Occupied ? 0 : 1;
        state = Occupied;
        return;
    }
    glm::ivec3 cell;
    for (cell.z = first.z; cell.z <= last.z; ++cell.z)
        for (cell.y = first.y; cell.y <= last.y; ++cell.y)
            for (cell.x = first.x; cell.x <= last.x; ++cell.x) {
                std::uint8_t& state = m_cells[indexOf(cell)];
                if (state == Occupied)
                    continue;
                const glm::dvec3 boxLo = glm::dvec3(cell) - kRoundingSlack;
                if (!triangleOverlapsBox(glm::dvec3(a), glm::dvec3(b), glm::dvec3(c), boxLo,
                        boxLo + 1.0 + 2.0 * kRoundingSlack))
                    continue;
                state = Occupied;
                ++m_occupiedCells;
            }
}

void EnclosedSpace::addMesh(const std::vector<glm::vec3>& positions,
    const std::vector<std::uint32_t>& indices, const glm::mat4& toGrid)
{
    m_skippedTriangles += forEachGridTriangle(positions, indices, toGrid,
        [&](const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) { addTriangle(a, b, c); });
}

void EnclosedSpace::solve()
{
    // A scanline flood: each seed fills its whole run of empty cells along x (contiguous in memory), then
    // seeds the runs beside it in the four neighbouring rows. Cell by cell with six neighbours each, it took
    // six times as long (docs/BENCHMARKS.md, "Enclosed space").
    const int n = m_resolution;
    std::vector<glm::ivec3> seeds;
    const auto row = [&](int y, int z) { return m_cells.data() + indexOf({ 0, y, z }); };
    // Seeds every run of empty cells of row (y, z) that meets [from, to].
    const auto seedRuns = [&](int y, int z, int from, int to) {
        if (y < 0 || y >= n || z < 0 || z >= n)
            return;
        const std::uint8_t* cells = row(y, z);
        for (int x = from; x <= to; ++x)
            if (cells[x] == Empty && (x == from || cells[x - 1] != Empty))
                seeds.push_back({ x, y, z });
    };
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y) {
            if (y == 0 || y == n - 1 || z == 0 || z == n - 1)
                seedRuns(y, z, 0, n - 1); // a whole face of the grid
            else {
                seedRuns(y, z, 0, 0);
                seedRuns(y, z, n - 1, n - 1);
            }
        }
    while (!seeds.empty()) {
        const glm::ivec3 seed = seeds.back();
        seeds.pop_back();
        std::uint8_t* cells = row(seed.y, seed.z);
        if (cells[seed.x] != Empty)
            continue;
        int from = seed.x, to = seed.x;
        while (from > 0 && cells[from - 1] == Empty)
            --from;
        while (to + 1 < n && cells[to + 1] == Empty)
            ++to;
        std::fill(cells + from, cells + to + 1, std::uint8_t(Open));
        seedRuns(seed.y - 1, seed.z, from, to);
        seedRuns(seed.y + 1, seed.z, from, to);
        seedRuns(seed.y, seed.z - 1, from, to);
        seedRuns(seed.y, seed.z + 1, from, to);
    }
    m_enclosedCells = 0;
    for (std::uint8_t& state : m_cells)
        if (state == Empty) {
            state = Enclosed;
            ++m_enclosedCells;
        }
}

bool EnclosedSpace::occupied(const glm::ivec3& cell) const
{
    return stateOf(cell) == Occupied;
}

bool EnclosedSpace::enclosed(const glm::ivec3& cell) const
{
    return stateOf(cell) == Enclosed;
}

std::optional<std::uint8_t> EnclosedSpace::stateOf(const glm::ivec3& cell) const
{
    if (glm::any(glm::lessThan(cell, glm::ivec3(0)))
        || glm::any(glm::greaterThanEqual(cell, glm::ivec3(m_resolution))))
        return std::nullopt;
    return m_cells[indexOf(cell)];
}

std::vector<std::uint8_t> EnclosedSpace::texels() const
{
    std::vector<std::uint8_t> bytes(m_cells.size(), 0);
    for (std::size_t i = 0; i < m_cells.size(); ++i)
        bytes[i] = m_cells[i] == Enclosed ? 255 : 0;
    return bytes;
}

std::size_t EnclosedSpace::indexOf(const glm::ivec3& cell) const
{
    const std::size_t n = std::size_t(m_resolution);
    return (std::size_t(cell.z) * n + std::size_t(cell.y)) * n + std::size_t(cell.x);
}

} // namespace vct::render
