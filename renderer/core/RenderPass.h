#pragma once

#include <string>
#include <vector>

namespace vct::render {

struct FrameContext;

/** Named resources passes hand to each other; the pipeline checks each read follows its write. */
enum class Resource {
    ShadowMaps,
    VoxelMaterials,
    VoxelRadiance,
    VoxelMips,
    VoxelIrradiance,
    GBuffer,
    IndirectLight,
    FinalImage
};

const char* resourceName(Resource resource);

/** What a pass reads and writes. */
struct PassDeclaration {
    std::vector<Resource> reads;
    std::vector<Resource> writes;
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
    virtual void execute(FrameContext& frame) = 0;
    /**
     * Called instead of execute() when plan() skips the pass: frees what it made for an effect the frame no
     * longer needs (textures, cached state), so that switching an effect off gives its memory back.
     */
    virtual void release(FrameContext& frame) { (void)frame; }
    /** Forgets cached state so the next plan() runs the pass (after GPU resources were recreated). */
    virtual void invalidate() = 0;
};

} // namespace vct::render
