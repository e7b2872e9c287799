#pragma once

#include "core/FrameStats.h"
#include "core/RenderPass.h"
#include "core/ResourceTable.h"
#include "gl/TimerQuery.h"

#include <memory>
#include <string>
#include <vector>

namespace vct::render {

/** Runs passes in order, each inside a GL timer query, and applies their run/reuse/skip decisions. */
class Pipeline {
public:
    /** When a frame's timer results are read. */
    enum class TimingReadback {
        ThisFrame, ///< execute() waits for them: exact per-frame figures (command lines, benchmarks, tests)
        PreviousFrame, ///< execute() reports the frame before, whose results are in: no stall (the editor)
    };

    /**
     * Throws std::logic_error when a pass reads a resource no earlier pass writes, nor @p given (written
     * before this pipeline runs: a clip level's reads the frame's shadow maps).
     */
    explicit Pipeline(std::vector<std::unique_ptr<RenderPass>> passes, std::vector<std::string> given = {});

    /** Runs one frame and returns its decisions, with GPU times as setTimingReadback() says. */
    FrameStats execute(FrameContext& frame);
    void setTimingReadback(TimingReadback readback);
    /**
     * With staged rebuilds a frame ends before the second pass that would redo the whole voxel grid
     * (RenderPass::redoesWholeGrid): that pass and the ones after it run in the next frame, and the final
     * image stays the last complete one meanwhile (FrameStats::deferred). While such a rebuild goes on, a
     * frame also ends right after its whole-grid step, so each step, and then the screen passes, get a frame
     * of their own; edits that redo the grid once (a light, a dragged object) are never split. An
     * interactive view stays responsive through a full rebuild; off by default, so one frame is always a
     * complete image.
     */
    void setStagedRebuilds(bool staged) { m_staged = staged; }
    /** Whether the last frame deferred passes: a staged rebuild is going on. */
    bool rebuilding() const { return m_rebuilding; }
    void invalidate();
    const std::vector<std::unique_ptr<RenderPass>>& passes() const { return m_passes; }
    /** Every texture the passes make; tools outside the pipeline register theirs here too. */
    ResourceTable& resources() { return m_resources; }
    const ResourceTable& resources() const { return m_resources; }

private:
    /** Makes @p pass's textures what it asks for this frame; true when one was made anew. */
    bool prepareTextures(RenderPass& pass, const FrameContext& frame);

    std::vector<std::unique_ptr<RenderPass>> m_passes;
    ResourceTable m_resources;
    /// Two sets, so a frame can issue into one while the previous frame's results are read from the other.
    std::vector<gl::TimerQuery> m_timers[2];
    std::vector<bool> m_ranLastFrame;
    int m_currentSet = 0;
    TimingReadback m_readback = TimingReadback::ThisFrame;
    bool m_staged = false;
    bool m_rebuilding = false; ///< the last frame deferred passes: a staged rebuild is going on
};

} // namespace vct::render
