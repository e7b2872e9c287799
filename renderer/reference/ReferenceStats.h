#pragma once

#include <cstdint>

namespace vct::render {

/** Work done by a ReferenceRenderer, summed over its completed passes. */
struct ReferenceStats {
    std::uint64_t samples = 0; ///< Camera paths traced (pixels x samples per pixel).
    std::uint64_t rays = 0; ///< Closest-hit and shadow rays.
    std::uint64_t nonFiniteSamples
        = 0; ///< Paths that came out NaN or infinite and were left out of the mean.
    double seconds = 0.0; ///< Wall-clock time inside render().
};

} // namespace vct::render
