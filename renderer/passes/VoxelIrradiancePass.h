#pragma once

#include "core/BackSideCells.h"
#include "core/ConeTraceKey.h"
#include "core/OccupiedCellList.h"
#include "core/RenderPass.h"
#include "core/VoxelGridFrame.h"
#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/VertexArray.h"

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <vector>

namespace vct::render {

struct VoxelVolume;

/**
 * The irradiance cache (RenderSettings::irradianceCache): cells of irradianceCellSize^3 voxels that hold a
 * surface trace the diffuse cones from it along its normal (both ways for a wall thinner than a voxel),
 * through the volume the per-pixel cones would see, and store what they gather (VoxelVolume::irradiance); the
 * cone pass then looks it up per pixel instead of tracing.
 *
 * Only the cells this frame's lookups read are gathered: a pass over the traced pixels requests the eight
 * cells around each one, and the gather runs over the cells requested for the first time since the voxel
 * light changed. A frame after a light or voxel change gathers what the camera sees, not the whole scene; a
 * camera move gathers only the cells that came into view; an unchanged view reuses everything. The image is
 * the one a gather over every cell would give, since no lookup reads a cell that was not requested.
 * Skipped and its textures released when the cache is off or nothing needs diffuse light.
 */
class VoxelIrradiancePass final : public RenderPass {
public:
    const char* name() const override { return "irradiance cache"; }
    PassDeclaration declare() const override;
    std::vector<TextureSlot> textures(const FrameContext& frame) override;
    PassDecision plan(const FrameContext& frame) const override;
    void execute(FrameContext& frame) override;
    void release(FrameContext& frame) override;
    void invalidate() override { m_radianceVersion = 0; }

private:
    /** Everything the gather depends on besides the radiance itself (bounces: which volume it traces). */
    struct GatherKey {
        ConeTraceKey cones;
        int bounces = 0; ///< which volume the cones trace (the bounced one, or the first-bounce light)
        bool ambientOcclusion = false;
        int cellSize = 0;
        VoxelGridFrame grid; ///< where the cells are: a clipmap's finest level follows the camera
        bool operator==(const GatherKey& other) const = default;
    };
    static GatherKey keyOf(const FrameContext& frame);
    /** What decides which cells the traced pixels look up: the camera, the pixel grids and the geometry. */
    struct ViewKey {
        glm::mat4 viewProjection { 0.0f };
        int width = 0, height = 0, divisor = 0;
        std::uint64_t staticGeometry = 0, dynamicGeometry = 0;
        bool operator==(const ViewKey& other) const = default;
    };
    static ViewKey viewOf(const FrameContext& frame);
    /** Fresh textures, nothing gathered: after the voxel light or a gather setting changed. */
    void forgetCells(VoxelVolume& voxels);
    /**
     * Lists the cells the traced pixels look up that hold voxels and were not gathered yet; @p fewNew after a
     * camera move (the pixels list the new cells themselves), otherwise in grid order over every cell.
     */
    void requestCells(FrameContext& frame, int cells, int cellVoxels, bool fewNew);

    gl::Framebuffer m_requestTarget; ///< no attachments, the traced pixels' size
    int m_requestWidth = 0, m_requestHeight = 0;
    gl::VertexArray m_emptyVao;
    OccupiedCellList m_newCells; ///< listed by the request pass after a camera move
    OccupiedCellList m_requested; ///< the cells to gather
    BackSideCells m_backSides; ///< the two-sided ones among them, whose back sides are gathered apart
    std::uint64_t m_radianceVersion = 0;
    std::uint64_t m_cellsSerial = 0; ///< the cache texture last cleared (a new one must be cleared)
    std::uint64_t m_bouncedVersion = 0;
    GatherKey m_key {};
    ViewKey m_view;
};

} // namespace vct::render
