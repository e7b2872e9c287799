#include "cli/PlanBenchmark.h"

#include "Renderer.h"
#include "cli/Statistics.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <sstream>

namespace vct::cli {

namespace {

int largestStaticMesh(const render::Scene& scene)
{
    int best = -1;
    for (std::size_t i = 0; i < scene.meshes.size(); ++i)
        if (!scene.meshes[i].dynamic
            && (best < 0
                || scene.meshes[i].triangleCount() > scene.meshes[std::size_t(best)].triangleCount()))
            best = int(i);
    return best;
}

/** Runs the sequence on the renderer; forced re-runs every pass of every frame. */
std::vector<render::FrameStats> replay(render::Renderer& renderer, const render::Scene& scene,
    const EditSequence& sequence, int width, int height, int frames, bool forced)
{
    renderer.setScene(scene);
    render::Camera camera = scene.camera;
    renderer.renderFrame(camera, width, height); // warm-up: shaders compiled, caches filled
    std::vector<render::FrameStats> stats;
    for (int frame = 0; frame < frames; ++frame) {
        sequence.apply(renderer, camera, frame);
        if (forced)
            renderer.invalidate();
        stats.push_back(renderer.renderFrame(camera, width, height));
    }
    return stats;
}

} // namespace

std::vector<EditSequence> PlanBenchmark::standardSequences(const render::Scene& scene)
{
    std::vector<EditSequence> sequences;
    sequences.push_back({ "orbit the camera", [](render::Renderer&, render::Camera& camera, int) {
                             const glm::mat4 turn
                                 = glm::rotate(glm::mat4(1.0f), glm::radians(3.0f), camera.up);
                             camera.position = camera.lookAt
                                 + glm::vec3(turn * glm::vec4(camera.position - camera.lookAt, 0.0f));
                         } });
    // Walking pace, 1.4 m/s, at 30 frames a second, along the view: what a clipmap's levels
    // (voxel_mode=clipmap) follow, a dense grid not at all.
    sequences.push_back({ "fly forward at walking speed", [](render::Renderer&, render::Camera& camera, int) {
                             const glm::vec3 step
                                 = glm::normalize(camera.lookAt - camera.position) * (1.4f / 30.0f);
                             camera.position += step;
                             camera.lookAt += step;
                         } });
    if (!scene.pointLights.empty() || !scene.directionalLights.empty() || !scene.surfaceLights.empty())
        sequences.push_back(
            { "move the light", [scene](render::Renderer& renderer, render::Camera&, int frame) {
                 std::vector<render::PointLight> points = scene.pointLights;
                 std::vector<render::DirectionalLight> directionals = scene.directionalLights;
                 std::vector<render::SurfaceLight> surfaces = scene.surfaceLights;
                 const float offset = 0.05f * float(frame + 1);
                 for (render::PointLight& light : points)
                     light.position.x += offset;
                 for (render::DirectionalLight& light : directionals)
                     light.direction.x += offset;
                 for (render::SurfaceLight& light : surfaces)
                     light.centre.x += offset;
                 renderer.setLights(points, directionals, surfaces);
             } });
    for (std::size_t i = 0; i < scene.meshes.size(); ++i)
        if (scene.meshes[i].dynamic) {
            const glm::mat4 base = scene.meshes[i].transform;
            sequences.push_back({ "drag the dynamic object (" + scene.meshes[i].name + ")",
                [i, base](render::Renderer& renderer, render::Camera&, int frame) {
                    renderer.setMeshTransform(
                        i, glm::translate(glm::mat4(1.0f), glm::vec3(0.05f * float(frame + 1), 0, 0)) * base);
                } });
            break;
        }
    if (const int mesh = largestStaticMesh(scene); mesh >= 0) {
        const int index = scene.meshes[std::size_t(mesh)].material;
        const render::Material original = scene.materials[std::size_t(index)];
        sequences.push_back({ "edit one material (" + original.name + ")",
            [index, original](render::Renderer& renderer, render::Camera&, int frame) {
                render::Material edited = original;
                edited.albedo *= frame % 2 ? 1.0f : 0.9f;
                renderer.setMaterial(std::size_t(index), edited);
            } });
    }
    for (std::size_t m = 0; m < scene.materials.size(); ++m)
        if (scene.materials[m].isGlossy()) {
            const render::Material glossy = scene.materials[m];
            sequences.push_back({ "toggle a glossy material (" + glossy.name + ")",
                [m, glossy](render::Renderer& renderer, render::Camera&, int frame) {
                    render::Material edited = glossy;
                    if (frame % 2 == 0)
                        edited.specular = glm::vec3(0.0f);
                    renderer.setMaterial(m, edited);
                } });
            break;
        }
    return sequences;
}

SequenceResult PlanBenchmark::run(render::Renderer& renderer, const render::Scene& scene,
    const EditSequence& sequence, int width, int height, int frames)
{
    SequenceResult result;
    result.name = sequence.name;
    const std::vector<render::FrameStats> planned
        = replay(renderer, scene, sequence, width, height, frames, false);
    const std::vector<render::FrameStats> forced
        = replay(renderer, scene, sequence, width, height, frames, true);
    std::vector<double> plannedTotals, forcedTotals;
    for (const render::FrameStats& f : planned)
        plannedTotals.push_back(f.totalGpuMs);
    for (const render::FrameStats& f : forced)
        forcedTotals.push_back(f.totalGpuMs);
    result.plannedMs = median(plannedTotals);
    if (!plannedTotals.empty()) {
        const auto worst = std::max_element(plannedTotals.begin(), plannedTotals.end());
        result.plannedWorstMs = *worst;
        result.worstFrame = int(worst - plannedTotals.begin());
        result.worstFramePasses = planned[std::size_t(result.worstFrame)].passes;
    }
    result.forcedMs = median(forcedTotals);
    for (std::size_t p = 0; !planned.empty() && p < planned.back().passes.size(); ++p) {
        PlannedPass pass { planned.back().passes[p] };
        std::vector<double> ms, whenRun;
        for (const render::FrameStats& f : planned) {
            ms.push_back(f.passes[p].gpuMs);
            if (f.passes[p].action == "run")
                whenRun.push_back(f.passes[p].gpuMs);
        }
        pass.stats.gpuMs = median(ms);
        pass.runs = int(whenRun.size());
        pass.msWhenRun = median(whenRun);
        result.plannedPasses.push_back(pass);
    }
    return result;
}

std::string PlanBenchmark::markdown(const std::vector<SequenceResult>& results)
{
    std::ostringstream out;
    char line[512];
    out << "| edit sequence | planned ms/frame (median) | planned, worst frame | forced ms/frame | forced / "
           "planned "
           "|\n|---|---|---|---|---|\n";
    for (const SequenceResult& r : results) {
        std::snprintf(line, sizeof line, "| %s | %.1f | %.1f | %.1f | %.2f× |\n", r.name.c_str(), r.plannedMs,
            r.plannedWorstMs, r.forcedMs, r.plannedMs > 0.0 ? r.forcedMs / r.plannedMs : 0.0);
        out << line;
    }
    for (const SequenceResult& r : results) {
        out << "\n**" << r.name
            << "**, planned passes (median ms over the frames; the frames it ran in and its median ms in "
               "them; action and reason of the last frame):\n\n"
            << "| pass | action | ms | ran in | ms when it ran | reason |\n|---|---|---|---|---|---|\n";
        for (const PlannedPass& p : r.plannedPasses) {
            std::snprintf(line, sizeof line, "| %s | %s | %.1f | %d | %.1f | %s |\n", p.stats.name.c_str(),
                p.stats.action.c_str(), p.stats.gpuMs, p.runs, p.msWhenRun, p.stats.reason.c_str());
            out << line;
        }
        // The median hides what a frame that redoes something pays (a clip level stepping with the camera).
        if (r.worstFrame < 0)
            continue;
        std::snprintf(line, sizeof line,
            "\nIts longest planned frame (frame %d, %.1f ms), the passes that ran:\n\n"
            "| pass | ms | reason |\n|---|---|---|\n",
            r.worstFrame + 1, r.plannedWorstMs);
        out << line;
        for (const render::PassStats& p : r.worstFramePasses) {
            if (p.action != "run")
                continue;
            std::snprintf(
                line, sizeof line, "| %s | %.1f | %s |\n", p.name.c_str(), p.gpuMs, p.reason.c_str());
            out << line;
        }
    }
    return out.str();
}

std::vector<RebuildResult> PlanBenchmark::rebuilds(render::Renderer& renderer, const render::Camera& camera,
    int width, int height, int iterationsPerFrame, int rounds)
{
    using Clock = std::chrono::steady_clock;
    std::vector<RebuildResult> results(2);
    std::vector<double> longest[2], toImage[2], toConverged[2], framesToImage[2], framesToConverged[2];
    renderer.setBounceIterationsPerFrame(iterationsPerFrame);
    renderer.renderFrame(camera, width, height); // warm-up: shaders compiled
    for (int round = 0; round < rounds; ++round)
        for (const int staged : { 0, 1 }) {
            renderer.setStagedRebuilds(staged == 1);
            renderer.invalidate();
            const Clock::time_point start = Clock::now();
            double worst = 0.0;
            int frames = 0;
            bool imaged = false;
            // Frame times are waited for (the default readback), so a frame's wall time is its whole cost.
            for (render::FrameStats stats; !imaged || !stats.lightConverged;) {
                const Clock::time_point begin = Clock::now();
                stats = renderer.renderFrame(camera, width, height);
                const Clock::time_point end = Clock::now();
                worst = std::max(worst, std::chrono::duration<double, std::milli>(end - begin).count());
                ++frames;
                const double sinceStart = std::chrono::duration<double, std::milli>(end - start).count();
                if (!imaged && !stats.deferred) {
                    imaged = true;
                    toImage[staged].push_back(sinceStart);
                    framesToImage[staged].push_back(frames);
                }
                if (imaged && stats.lightConverged) {
                    toConverged[staged].push_back(sinceStart);
                    framesToConverged[staged].push_back(frames);
                }
            }
            longest[staged].push_back(worst);
        }
    renderer.setStagedRebuilds(false);
    renderer.setBounceIterationsPerFrame(0);
    for (const int staged : { 0, 1 }) {
        RebuildResult& r = results[std::size_t(staged)];
        r.staged = staged == 1;
        r.longestFrameMs = median(longest[staged]);
        r.firstImageMs = median(toImage[staged]);
        r.convergedMs = median(toConverged[staged]);
        r.framesToImage = int(median(framesToImage[staged]));
        r.framesToConverged = int(median(framesToConverged[staged]));
    }
    return results;
}

std::string PlanBenchmark::markdown(const std::vector<RebuildResult>& results, int iterationsPerFrame)
{
    std::ostringstream out;
    char line[512];
    std::snprintf(line, sizeof line,
        "\n**A full rebuild as the editor draws it** (%d bounce iterations a frame; wall clock, medians over "
        "the "
        "rounds):\n\n| rebuild | longest frame ms | first complete image: frames, ms | converged: frames, ms "
        "|\n"
        "|---|---|---|---|\n",
        iterationsPerFrame);
    out << line;
    for (const RebuildResult& r : results) {
        std::snprintf(line, sizeof line, "| %s | %.0f | %d, %.0f | %d, %.0f |\n",
            r.staged ? "staged over frames (the editor)" : "in one frame", r.longestFrameMs, r.framesToImage,
            r.firstImageMs, r.framesToConverged, r.convergedMs);
        out << line;
    }
    return out.str();
}

} // namespace vct::cli
