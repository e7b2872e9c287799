#pragma once

#include "core/OccupiedCellList.h"

#include <cstddef>
#include <string>
#include <vector>

namespace vct::render {

/**
 * The two-sided cells of a gather over cells (irradiance/GatherCells.comp), whose back sides a second
 * dispatch of the same shader gathers apart (BACK_SIDES). Gathered in the same invocation, a back side cost
 * every cell of a work group where one cell had one: llvmpipe runs a loop's body for all lanes while any lane
 * needs it. The first dispatch lists the cells here; one that finds the list full gathers its back side in
 * place, so nothing is lost at any size (docs/BENCHMARKS.md, "Back sides gathered apart").
 */
class BackSideCells {
public:
    /** Most cells listed: 4 MiB of list, however large the grid. */
    static constexpr std::size_t kMaxCells = std::size_t(1) << 20;

    /**
     * Empties the list and binds it (storage buffers 2 and 3) for @p gather, the first dispatch, to fill; a
     * grid of @p cells cells has room for all of them up to kMaxCells.
     */
    void bindForGather(const gl::Program& gather, std::size_t cells);
    /** The second dispatch's defines, from the first's: the back sides, of cells whose geometry it wrote. */
    static std::vector<std::string> backSideDefines(std::vector<std::string> defines);
    /** Runs the second dispatch (its program in use, set up as the first) over the listed cells. */
    void dispatch() const { m_list.dispatchOverCells(); }

private:
    OccupiedCellList m_list;
};

} // namespace vct::render
