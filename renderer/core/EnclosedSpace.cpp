#include "core/EnclosedSpace.h"

#include "core/TriangleAxes.h"
#include "core/TriangleBoxOverlap.h"

#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <vector>

namespace vct::render {

namespace {

/// Grows every cell a little, so a surface through a cell's face or edge marks the cells on both sides: the
/// flood must never slip between two triangles that meet there.
constexpr double kRoundingSlack = 1e-4;

/// A row of cells along x, bit x for cell x: the grid is at most 128 cells a side.
using CellRow = unsigned __int128;
static_assert(EnclosedSpace::kMaxResolution <= 128);

/// The cells of @p empty in the runs that hold a cell of @p seeds (seeds within empty): a fill each way along
/// the row, seven shifts of doubling length (a Kogge-Stone fill), whatever the runs' lengths.
CellRow runsHolding(CellRow seeds, CellRow empty)
{
    CellRow up = seeds, down = seeds, upPath = empty, downPath = empty;
    for (int shift = 1; shift < 128; shift *= 2) {
        up |= upPath & (up << shift);
        upPath &= upPath << shift;
        down |= downPath & (down >> shift);
        downPath &= downPath >> shift;
    }
    return up | down;
}

/// Bit x set where cell x of a row of @p n cells (0 Empty, else not) is not empty: eight cells at a time,
/// each byte's lowest bits folded into its lowest and gathered into a byte by one multiplication.
CellRow occupiedBits(const std::uint8_t* cells, int n)
{
    static_assert(std::endian::native == std::endian::little);
    CellRow bits = 0;
    for (int x = 0; x < n; x += 8) {
        std::uint64_t eight = 0;
        std::memcpy(&eight, cells + x, std::size_t(std::min(8, n - x)));
        eight = (eight | (eight >> 1)) & 0x0101010101010101ull; // the states fit two bits
        bits |= CellRow((eight * 0x0102040810204080ull) >> 56) << x;
    }
    return bits;
}

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
    const TriangleAxes axes(a, b, c, kRoundingSlack);
    glm::ivec3 cell;
    for (cell.z = first.z; cell.z <= last.z; ++cell.z)
        for (cell.y = first.y; cell.y <= last.y; ++cell.y)
            for (cell.x = first.x; cell.x <= last.x; ++cell.x) {
                std::uint8_t& state = m_cells[indexOf(cell)];
                if (state == Occupied || !axes.meetsCell(cell))
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
    // A flood over rows of cells along x held as bits: a row that gains open cells fills the whole runs of
    // empty cells they lie in at once, and seeds the four rows beside it with what it gained. On the atrium's
    // 128^3 it takes 1.6-2.0 ms of CPU where the flood along runs of bytes took 9.3-9.9, and that one a sixth
    // of a flood cell by cell (docs/BENCHMARKS.md, "Enclosed space"): the worker shares the two cores with
    // the GL.
    const int n = m_resolution;
    const std::size_t rows = std::size_t(n) * std::size_t(n);
    const CellRow wholeRow = n == 128 ? ~CellRow(0) : (CellRow(1) << n) - 1;
    std::vector<CellRow> empty(rows, 0), open(rows, 0), pending(rows, 0);
    for (std::size_t r = 0; r < rows; ++r)
        empty[r] = ~occupiedBits(m_cells.data() + r * std::size_t(n), n) & wholeRow;
    std::vector<std::size_t> toFill;
    const auto seed = [&](int y, int z, CellRow bits) {
        if (y < 0 || y >= n || z < 0 || z >= n)
            return;
        const std::size_t r = std::size_t(z) * std::size_t(n) + std::size_t(y);
        bits &= empty[r] & ~open[r];
        if (!bits)
            return;
        if (!pending[r])
            toFill.push_back(r);
        pending[r] |= bits;
    };
    const CellRow rowEnds = CellRow(1) | (CellRow(1) << (n - 1));
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            seed(y, z, y == 0 || y == n - 1 || z == 0 || z == n - 1 ? wholeRow : rowEnds);
    while (!toFill.empty()) {
        const std::size_t r = toFill.back();
        toFill.pop_back();
        const CellRow seeds = pending[r] & ~open[r];
        pending[r] = 0;
        if (!seeds)
            continue;
        const CellRow gained = runsHolding(seeds, empty[r]) & ~open[r];
        open[r] |= gained;
        const int y = int(r % std::size_t(n)), z = int(r / std::size_t(n));
        seed(y - 1, z, gained);
        seed(y + 1, z, gained);
        seed(y, z - 1, gained);
        seed(y, z + 1, gained);
    }
    // Only the enclosed cells are written: the open ones, most of a grid, stay as they were (Empty).
    m_enclosedCells = 0;
    for (std::size_t r = 0; r < rows; ++r)
        for (CellRow enclosed = empty[r] & ~open[r]; enclosed; enclosed &= enclosed - 1) {
            const auto low = std::uint64_t(enclosed);
            const int x = low ? std::countr_zero(low) : 64 + std::countr_zero(std::uint64_t(enclosed >> 64));
            m_cells[r * std::size_t(n) + std::size_t(x)] = Enclosed;
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
