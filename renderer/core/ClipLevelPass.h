#pragma once

#include "core/FrameResources.h"
#include "core/Pipeline.h"
#include "core/RenderPass.h"

#include <memory>
#include <string>
#include <vector>

namespace vct::render {

/**
 * One coarser level of a clipmap (RenderSettings::voxelMode): a voxel grid of its own, placed by
 * core/ClipmapLayout around the camera, with its own voxelize, inject, mip and bounce passes in a pipeline of
 * their own (their textures in its own resource table, names unprefixed; Renderer::describeVoxelMemory
 * prefixes them). The frame's pipeline runs the levels coarsest first, after the shadow maps and before the
 * finest level's passes, so that every level's bounce gather can go on into the solved levels around it; a
 * level whose grid did not move and whose light did not change reuses everything.
 */
class ClipLevelPass final : public RenderPass {
public:
    /** Level @p level (1 = next to the finest) of a clipmap; @p coarser: the levels around it, finest first.
     */
    ClipLevelPass(int level, std::vector<const VoxelVolume*> coarser);

    const char* name() const override { return m_name.c_str(); }
    PassDeclaration declare() const override;
    PassDecision plan(const FrameContext& frame) const override;
    void execute(FrameContext& frame) override;
    void invalidate() override { m_pipeline->invalidate(); }
    bool timedByPipeline() const override { return false; }
    double gpuMsOfLastRun() const override { return m_lastStats.totalGpuMs; }
    std::vector<PassStats> nestedStats() const override;

    int level() const { return m_level; }
    const VoxelVolume& volume() const { return m_volume; }
    VoxelVolume& volume() { return m_volume; }
    Pipeline& pipeline() { return *m_pipeline; }
    const Pipeline& pipeline() const { return *m_pipeline; }

private:
    int m_level;
    std::string m_name;
    VoxelVolume m_volume;
    std::vector<const VoxelVolume*> m_coarser;
    std::unique_ptr<Pipeline> m_pipeline;
    FrameStats m_lastStats;
};

} // namespace vct::render
