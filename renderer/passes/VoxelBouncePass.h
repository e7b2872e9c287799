#pragma once

#include "core/ConeTraceKey.h"
#include "core/OccupiedCellList.h"
#include "core/RenderPass.h"
#include "core/VoxelMipBuilder.h"
#include "gl/Program.h"
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
 * shrinks) are both under bounceTolerance, at most kMaxBounces.
 *
 * A camera move reuses it. Renderer::setBounceIterationsPerFrame spreads the iterations over frames for an
 * interactive view, starting each new solve from the last one (a light edit then changes the image smoothly);
 * by default a frame runs every iteration from the first-bounce volume, so a frame is a function of its
 * inputs.
 */
class VoxelBouncePass final : public RenderPass {
public:
    const char* name() const override { return "bounces"; }
    PassDeclaration declare() const override
    {
        return { { Resource::VoxelMaterials, Resource::VoxelMips }, { Resource::VoxelMips } };
    }
    PassDecision plan(const FrameContext& frame) override;
    void execute(FrameContext& frame) override;
    void invalidate() override { m_radianceVersion = 0; }

private:
    /** Everything the iteration depends on besides the first-bounce radiance itself. */
    struct SolveKey {
        ConeTraceKey cones;
        int bounces = 0, cellSize = 0;
        float tolerance = 0.0f;
        std::uint64_t materials = 0;
        bool operator==(const SolveKey& other) const = default;
    };
    static SolveKey keyOf(const FrameContext& frame);
    /** Iterations the current setting asks for: bounces - 1, or kMaxBounces when converging. */
    static int iterationLimit(const FrameContext& frame);
    void allocate(VoxelVolume& v, int cells, int levels);
    /** Makes the first-bounce light the current iterate: level 0 copied, the levels cones read filtered. */
    void startFromFirstBounce(FrameContext& frame);
    void buildMips(FrameContext& frame);
    /**
     * One iteration: gather the cells from the current iterate, reinject, filter; with @p compare, the
     * residual's sums go to texel pair @p slot of m_residualSums.
     */
    void iterate(FrameContext& frame, bool compare, int slot);
    /** The residuals of the first @p count slots: sum of |change| over sum of radiance (one readback). */
    std::vector<double> readResiduals(int count);
    static constexpr int kResidualSlots = 8; ///< iterations whose residuals one readback collects

    const gl::Program* m_reinject = nullptr;
    OccupiedCellList m_cells; ///< the occupied bounce cells, relisted when the voxels change
    VoxelMipBuilder m_builder;
    gl::Texture m_residualSums; ///< r32f, 2 x kResidualSlots: per iteration, sum of |change| and of radiance
    std::uint64_t m_radianceVersion = 0; ///< the first-bounce radiance the current solve is for
    std::uint64_t m_listedMaterials = 0; ///< the voxels m_cells and the mip lists were made for
    SolveKey m_key;
    int m_iterations = 0;
    double m_residual = 0.0, m_previousResidual = 0.0;
    bool m_done = false;
};

} // namespace vct::render
