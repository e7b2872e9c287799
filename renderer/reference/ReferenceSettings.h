#pragma once

#include <cstdint>
#include <thread>

namespace vct::render {

/** How the reference path tracer samples; everything but maxBounces leaves the estimate unbiased. */
struct ReferenceSettings {
    /// Longest path, in reflections: 0 shows emitters only, 1 adds direct light, and so on. The only bias:
    /// Russian roulette ends paths without bias, so the cap only needs to be beyond where it matters.
    int maxBounces = 64;
    /// Russian roulette starts after this many reflections; before it, every path continues.
    int rouletteStartBounce = 3;
    std::uint64_t seed = 0; ///< Same seed, scene and sample count: bit-identical image on any thread count.
    int threads = int(std::thread::hardware_concurrency()); ///< Worker threads; values below 1 mean 1.
    int tileSize = 16; ///< Pixels per tile side; threads pull tiles from a shared counter.
};

} // namespace vct::render
