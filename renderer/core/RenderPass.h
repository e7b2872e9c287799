#pragma once

#include "core/FrameStats.h"
#include "core/ResourceTable.h"

#include <string>
#include <vector>

namespace vct::render {

struct FrameContext;

/**
 * What a pass reads and writes, by the textures' names in the resource table (core/ResourceNames.h). The
 * pipeline rejects an order in which a read comes before any write, and a pass that makes a texture it does
 * not declare it writes.
 */
struct PassDeclaration {
    std::vector<std::string> reads;
    std::vector<std::string> writes;
};

/** Whether a pass runs this frame, and why. */
struct PassDecision {
    enum class Action { Run, Reuse, Skip };
    Action action = Action::Run;
    std::string reason;
};

/** One stage of the frame: its own class and shaders; the pipeline times it and may reuse its output. */
class RenderPass {
public:
    virtual ~RenderPass() = default;
    virtual const char* name() const = 0;
    virtual PassDeclaration declare() const = 0;
    /**
     * Decides run, reuse (last output still valid) or skip (effect not needed), with the reason. Changes
     * nothing: what a skipped pass frees, it frees in release().
     */
    virtual PassDecision plan(const FrameContext& frame) const = 0;
    /**
     * The textures this pass makes, every one of them every frame (in the same order), each with what this
     * frame needs of it: an empty description frees it. The pipeline makes them so before execute(), also
     * when the pass is skipped or reused; when one is made anew it calls invalidate() first, so the pass
     * redoes its output. The names are among declare()'s writes.
     */
    virtual std::vector<TextureSlot> textures(const FrameContext& frame)
    {
        (void)frame;
        return {};
    }
    virtual void execute(FrameContext& frame) = 0;
    /**
     * Whether the run plan() decided redoes the whole voxel grid (asked before execute()). With staged
     * frames (Pipeline::setStagedRebuilds) the second such run in one frame waits for the next frame, so that
     * a full rebuild is split over several short frames instead of blocking for the sum of them.
     */
    virtual bool redoesWholeGrid(const FrameContext& frame) const
    {
        (void)frame;
        return false;
    }
    /**
     * Called instead of execute() when plan() skips the pass: forgets state kept for an effect the frame no
     * longer needs (its textures are freed by what textures() asks for).
     */
    virtual void release(FrameContext& frame) { (void)frame; }
    /** Forgets cached state so the next plan() runs the pass (after GPU resources were recreated). */
    virtual void invalidate() = 0;
    /**
     * False for a pass that runs passes of its own (core/ClipLevelPass), which time themselves: GL timer
     * queries do not nest. The pipeline then reports gpuMsOfLastRun() and appends nestedStats().
     */
    virtual bool timedByPipeline() const { return true; }
    virtual double gpuMsOfLastRun() const { return 0.0; }
    /**
     * A pass of its own passes: theirs. A pass timed by the pipeline: the phases of the run it just made, if
     * it times them (core/PhaseTimes), appended after every pass's own line and part of its time.
     */
    virtual std::vector<PassStats> nestedStats() const { return {}; }
};

} // namespace vct::render
