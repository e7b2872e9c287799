#pragma once

#include "core/FrameStats.h"
#include "scene/RenderSettings.h"
#include "scene/Scene.h"

#include <functional>
#include <string>
#include <vector>

namespace vct::render {
class Renderer;
}

namespace vct::cli {

/** One scripted edit sequence: `apply(renderer, frame)` makes the edit before frame `frame` is drawn. */
struct EditSequence {
    std::string name;
    std::function<void(render::Renderer&, render::Camera&, int frame)> apply;
};

/** One pass over a sequence's planned frames. */
struct PlannedPass {
    render::PassStats stats; ///< median ms over every frame, action and reason of the last frame
    int runs = 0; ///< frames it ran in
    double msWhenRun = 0.0; ///< median ms over those frames: what a frame that redoes it pays
};

/** Median GPU ms per frame of a sequence with the plan and with every pass forced, and the planned passes. */
struct SequenceResult {
    std::string name;
    double plannedMs = 0.0; ///< median GPU ms per frame
    double plannedWorstMs = 0.0; ///< the longest planned frame
    double forcedMs = 0.0;
    std::vector<PlannedPass> plannedPasses;
    int worstFrame = -1; ///< which planned frame was the longest (0 = the first)
    std::vector<render::PassStats> worstFramePasses; ///< that frame's passes as they ran
};

/**
 * A full rebuild drawn as the editor draws it (bounce iterations spread over frames): the frames from the
 * rebuild to a complete image with converged bounces, one frame blocking the event loop at a time.
 */
struct RebuildResult {
    bool staged = false; ///< Renderer::setStagedRebuilds
    int framesToImage = 0; ///< frames until the first complete image (median over the rounds)
    int framesToConverged = 0; ///< frames until the bounces converged too
    double longestFrameMs = 0.0; ///< the longest frame, wall clock: how long the window is frozen at most
    double firstImageMs = 0.0; ///< wall clock from the rebuild to the first complete image
    double convergedMs = 0.0; ///< wall clock from the rebuild to converged bounces
};

/**
 * `vct-bench plan`: replays edit sequences (orbit the camera, move the light, drag the dynamic object, edit a
 * material, toggle a glossy material) on one renderer, first letting the plan reuse and skip passes, then
 * forcing every pass, and compares the GPU time per frame.
 */
class PlanBenchmark {
public:
    /** The standard sequences for a scene (those that do not apply, e.g. no dynamic mesh, are left out). */
    static std::vector<EditSequence> standardSequences(const render::Scene& scene);
    static SequenceResult run(render::Renderer& renderer, const render::Scene& scene,
        const EditSequence& sequence, int width, int height, int frames);
    static std::string markdown(const std::vector<SequenceResult>& results);
    /**
     * A full rebuild (every pass invalidated) drawn with @p iterationsPerFrame bounce iterations a frame,
     * with and without staged rebuilds, alternating over @p rounds; medians over the rounds.
     */
    static std::vector<RebuildResult> rebuilds(render::Renderer& renderer, const render::Camera& camera,
        int width, int height, int iterationsPerFrame, int rounds);
    static std::string markdown(const std::vector<RebuildResult>& results, int iterationsPerFrame);
};

} // namespace vct::cli
