#include "core/ClipLevelPass.h"

#include "core/ClipmapLayout.h"
#include "core/FrameContext.h"
#include "core/ResourceNames.h"
#include "passes/InjectLightPass.h"
#include "passes/MipmapPass.h"
#include "passes/VoxelBouncePass.h"
#include "passes/VoxelizePass.h"
#include "scene/VoxelTextureEstimate.h"

namespace vct::render {

ClipLevelPass::ClipLevelPass(int level, std::vector<const VoxelVolume*> coarser)
    : m_level(level)
    , m_name(clipLevelName(level, "voxels"))
    , m_coarser(std::move(coarser))
{
    std::vector<std::unique_ptr<RenderPass>> passes;
    passes.push_back(std::make_unique<VoxelizePass>());
    passes.push_back(std::make_unique<InjectLightPass>());
    passes.push_back(std::make_unique<MipmapPass>());
    passes.push_back(std::make_unique<VoxelBouncePass>());
    m_pipeline = std::make_unique<Pipeline>(std::move(passes),
        std::vector<std::string> {
            resource::kPointShadows, resource::kDirectionalShadows, resource::kEnclosure });
}

PassDeclaration ClipLevelPass::declare() const
{
    // Injection reads the shadow maps the frame's pipeline made before, the bounce gathers its enclosed
    // space.
    return { { resource::kPointShadows, resource::kDirectionalShadows, resource::kEnclosure }, {} };
}

PassDecision ClipLevelPass::plan(const FrameContext& frame) const
{
    (void)frame;
    return { PassDecision::Action::Run, "its own passes decide (listed after the frame's)" };
}

void ClipLevelPass::execute(FrameContext& frame)
{
    m_volume.frame
        = ClipmapLayout::level(frame.sceneGrid, frame.settings.gridLevels(), m_level, frame.camera.position);
    FrameContext level { frame.shaders, frame.scene, frame.settings, frame.versions, m_volume, frame.shadows,
        frame.screen, frame.diffuseCones, frame.staticMaterialEdits, frame.camera, frame.view,
        frame.projection, frame.pixelToRay, nullptr, frame.bounceIterationsPerFrame, FrameShape {},
        &m_pipeline->resources(), frame.sceneGrid, m_coarser };
    level.enclosure = frame.enclosure;
    level.phaseTimes = frame.phaseTimes;
    level.shape = FrameShape::of(level);
    m_lastStats = m_pipeline->execute(level);
}

std::vector<PassStats> ClipLevelPass::nestedStats() const
{
    std::vector<PassStats> stats = m_lastStats.passes;
    for (PassStats& pass : stats)
        pass.name = clipLevelName(m_level, pass.name);
    return stats;
}

} // namespace vct::render
