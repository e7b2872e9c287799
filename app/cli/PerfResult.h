#pragma once

#include "core/VoxelTextureMemory.h"
#include "debug/TrilinearRateProbe.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace vct::cli {

/** Which scaling curve a configuration is a point of (bits; one configuration can serve several). */
enum PerfSweep : unsigned { kSizeSweep = 1u, kGridSweep = 2u, kTriangleSweep = 4u };

/** One configuration of `vct-bench perf`. */
struct PerfConfig {
    int width = 0, height = 0; ///< output pixels
    int grid = 0; ///< voxel grid cells per side (per level of a clipmap)
    int triangleFactor = 1; ///< every triangle of the scene split into this many
    unsigned sweeps = 0; ///< PerfSweep bits
};

/** The median and the range of one figure over the timed frames, milliseconds. */
struct TimingSpread {
    double median = 0.0;
    double min = 0.0;
    double max = 0.0;
};

/** One pass over the timed frames: GPU ms (0 in frames where it was reused or skipped). */
struct PassTiming {
    std::string pass;
    std::string action; ///< of the last timed frame: "run", "reused" or "skipped"
    TimingSpread ms;
};

/** Every pass and the whole frame, over the timed frames of one mode. */
struct ModeTiming {
    std::vector<PassTiming> passes;
    TimingSpread frameGpuMs; ///< sum of the passes' timestamp intervals
    TimingSpread frameWallMs; ///< Renderer::renderFrame on the CPU clock, timer readback included
};

/** Everything measured for one configuration. */
struct PerfResult {
    PerfConfig config;
    int gridLevels = 1; ///< grids the voxels take: a clipmap's levels, else 1
    std::size_t triangles = 0;
    int frames = 0; ///< timed frames per mode
    ModeTiming full; ///< every pass re-run (Renderer::invalidate() before each frame)
    ModeTiming cameraOnly; ///< only the camera moves: the render plan reuses voxels, injection and mips
    std::vector<render::VoxelTextureMemory> memory;
    std::size_t occupiedVoxels = 0; ///< voxels holding a surface
    std::uint64_t coneSamples
        = 0; ///< 3D texture fetches of the cone pass in one frame (separate, untimed run)
    double coneMs = 0.0; ///< cone pass median GPU ms of the full frames
    int tracedWidth = 0, tracedHeight = 0; ///< pixels the cone pass draws (output / indirect divisor)
    render::TrilinearRate peak; ///< the probe at the cone pass's size and this grid

    double coneSamplesPerSecond() const { return coneMs > 0.0 ? double(coneSamples) / (coneMs * 1e-3) : 0.0; }
    /** Cone-pass sampling rate as a share of the probe's peak; 0 when either is unknown. */
    double coneEfficiency() const
    {
        return peak.samplesPerSecond > 0.0 ? coneSamplesPerSecond() / peak.samplesPerSecond : 0.0;
    }
    std::size_t voxelBytes() const
    {
        std::size_t total = 0;
        for (const render::VoxelTextureMemory& m : memory)
            total += m.totalBytes();
        return total;
    }
    /** What GL reports for the same textures (VoxelTextureMemory::glBytes). */
    std::size_t glVoxelBytes() const
    {
        std::size_t total = 0;
        for (const render::VoxelTextureMemory& m : memory)
            total += m.glBytes;
        return total;
    }
};

} // namespace vct::cli
