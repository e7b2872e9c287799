#pragma once

#include <cstdint>

namespace vct::render {

/**
 * PCG32 (O'Neill, pcg-random.org, XSH RR variant): small, fast and good enough for Monte Carlo. A generator
 * is seeded from (seed, stream) alone, so a pixel's samples do not depend on which thread draws them.
 */
class Pcg32 {
public:
    Pcg32(std::uint64_t seed, std::uint64_t stream)
        : m_increment((stream << 1u) | 1u)
    {
        nextUint();
        m_state += seed;
        nextUint();
    }

    std::uint32_t nextUint()
    {
        const std::uint64_t old = m_state;
        m_state = old * 6364136223846793005ull + m_increment;
        const auto xorShifted = std::uint32_t(((old >> 18u) ^ old) >> 27u);
        const auto rotation = std::uint32_t(old >> 59u);
        return (xorShifted >> rotation) | (xorShifted << ((32u - rotation) & 31u));
    }

    /** Uniform in [0, 1): 24 random bits, so the result never rounds up to 1. */
    float nextFloat() { return float(nextUint() >> 8) * 0x1p-24f; }

private:
    std::uint64_t m_state = 0;
    std::uint64_t m_increment;
};

} // namespace vct::render
