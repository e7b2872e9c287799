#include "core/Pipeline.h"

#include <algorithm>
#include <stdexcept>

namespace vct::render {

const char* resourceName(Resource resource)
{
    switch (resource) {
    case Resource::ShadowMaps: return "shadow maps";
    case Resource::VoxelMaterials: return "voxel materials";
    case Resource::VoxelRadiance: return "voxel radiance";
    case Resource::VoxelMips: return "voxel mips";
    case Resource::VoxelIrradiance: return "voxel irradiance";
    case Resource::GBuffer: return "G-buffer";
    case Resource::IndirectLight: return "indirect light";
    case Resource::FinalImage: return "final image";
    }
    return "?";
}

Pipeline::Pipeline(std::vector<std::unique_ptr<RenderPass>> passes)
    : m_passes(std::move(passes))
{
    std::vector<Resource> written;
    for (const auto& pass : m_passes) {
        const PassDeclaration declaration = pass->declare();
        for (Resource r : declaration.reads)
            if (std::find(written.begin(), written.end(), r) == written.end())
                throw std::logic_error(std::string("pass ") + pass->name() + " reads " + resourceName(r)
                    + " before any pass writes it");
        written.insert(written.end(), declaration.writes.begin(), declaration.writes.end());
        m_timers.push_back(gl::TimerQuery::create());
    }
}

FrameStats Pipeline::execute(FrameContext& frame)
{
    FrameStats stats;
    std::vector<bool> ran(m_passes.size(), false);
    for (std::size_t i = 0; i < m_passes.size(); ++i) {
        RenderPass& pass = *m_passes[i];
        const PassDecision decision = pass.plan(frame);
        PassStats entry{pass.name(), "run", decision.reason, 0.0};
        if (decision.action == PassDecision::Action::Run) {
            m_timers[i].begin();
            pass.execute(frame);
            m_timers[i].end();
            ran[i] = true;
        } else {
            entry.action = decision.action == PassDecision::Action::Reuse ? "reused" : "skipped";
        }
        stats.passes.push_back(entry);
    }
    for (std::size_t i = 0; i < m_passes.size(); ++i)
        if (ran[i]) {
            stats.passes[i].gpuMs = m_timers[i].elapsedMs();
            stats.totalGpuMs += stats.passes[i].gpuMs;
        }
    return stats;
}

void Pipeline::invalidate()
{
    for (auto& pass : m_passes)
        pass->invalidate();
}

} // namespace vct::render
