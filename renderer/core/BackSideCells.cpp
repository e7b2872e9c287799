#include "core/BackSideCells.h"

#include <algorithm>

namespace vct::render {

void BackSideCells::bindForGather(const gl::Program& gather, std::size_t cells)
{
    const std::size_t capacity = std::max<std::size_t>(std::min(cells, kMaxCells), 1);
    m_list.reset(capacity, 2);
    gather.set("uGroupSize", OccupiedCellList::kGroupSize);
    gather.set("uBackSideCapacity", unsigned(capacity));
}

std::vector<std::string> BackSideCells::backSideDefines(std::vector<std::string> defines)
{
    if (std::find(defines.begin(), defines.end(), "CACHED_GEOMETRY") == defines.end())
        defines.emplace_back("CACHED_GEOMETRY");
    defines.emplace_back("BACK_SIDES");
    return defines;
}

} // namespace vct::render
