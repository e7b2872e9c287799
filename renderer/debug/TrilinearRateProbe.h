#pragma once

#include <cstdint>
#include <memory>

namespace vct::render {

/** What one TrilinearRateProbe::measure call found. */
struct TrilinearRate {
    double samplesPerSecond = 0.0; ///< from the median draw time
    double medianMs = 0.0; ///< GPU ms of one draw (timestamp queries), median over the repeats
    std::uint64_t samplesPerDraw = 0;
    int width = 0, height = 0; ///< pixels drawn
    int volumeSize = 0; ///< texels per side of level 0
    int samplesPerPixel = 0;
};

/**
 * Measures the peak rate of trilinear, mip-interpolated 3D texture samples (textureLod on an RGBA16F volume
 * with a full mip chain, the format and filter of the voxel radiance) on the current context: the practical
 * limit of the cone pass on llvmpipe, where every sample is CPU work. A full-screen draw takes a fixed number
 * of coherent samples per pixel, timed with GL timestamps. Needs the context current and GL loaded (a
 * Renderer created on it); owns its GL objects.
 */
class TrilinearRateProbe {
public:
    TrilinearRateProbe();
    ~TrilinearRateProbe();
    TrilinearRateProbe(const TrilinearRateProbe&) = delete;
    TrilinearRateProbe& operator=(const TrilinearRateProbe&) = delete;

    /**
     * Draws `repeats` timed passes (after one untimed draw that compiles the shader) over width x height
     * pixels, sampling a volumeSize^3 texture (power of two); rays x steps samples per pixel.
     */
    TrilinearRate measure(
        int width, int height, int volumeSize, int repeats = 3, int rays = 6, int steps = 16);

private:
    struct State;
    std::unique_ptr<State> m_state;
};

} // namespace vct::render
