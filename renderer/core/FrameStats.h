#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace vct::render {

/** What one pass did in the last frame. */
struct PassStats {
    std::string name;
    std::string action; ///< "run", "reused" or "skipped"
    std::string reason;
    double gpuMs = 0.0; ///< GL timer query; 0 unless it ran (in the previous frame, see FrameStats).
};

/** Per-frame figures for --stats, the benchmarks and the editor's stats panel. */
struct FrameStats {
    std::vector<PassStats> passes;
    double totalGpuMs = 0.0;
    std::size_t voxelBytes = 0;
    int width = 0, height = 0;
    int voxelResolution = 0;
    float voxelSize = 0.0f; ///< metres
    /// The GPU times are those of the previous frame's passes (Pipeline::TimingReadback::PreviousFrame):
    /// reading this frame's would stall the CPU until the frame is done.
    bool timesFromPreviousFrame = false;
};

} // namespace vct::render
