#pragma once

#include "core/OccupiedCellList.h"
#include "core/RenderPass.h"
#include "gl/Program.h"

#include <cstdint>
#include <tuple>

namespace vct::render {

/**
 * The irradiance cache (RenderSettings::irradianceCache): every cell of irradianceCellSize^3 voxels that holds a
 * surface traces the diffuse cones from it along its normal (both ways for a wall thinner than a voxel),
 * through the volume the per-pixel cones would see, and stores what they gather (VoxelVolume::irradiance). The cone pass then looks it up per pixel instead of tracing. Runs only when the
 * voxels' light or a gather parameter changed, so a camera move traces no diffuse cones; skipped and its
 * texture released when the cache is off or nothing needs diffuse light.
 */
class VoxelIrradiancePass final : public RenderPass {
public:
    const char* name() const override { return "irradiance cache"; }
    PassDeclaration declare() const override
    {
        return {{Resource::VoxelMaterials, Resource::VoxelMips}, {Resource::VoxelIrradiance}};
    }
    PassDecision plan(const FrameContext& frame) override;
    void execute(FrameContext& frame) override;
    void invalidate() override { m_radianceVersion = 0; }

    /** Whether the cone pass should look diffuse light up in the cache this frame. */
    static bool inUse(const FrameContext& frame);

private:
    /** Everything the gather depends on besides the radiance itself (bounces: which volume it traces). */
    using GatherKey = std::tuple<bool, int, int, float, float, float, float, int, bool, int>;
    static GatherKey keyOf(const FrameContext& frame);
    gl::Program m_programs[2]; ///< [0] box-filtered mips, [1] anisotropic
    OccupiedCellList m_occupied;
    std::uint64_t m_radianceVersion = 0;
    GatherKey m_key{};
};

} // namespace vct::render
