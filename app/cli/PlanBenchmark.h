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

/** Median GPU ms per frame of a sequence with the plan and with every pass forced, and the planned passes. */
struct SequenceResult {
    std::string name;
    double plannedMs = 0.0;
    double forcedMs = 0.0;
    std::vector<render::PassStats> plannedPasses; ///< median ms per pass, action and reason of the last frame
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
};

} // namespace vct::cli
