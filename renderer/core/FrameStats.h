#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace vct::render {

/** What one pass did in the last frame. */
struct PassStats {
    std::string name;
    /// "run", "reused", "skipped", or "deferred" (staged frames: it runs in the next frame)
    std::string action;
    std::string reason;
    double gpuMs = 0.0; ///< GL timer query; 0 unless it ran (in the previous frame, see FrameStats).
};

/** Per-frame figures for --stats, the benchmarks and the editor's stats panel. */
struct FrameStats {
    /** Voxel memory over the grids' cells (resolution^3 each), and over the cells holding a surface. */
    double voxelBytesPerCell() const
    {
        const double cells = double(voxelResolution) * double(voxelResolution) * double(voxelResolution)
            * double(gridLevels);
        return cells > 0.0 ? double(voxelBytes) / cells : 0.0;
    }
    double voxelBytesPerOccupiedVoxel() const
    {
        return occupiedVoxels > 0 ? double(voxelBytes) / double(occupiedVoxels) : 0.0;
    }

    std::vector<PassStats> passes;
    double totalGpuMs = 0.0;
    std::size_t voxelBytes = 0;
    std::size_t occupiedVoxels = 0; ///< voxels holding a surface, in every level of a clipmap
    int width = 0, height = 0;
    int voxelResolution = 0;
    int gridLevels = 1; ///< a clipmap's levels (RenderSettings::voxelMode), else 1
    /// voxel_mode=sparse: the bricks of 8^3 voxels its pools store, of how many the grid has; 0 otherwise.
    std::size_t storedBricks = 0;
    std::size_t gridBricks = 0;
    float voxelSize = 0.0f; ///< metres
    /// The GPU times are those of the previous frame's passes (Pipeline::TimingReadback::PreviousFrame):
    /// reading this frame's would stall the CPU until the frame is done.
    bool timesFromPreviousFrame = false;
    /// The bounce iteration (bounces != 1): iterations run for the current light, the relative change of the
    /// last one, and whether more are to come in later frames (Renderer::setBounceIterationsPerFrame).
    int bounceIterations = 0;
    double bounceResidual = 0.0;
    bool lightConverged = true;
    bool bounceExtrapolated = false; ///< the geometric tail was added (bounceResidual is then its error)
    /// The solve ended at its iteration limit short of its tolerance (BounceProgress::stoppedAtLimit), in any
    /// grid of a clipmap.
    bool bounceStoppedAtLimit = false;
    /// Cells of the enclosed-space map (passes/EnclosurePass) no light can leave, and the map's cells: the
    /// diffuse gathers starting in them count what walls let through as the walls' light. 0 of 0 when off.
    std::size_t enclosedCells = 0;
    std::size_t enclosureCells = 0;
    /// Staged frames (Renderer::setStagedRebuilds): passes were deferred to the next frame, so the final
    /// image is still the last complete one; render again to go on.
    bool deferred = false;
};

} // namespace vct::render
