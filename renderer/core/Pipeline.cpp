#include "core/Pipeline.h"

#include <algorithm>
#include <stdexcept>

namespace vct::render {

Pipeline::Pipeline(std::vector<std::unique_ptr<RenderPass>> passes, std::vector<std::string> given)
    : m_passes(std::move(passes))
{
    std::vector<std::string> written = std::move(given);
    for (const auto& pass : m_passes) {
        const PassDeclaration declaration = pass->declare();
        for (const std::string& r : declaration.reads)
            if (std::find(written.begin(), written.end(), r) == written.end())
                throw std::logic_error(
                    std::string("pass ") + pass->name() + " reads " + r + " before any pass writes it");
        written.insert(written.end(), declaration.writes.begin(), declaration.writes.end());
        for (auto& set : m_timers)
            set.push_back(gl::TimerQuery::create());
    }
    m_ranLastFrame.assign(m_passes.size(), false);
}

void Pipeline::setTimingReadback(TimingReadback readback)
{
    m_readback = readback;
    m_ranLastFrame.assign(m_passes.size(), false);
}

FrameStats Pipeline::execute(FrameContext& frame)
{
    FrameStats stats;
    std::vector<bool> ran(m_passes.size(), false);
    std::vector<gl::TimerQuery>& timers = m_timers[m_currentSet];
    bool wholeGridRedone = false, endAfter = false;
    std::vector<PassStats> nestedStats;
    for (std::size_t i = 0; i < m_passes.size(); ++i) {
        RenderPass& pass = *m_passes[i];
        if (stats.deferred) {
            stats.passes.push_back(
                { pass.name(), "deferred", "a staged rebuild goes on in the next frame", 0.0 });
            continue;
        }
        PassDecision decision = pass.plan(frame);
        if (m_staged && decision.action == PassDecision::Action::Run && pass.redoesWholeGrid(frame)) {
            if (wholeGridRedone) {
                stats.deferred = true;
                stats.passes.push_back({ pass.name(), "deferred",
                    "staged rebuild: the grid was already redone whole this frame", 0.0 });
                continue;
            }
            wholeGridRedone = true;
            // While a rebuild goes on each whole-grid step gets a frame of its own, the screen passes too.
            endAfter = m_rebuilding;
        }
        if (prepareTextures(pass, frame) && decision.action != PassDecision::Action::Skip) {
            // Its output went with the old textures.
            pass.invalidate();
            if (decision.action == PassDecision::Action::Reuse)
                decision = { PassDecision::Action::Run, "its textures were made anew" };
        }
        PassStats entry { pass.name(), "run", decision.reason, 0.0 };
        if (decision.action == PassDecision::Action::Run) {
            if (pass.timedByPipeline())
                timers[i].begin();
            pass.execute(frame);
            if (pass.timedByPipeline()) {
                timers[i].end();
                ran[i] = true;
            } else {
                entry.gpuMs = pass.gpuMsOfLastRun();
                stats.totalGpuMs += entry.gpuMs;
                for (const PassStats& nested : pass.nestedStats())
                    nestedStats.push_back(nested);
            }
        } else if (decision.action == PassDecision::Action::Reuse) {
            entry.action = "reused";
        } else {
            entry.action = "skipped";
            pass.release(frame);
        }
        stats.passes.push_back(entry);
        if (endAfter)
            stats.deferred = i + 1 < m_passes.size();
        endAfter = false;
    }
    m_rebuilding = stats.deferred;
    const bool previous = m_readback == TimingReadback::PreviousFrame;
    // The previous frame's queries finished with it, so reading them does not wait for this frame's work.
    const std::vector<gl::TimerQuery>& results = previous ? m_timers[1 - m_currentSet] : timers;
    const std::vector<bool>& measured = previous ? m_ranLastFrame : ran;
    for (std::size_t i = 0; i < m_passes.size(); ++i)
        if (measured[i]) {
            stats.passes[i].gpuMs = results[i].elapsedMs();
            stats.totalGpuMs += stats.passes[i].gpuMs;
        }
    stats.timesFromPreviousFrame = previous;
    // After the timings, which are indexed by pass: the nested passes' and the phases of those that time them
    // (core/PhaseTimes), which are parts of their pass's time, not added to the frame's again.
    stats.passes.insert(stats.passes.end(), nestedStats.begin(), nestedStats.end());
    for (std::size_t i = 0; i < m_passes.size(); ++i)
        if (ran[i])
            for (const PassStats& phase : m_passes[i]->nestedStats())
                stats.passes.push_back(phase);
    if (previous) {
        m_ranLastFrame = ran;
        m_currentSet = 1 - m_currentSet;
    }
    return stats;
}

bool Pipeline::prepareTextures(RenderPass& pass, const FrameContext& frame)
{
    const std::vector<TextureSlot> slots = pass.textures(frame);
    // Names are checked against the declaration when the table first sees them: a pass lists the same slots
    // every frame.
    for (const TextureSlot& slot : slots) {
        if (m_resources.find(slot.name))
            continue;
        const std::vector<std::string> writes = pass.declare().writes;
        if (std::find(writes.begin(), writes.end(), slot.name) == writes.end())
            throw std::logic_error(
                std::string("pass ") + pass.name() + " makes " + slot.name + " but does not declare it");
    }
    return m_resources.apply(pass.name(), slots);
}

void Pipeline::invalidate()
{
    for (auto& pass : m_passes)
        pass->invalidate();
}

} // namespace vct::render
