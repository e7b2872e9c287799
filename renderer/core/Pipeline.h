#pragma once

#include "core/FrameStats.h"
#include "core/RenderPass.h"
#include "gl/TimerQuery.h"

#include <memory>
#include <vector>

namespace vct::render {

/** Runs passes in order, each inside a GL timer query, and applies their run/reuse/skip decisions. */
class Pipeline {
public:
    /** Throws std::logic_error when a pass reads a resource no earlier pass writes. */
    explicit Pipeline(std::vector<std::unique_ptr<RenderPass>> passes);

    /** Runs one frame; returns after the timer results are read back (the caller wants them now). */
    FrameStats execute(FrameContext& frame);
    void invalidate();
    const std::vector<std::unique_ptr<RenderPass>>& passes() const { return m_passes; }

private:
    std::vector<std::unique_ptr<RenderPass>> m_passes;
    std::vector<gl::TimerQuery> m_timers;
};

} // namespace vct::render
