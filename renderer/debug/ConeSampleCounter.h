#pragma once

#include "gl/Buffer.h"

#include <cstdint>

namespace vct::render {

/**
 * Counts the 3D texture fetches of the cone pass's COUNT_SAMPLES shader variant (vct-bench perf): a 64-bit
 * count kept as two 32-bit words (low, high) in a shader storage buffer, since GLSL 4.50 has no 64-bit
 * atomics. The variant is slower than the timed one, so frames drawn while counting are not timed.
 */
class ConeSampleCounter {
public:
    /** The SSBO binding the shader declares for the count (shaders/cone/ConeSampleCount.glsl). */
    static constexpr unsigned kBinding = 0;

    ConeSampleCounter();
    void reset();
    void bind() const;
    /** Waits for the GPU's writes and returns the count since the last reset(). */
    std::uint64_t read() const;

private:
    gl::Buffer m_buffer;
};

} // namespace vct::render
