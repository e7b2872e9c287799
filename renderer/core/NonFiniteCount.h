#pragma once

#include <cstdint>
#include <string>

namespace vct::render {

/** How many texels of one render target or voxel level hold NaN or Inf. */
struct NonFiniteCount {
    std::string resource; ///< e.g. "final", "g-buffer normal", "radiance level 3"
    std::uint64_t count = 0;
};

} // namespace vct::render
