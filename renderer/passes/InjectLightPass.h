#pragma once

#include "core/OccupiedCellList.h"
#include "core/RenderPass.h"
#include "core/VoxelGridFrame.h"
#include "core/VoxelRegion.h"
#include "gl/Program.h"

#include <array>
#include <cstdint>
#include <map>
#include <tuple>
#include <utility>
#include <vector>

namespace vct::render {

/**
 * Writes level 0 of the radiance volume: shadowed direct light reflected by each voxel, plus emission. Two
 * dispatches: one over the region lists its occupied voxels and clears the rest, the lighting one runs over
 * that list only (an indirect dispatch, so the count never comes back to the CPU).
 */
class InjectLightPass final : public RenderPass {
public:
    const char* name() const override { return "inject light"; }
    PassDeclaration declare() const override;
    std::vector<TextureSlot> textures(const FrameContext& frame) override;
    PassDecision plan(const FrameContext& frame) const override;
    void execute(FrameContext& frame) override;
    bool redoesWholeGrid(const FrameContext& frame) const override;
    void invalidate() override
    {
        m_key = {};
        m_radianceSerial = 0;
    }

private:
    /** The versions the injected light depends on; all zero before the first injection. */
    struct LightKey {
        std::uint64_t materials = 0; ///< VoxelVolume::materialsVersion
        std::uint64_t lightValues = 0;
        bool direct = false; ///< the settings that change what is injected
        bool emission = false;
        int shadowMapSize = 0; ///< every shadow lookup changes with it
        std::uint64_t shadowMaps = 0;
        std::uint64_t areaLights = 0;
        bool operator==(const LightKey& other) const = default;
    };
    static LightKey keyOf(const FrameContext& frame);
    /** The voxels whose light can differ from the last injection: the whole grid, or (the voxelizer redid
     * regions only) those regions and the shadows of a moved object. */
    std::vector<VoxelRegion> regionsToInject(const FrameContext& frame) const;
    /** The light injected before can move with the grid (VoxelVolume::shiftedBy) and be kept. */
    bool keepsMovedLight(const FrameContext& frame) const;
    /** Level 0 of VoxelVolume::opacity from the occupied voxels, and its mips, when the voxels changed. */
    void buildOpacity(FrameContext& frame);
    const gl::Program* m_markOpacity = nullptr;
    const gl::Program* m_downsampleOpacity = nullptr;
    OccupiedCellList m_occupied;
    LightKey m_key;
    std::uint64_t m_opacitySerial = 0; ///< the opacity texture last built (with VoxelVolume::opacityVersion)
    std::uint64_t m_radianceSerial = 0; ///< the radiance texture last injected into
    VoxelGridFrame m_grid; ///< where the grid was at the last injection
};

} // namespace vct::render
