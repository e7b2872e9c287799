#pragma once

#include "core/BackSideCells.h"
#include "core/ConeTraceKey.h"
#include "core/OccupiedCellList.h"
#include "core/PhaseTimes.h"
#include "core/RenderPass.h"
#include "core/VoxelMipBuilder.h"
#include "gl/Program.h"
#include "gl/Sampler.h"
#include "gl/Texture.h"

#include <cstdint>
#include <vector>

namespace vct::render {

struct VoxelVolume;

/**
 * Every bounce through the voxels (RenderSettings::bounces != 1). Each iteration gathers the diffuse cones
 * once per occupied cell of bounceCellSize^3 voxels from the current iterate (the first-bounce volume to
 * begin with), then sets every occupied voxel to L = L_direct + albedo * (what its cells gathered) in
 * VoxelVolume::bounced and filters that into mips; per-pixel cones trace the result. With bounces = N it runs
 * N - 1 iterations; with `converged` until the relative change and the change still to come (from how fast it
 * shrinks) are both under bounceTolerance, at most kMaxBounces, or, usually sooner, until one reinjection has
 * added the change still to come itself because its estimated error is under the tolerance
 * (bounce/DecideTail.comp, docs/DESIGN.md).
 *
 * With higherBounceCellSize above bounceCellSize the gather is split by what it gathers, as it is linear in
 * the light: the first-bounce light L_direct on the bounce cells, once per solve, and what later iterates add
 * to it on the coarser cells, as their gather of the iterate less their gather of L_direct; a later iteration
 * gathers only the coarse cells (docs/DESIGN.md, "Higher bounces on coarser cells").
 *
 * A camera move reuses it. Renderer::setBounceIterationsPerFrame spreads the iterations over frames for an
 * interactive view, starting each new solve from the last one (a light edit then changes the image smoothly);
 * by default a frame runs every iteration from the first-bounce volume, so a frame is a function of its
 * inputs.
 */
class VoxelBouncePass final : public RenderPass {
public:
    const char* name() const override { return "bounces"; }
    PassDeclaration declare() const override;
    std::vector<TextureSlot> textures(const FrameContext& frame) override;
    PassDecision plan(const FrameContext& frame) const override;
    void execute(FrameContext& frame) override;
    bool redoesWholeGrid(const FrameContext& frame) const override;
    void release(FrameContext& frame) override;
    void invalidate() override { m_radianceVersion = 0; }
    /** The solve's gathers, reinjections and filterings in the frame's run, when the frame asks for them. */
    std::vector<PassStats> nestedStats() const override { return m_phases.read(name()); }

private:
    /** Everything the iteration depends on besides the first-bounce radiance itself. */
    struct SolveKey {
        ConeTraceKey cones;
        int bounces = 0, cellSize = 0, higherCellSize = 0;
        float tolerance = 0.0f, stepScale = 0.0f;
        std::uint64_t materials = 0;
        bool operator==(const SolveKey& other) const = default;
    };
    static SolveKey keyOf(const FrameContext& frame);
    /** Whether the voxels changed since the cells were found (or their textures were made anew). */
    bool cellsOutdated(const VoxelVolume& voxels) const;
    /** Iterations the current setting asks for: bounces - 1, or kMaxBounces when converging. */
    static int iterationLimit(const FrameContext& frame);
    /** Whether the solve gathers the bounces after the second on coarser cells (see the class comment). */
    static bool splitsBounces(const FrameContext& frame);
    /** Makes the first-bounce light the current iterate: the levels cones read filtered from it. */
    void startFromFirstBounce(FrameContext& frame);
    /** Filters the iterate into the levels cones read, timed as a phase; filterMips() untimed. */
    void buildMips(FrameContext& frame);
    void filterMips(FrameContext& frame);
    /** The occupied cells of one size, and whether their normals and sides were found already. */
    struct CellGrid {
        const OccupiedCellList* list = nullptr; ///< the mip builder's list of cells of this size
        int cellSize = 0;
        bool geometryKnown = false;
    };
    /**
     * What else a gather writes: with ShiftIterate (a gather of new first-bounce light into the higher-bounce
     * base), the higher-bounce cells' gather of the iterate moves by what the base changed; with WriteChange
     * (a later gather of the iterate), how much each cell's gather changed goes to the higher-bounce change
     * textures.
     */
    enum class GatherExtra { None, ShiftIterate, WriteChange };
    /**
     * Gathers the diffuse cones over @p grid's cells into @p front and @p back (normals in @p normals), from
     * the first-bounce light (@p fromFirstBounce) or the iterate in `bounced`. With @p sumsIteration >= 0
     * also sums the change from what the cells held (nothing, with @p firstGather) into that iteration's
     * sums; @p extra as GatherExtra says.
     */
    void gather(FrameContext& frame, CellGrid& grid, const gl::Texture& front, const gl::Texture& back,
        const gl::Texture& normals, bool fromFirstBounce, int sumsIteration, bool firstGather,
        GatherExtra extra = GatherExtra::None);
    /**
     * Iteration @p iteration of the solve (from 0): gather the cells from the current iterate, decide whether
     * to add the tail (converging only), reinject, filter; the sums go to the iteration's texels of m_sums.
     * @p compare: the current iterate is in `bounced` (else the first-bounce light is).
     */
    void iterate(FrameContext& frame, bool compare, int iteration);
    /**
     * The same split by splitsBounces(); @p firstOfSolve: this solve's first iteration, which gathers the
     * first-bounce light on both sizes of cells (after the earlier iterate, with @p compare).
     */
    void iterateSplit(FrameContext& frame, bool compare, bool firstOfSolve, int iteration);
    /**
     * How a reinjection finds each voxel's new radiance. FromCleared: the volume is cleared first (its
     * previous iterate is the first-bounce light), L = L_direct + albedo * gathered; FirstBounceOnly: the
     * same when the higher bounces add nothing yet (a cold start's first iteration); OverIterate: the same
     * sum over the iterate in the volume; AddHigherChange: a split solve's later iteration, the iterate plus
     * albedo times what the higher-bounce gather changed by, the same sum for one lookup a voxel.
     */
    enum class Reinjection { FromCleared, FirstBounceOnly, OverIterate, AddHigherChange };
    /** The tail decision (converging only), the reinjection, the filter. */
    void reinject(FrameContext& frame, Reinjection how, int iteration);
    /**
     * One iteration's sums over the occupied voxels, of |change| of the radiance and of the radiance, and the
     * tail its reinjection added (0 for none) with that tail's estimated relative error.
     */
    struct Change {
        double change = 0.0, total = 0.0, tail = 0.0, tailError = -1.0;
    };
    /** The sums of iterations @p first to @p first + @p count - 1 (one readback). */
    std::vector<Change> readChanges(int first, int count);
    /** Takes one iteration's change into the solve's state (m_residual, m_tail, m_done, m_extrapolated). */
    void judge(const Change& change, double tolerance);
    /// Above this ratio between consecutive changes the solve is too slow for its tail to be trusted.
    static constexpr double kLargestRatio = 0.9;
    static constexpr int kBatchIterations = 8; ///< iterations an interactive frame runs between readbacks
    /// The iterations of a split solve (from 0) up to this add their higher bounces' change to the iterate
    /// (Reinjection::AddHigherChange); later ones take the whole sum again.
    static constexpr int kIncrementalIterations = 3;

    CellGrid m_cells; ///< the occupied bounce cells, relisted when the voxels change
    CellGrid m_higherCells; ///< the higher bounces' cells when the solve splits them off
    VoxelMipBuilder m_builder;
    gl::Sampler m_nearestLevel; ///< the gathers' filtering of the volumes they trace (gather())
    gl::Texture m_sums; ///< r32f, one row laid out by bounce/BounceSums.glsl
    BackSideCells m_backSides; ///< the two-sided cells of the gather running, whose back sides go apart
    PhaseTimes m_phases;
    std::uint64_t m_brickLayout = 0; ///< VoxelVolume::brickLayout when the cells were found
    std::uint64_t m_bouncedSerial = 0; ///< the textures m_cells and the builder's lists were found for
    std::uint64_t m_cellsSerial = 0;
    std::uint64_t m_higherCellsSerial = 0; ///< the higher bounces' textures m_higherCells was found for
    std::uint64_t m_radianceVersion = 0; ///< the first-bounce radiance the current solve is for
    std::uint64_t m_listedMaterials = 0; ///< the voxels m_cells and the mip lists were made for
    SolveKey m_key;
    int m_iterations = 0;
    double m_residual = 0.0;
    double m_lastChange = 0.0; ///< the last iteration's sum of |change|
    double m_tail = -1.0; ///< q / (1 - q) as last measured, -1 while unknown
    bool m_done = false;
    bool m_extrapolated = false;
    bool m_stoppedAtLimit = false; ///< ended at the iteration limit short of the tolerance
    /// The bounced volume holds a solve over other voxels (a carried-over start): voxels no longer occupied
    /// must be cleared before the next reinjection.
    bool m_staleVoxels = false;
    VoxelGridFrame m_grid; ///< where the grid was for the last solve
    bool m_coldSolve = false; ///< the current split solve started from the first-bounce light alone
    bool m_baseInPlace = false; ///< the grid has not moved since the higher-bounce base was gathered
    /// Each higher-bounce cell's sums of its surface voxels (normals, positions, count; GatherCells.comp),
    /// added up by the bounce cells' first gather over the voxels.
    gl::Texture m_higherCellSums;
    bool m_cellSumsReady = false; ///< m_higherCellSums holds the sums of the current cells
};

} // namespace vct::render
