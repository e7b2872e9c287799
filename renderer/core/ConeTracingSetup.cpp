#include "core/ConeTracingSetup.h"

#include "core/ConeTraceKey.h"

#include "core/FrameContext.h"
#include "scene/DirectionalStackLayout.h"

#include "common/Bindings.glsl"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace vct::render {

void ConeTracingSetup::apply(const gl::Program& program, const FrameContext& frame, bool anisotropic)
{
    const RenderSettings& settings = frame.settings;
    const VoxelVolume& v = frame.voxels;
    const float voxel = v.frame.voxelSize();
    // Negative: the diagonal of the grid around the scene (a clipmap's coarsest level, not its finest).
    const float maxDistance
        = settings.maxDistance >= 0.0f ? settings.maxDistance : frame.sceneGrid.extent * std::sqrt(3.0f);
    std::vector<glm::vec4> cones;
    for (int i = 0; i < frame.diffuseCones.size(); ++i)
        cones.emplace_back(
            frame.diffuseCones.directions()[std::size_t(i)], frame.diffuseCones.weights()[std::size_t(i)]);

    program.set("uGridOrigin", v.frame.origin);
    program.set("uGridExtent", v.frame.extent);
    program.set("uVoxelSize", voxel);
    program.set("uMaxLevel", float(v.frame.levelCount() - 1));
    program.set("uStepFactor", settings.stepFactor);
    program.set("uMaxDistance", maxDistance);
    program.set("uConeOffset", coneOffsetMetres(frame));
    program.set("uConeCount", frame.diffuseCones.size());
    program.set("uCones", cones);
    program.set("uDiffuseTanHalf", std::tan(glm::radians(settings.diffuseApertureDeg * 0.5f)));

    // Only where some space is closed in (open scenes keep their images bit for bit and skip the lookup), and
    // not with a cone length set: there a cone's light beyond it is meant to be left out, not made up.
    if (frame.enclosure)
        frame.enclosure->finish();
    const bool enclosure = frame.enclosure && frame.enclosure->inUse && frame.enclosure->texture
        && frame.enclosure->enclosedCells > 0 && settings.maxDistance < 0.0f;
    program.set("uEnclosureUsed", int(enclosure));
    if (enclosure) {
        const VoxelGridFrame& map = frame.enclosure->grid;
        program.set("uEnclosureBox", glm::vec4(map.origin, map.extent));
        program.set("uEnclosureLift", 1.5f * map.voxelSize());
        frame.enclosure->texture.bindUnit(ENCLOSURE_UNIT);
    }
    v.coneRadiance().bindUnit(5);
    if (anisotropic) {
        v.coneDirectional().bindUnit(6);
        // The chains were made by this layout (VoxelMipBuilder::directionalDesc); in tiles for the lookup.
        const DirectionalStackLayout stack = DirectionalStackLayout::of(v.frame.resolution);
        const float tile = float(std::max(stack.size, 1));
        program.set("uStack", glm::vec2(float(stack.stride(0)) / tile, float(stack.depth()) / tile));
    }
    if (frame.coarserLevels.empty())
        return;
    std::vector<glm::vec4> boxes, grids;
    clipLevelFrames(frame, boxes, grids);
    for (std::size_t k = 0; k < frame.coarserLevels.size(); ++k) {
        const VoxelVolume& level = *frame.coarserLevels[k];
        level.coneRadiance().bindUnit(GLuint(CLIP_RADIANCE_UNIT + int(k)));
        if (anisotropic)
            level.coneDirectional().bindUnit(GLuint(CLIP_TOWARDS_UNIT + int(k)));
    }
    program.set("uClipBox", boxes);
    program.set("uClipGrid", grids);
}

void ConeTracingSetup::bindVolumeSampler(const FrameContext& frame, GLuint sampler)
{
    glBindSampler(5, sampler);
    glBindSampler(6, sampler);
    for (std::size_t k = 0; k < frame.coarserLevels.size(); ++k) {
        glBindSampler(GLuint(CLIP_RADIANCE_UNIT + int(k)), sampler);
        glBindSampler(GLuint(CLIP_TOWARDS_UNIT + int(k)), sampler);
    }
}

void ConeTracingSetup::clipLevelFrames(
    const FrameContext& frame, std::vector<glm::vec4>& boxes, std::vector<glm::vec4>& grids)
{
    boxes.clear();
    grids.clear();
    for (const VoxelVolume* level : frame.coarserLevels) {
        boxes.emplace_back(level->frame.origin, level->frame.extent);
        grids.emplace_back(level->frame.voxelSize(), float(level->frame.levelCount() - 1),
            coneOffsetMetres(frame, level->frame), 0.0f);
    }
}

void ConeTracingSetup::applyCacheBand(const gl::Program& program, const FrameContext& frame)
{
    const VoxelGridFrame& finest = frame.voxels.frame;
    program.set("uCacheGrid", glm::vec4(finest.origin, finest.extent));
    program.set("uCacheScene", glm::vec4(frame.sceneGrid.origin, frame.sceneGrid.extent));
    program.set(
        "uCacheBand", frame.coarserLevels.empty() ? 0.0f : float(CLIP_BAND_VOXELS) * finest.voxelSize());
}

void ConeTracingSetup::addDefines(std::vector<std::string>& defines, const FrameContext& frame)
{
    if (!frame.coarserLevels.empty())
        defines.push_back("CLIP_LEVELS " + std::to_string(frame.coarserLevels.size()));
}

float ConeTracingSetup::coneOffsetMetres(const FrameContext& frame)
{
    return coneOffsetMetres(frame, frame.voxels.frame);
}

float ConeTracingSetup::coneOffsetMetres(const FrameContext& frame, const VoxelGridFrame& grid)
{
    // On a clipmap's fine levels too: their voxels are those of a finer grid around the scene.
    return frame.settings.coneOffsetVoxels
        * std::max(grid.voxelSize(), frame.sceneGrid.extent / float(kOffsetGrid));
}

ConeTraceKey ConeTraceKey::of(const FrameContext& frame)
{
    const RenderSettings& s = frame.settings;
    ConeTraceKey key { s.anisotropicMips, s.diffuseConeCount, frame.voxels.frame.resolution,
        s.diffuseApertureDeg, s.stepFactor, s.dropBackFaces, s.maxDistance, s.coneOffsetVoxels,
        frame.enclosure && frame.enclosure->inUse ? frame.enclosure->version : 0, {} };
    for (const VoxelVolume* level : frame.coarserLevels) {
        key.coarserLight.push_back(level->radianceVersion);
        key.coarserLight.push_back(level->bouncedVersion);
    }
    return key;
}

void ConeTracingSetup::applyCellGather(const gl::Program& program, const FrameContext& frame,
    bool anisotropic, int cellSize, bool ao, const gl::Texture& front, const gl::Texture& back,
    const gl::Texture& normals)
{
    const VoxelVolume& v = frame.voxels;
    apply(program, frame, anisotropic);
    program.set("uResolution", v.frame.resolution);
    program.set("uCellSize", cellSize);
    program.set("uOne", 1);
    program.set("uAoEnabled", ao ? 1 : 0);
    program.set("uAoDistance", 0.1f * frame.sceneGrid.extent);
    v.albedo.bindUnit(0);
    v.normal.bindUnit(1);
    front.bindImage(0, 0, GL_WRITE_ONLY);
    back.bindImage(1, 0, GL_WRITE_ONLY);
    normals.bindImage(2, 0, GL_WRITE_ONLY);
}

} // namespace vct::render
