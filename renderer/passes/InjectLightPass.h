#pragma once

#include "core/OccupiedCellList.h"
#include "core/RenderPass.h"
#include "core/VoxelRegion.h"
#include "gl/Program.h"

#include <array>
#include <cstdint>
#include <map>
#include <tuple>
#include <utility>

namespace vct::render {

/**
 * Writes level 0 of the radiance volume: shadowed direct light reflected by each voxel, plus emission. Two
 * dispatches: one over the region lists its occupied voxels and clears the rest, the lighting one runs over
 * that list only (an indirect dispatch, so the count never comes back to the CPU).
 */
class InjectLightPass final : public RenderPass {
public:
    const char* name() const override { return "inject light"; }
    PassDeclaration declare() const override
    {
        return { { Resource::VoxelMaterials, Resource::ShadowMaps }, { Resource::VoxelRadiance } };
    }
    PassDecision plan(const FrameContext& frame) override;
    void execute(FrameContext& frame) override;
    void invalidate() override { m_key = {}; }

private:
    std::array<std::uint64_t, 5> keyOf(const FrameContext& frame) const;
    /** The voxels whose light can differ from the last injection (the whole grid unless only a dynamic object
     * moved). */
    VoxelRegion regionToInject(const FrameContext& frame) const;
    /** Level 0 of VoxelVolume::opacity from the occupied voxels, and its mips, when the voxels changed. */
    void buildOpacity(FrameContext& frame);
    const gl::Program* m_markOpacity = nullptr;
    const gl::Program* m_downsampleOpacity = nullptr;
    OccupiedCellList m_occupied;
    std::array<std::uint64_t, 5> m_key {};
};

} // namespace vct::render
