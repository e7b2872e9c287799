#include "passes/InjectLightPass.h"

#include "core/FrameContext.h"
#include "core/Level0Clear.h"
#include "core/LightUniforms.h"
#include "core/ResourceNames.h"
#include "core/VolumeShift.h"

#include <algorithm>
#include <string>
#include <vector>

namespace vct::render {

InjectLightPass::LightKey InjectLightPass::keyOf(const FrameContext& frame)
{
    return { frame.voxels.materialsVersion, frame.versions.lightValues, frame.settings.direct,
        frame.settings.emission, frame.settings.shadowMapSize, frame.shadows.version,
        frame.scene.areaLightsVersion() };
}

namespace {

/**
 * The grid box that can fall into the shadow of `box`: the box plus everything behind it as seen from each
 * light, i.e. its corners pushed away from the light by a grid diagonal. Conservative (a box around the
 * shadow frustum), and the whole grid when a point light sits inside the box.
 */
VoxelRegion shadowReach(const Aabb& box, const Scene& scene, const std::vector<AreaLight>& areaLights,
    const VoxelGridFrame& grid, int margin)
{
    if (box.isEmpty())
        return {};
    const float reach = grid.extent * 1.75f;
    Aabb covered = box;
    const glm::vec3 corners[8]
        = { box.min, { box.max.x, box.min.y, box.min.z }, { box.min.x, box.max.y, box.min.z },
              { box.min.x, box.min.y, box.max.z }, { box.max.x, box.max.y, box.min.z },
              { box.max.x, box.min.y, box.max.z }, { box.min.x, box.max.y, box.max.z }, box.max };
    for (const PointLight& light : scene.pointLights) {
        if (!light.castsShadows)
            continue;
        if (glm::all(glm::greaterThanEqual(light.position, box.min - grid.voxelSize()))
            && glm::all(glm::lessThanEqual(light.position, box.max + grid.voxelSize())))
            return VoxelRegion::whole(grid.resolution);
        for (const glm::vec3& c : corners)
            covered.extend(c + glm::normalize(c - light.position) * reach);
    }
    for (const DirectionalLight& light : scene.directionalLights)
        if (light.castsShadows)
            for (const glm::vec3& c : corners)
                covered.extend(c + glm::normalize(light.direction) * reach);
    // An area light's shadow spreads beyond its centre's by the light's size.
    for (const AreaLight& light : areaLights) {
        if (glm::length(box.center() - light.centre) <= light.radius + 0.5f * glm::length(box.size()))
            return VoxelRegion::whole(grid.resolution);
        for (const glm::vec3& c : corners) {
            covered.extend(c + glm::normalize(c - light.centre) * reach + glm::vec3(light.radius));
            covered.extend(c + glm::normalize(c - light.centre) * reach - glm::vec3(light.radius));
        }
    }
    return VoxelRegion::around(covered, grid, margin);
}

/** Whether @p regions is the whole grid, which regionsToInject() gives as one region. */
bool coversWholeGrid(const std::vector<VoxelRegion>& regions, int resolution)
{
    return regions.size() == 1 && regions[0].size() == VoxelRegion::whole(resolution).size();
}

} // namespace

bool InjectLightPass::keepsMovedLight(const FrameContext& frame) const
{
    const VoxelVolume& v = frame.voxels;
    if (!v.shiftedBy || v.radiance.serial() != m_radianceSerial)
        return false;
    const std::optional<glm::ivec3> step = VolumeShift::between(m_grid, v.frame);
    return step && *step == *v.shiftedBy;
}

std::vector<VoxelRegion> InjectLightPass::regionsToInject(const FrameContext& frame) const
{
    const VoxelVolume& v = frame.voxels;
    const std::vector<VoxelRegion> whole { VoxelRegion::whole(v.frame.resolution) };
    const auto key = keyOf(frame);
    // Lights, the direct and emission settings and the shadow maps' size need everything.
    // An emitter's edit changes the light everywhere its area light reaches, not only in its own voxels.
    const bool sameLights = m_key != LightKey {} && key.lightValues == m_key.lightValues
        && key.direct == m_key.direct && key.emission == m_key.emission
        && key.shadowMapSize == m_key.shadowMapSize && key.areaLights == m_key.areaLights;
    if (!sameLights || !v.partialRewrite)
        return whole;
    // A grid that stepped keeps its light where it keeps its voxels, if this pass's light followed it. Not
    // with area lights: a voxel's shadow cone reads the level's opacity, which the step changed near the
    // faces it had (measured on the Cornell box: slabs alone left 1.4% less light in the voxels, 7.6% of the
    // brightest voxel's in the worst, after eight steps).
    if (v.shiftedBy && (!keepsMovedLight(frame) || frame.shape.areaLights > 0))
        return whole;
    std::vector<VoxelRegion> regions = v.changedRegions;
    if (!v.dynamicMoved) // a static material edit or a step: only those voxels' own light changed
        return regions;
    const Scene& scene = frame.scene.scene();
    static const std::vector<AreaLight> none;
    const std::vector<AreaLight>& areaLights
        = frame.shape.areaLights > 0 ? frame.scene.areaLights().lights : none;
    // The moved object's region is the last; its shadows join it (the slabs before it stay as they are, so
    // a voxel in both is lit twice, with the same result).
    VoxelRegion& moved = regions.back();
    moved = moved.united(shadowReach(v.dynamicBounds, scene, areaLights, v.frame, 2))
                .united(shadowReach(v.previousDynamicBounds, scene, areaLights, v.frame, 2));
    return regions;
}

PassDeclaration InjectLightPass::declare() const
{
    using namespace resource;
    return { { kAlbedo, kNormal, kEmission, kPointShadows, kDirectionalShadows }, { kRadiance, kOpacity } };
}

std::vector<TextureSlot> InjectLightPass::textures(const FrameContext& frame)
{
    using gl::TextureDesc;
    VoxelVolume& v = frame.voxels;
    const int res = v.frame.resolution;
    // Level 0 alone when the bounced volume carries the levels cones read (MipmapPass). Only the area
    // lights' shadow cones read the opacity volume: scenes without them do not keep it.
    return { { resource::kRadiance, ResourceGroup::Voxels, &v.radiance,
                 v.level0(GL_RGBA16F, frame.shape.radianceLevels) },
        { resource::kOpacity, ResourceGroup::Voxels, &v.opacity,
            frame.shape.areaLights > 0 ? TextureDesc::volume(GL_RGBA8, res, v.frame.levelCount())
                                       : TextureDesc {} } };
}

bool InjectLightPass::redoesWholeGrid(const FrameContext& frame) const
{
    const std::vector<VoxelRegion> regions = regionsToInject(frame);
    return coversWholeGrid(regions, frame.voxels.frame.resolution);
}

PassDecision InjectLightPass::plan(const FrameContext& frame) const
{
    if (keyOf(frame) == m_key)
        return { PassDecision::Action::Reuse, "voxels, lights and shadows unchanged" };
    std::string reason = m_key == LightKey {} ? "no valid output yet" : "voxels or lights changed";
    const std::vector<VoxelRegion> regions = regionsToInject(frame);
    const int side = frame.voxels.frame.resolution;
    if (!coversWholeGrid(regions, side)) {
        std::size_t voxels = 0;
        for (const VoxelRegion& region : regions) {
            const glm::ivec3 s = region.size();
            voxels += std::size_t(s.x) * std::size_t(s.y) * std::size_t(s.z);
        }
        const int percent = int(100.0 * double(voxels) / (double(side) * side * side) + 0.5);
        reason = "re-injecting only the " + std::to_string(voxels) + " voxels (" + std::to_string(percent)
            + "%) that changed" + (frame.voxels.shiftedBy ? ", the rest moved with the grid" : "")
            + (frame.voxels.dynamicMoved ? " or lie in the moved object's shadow" : "");
    }
    if (frame.shape.areaLights > 0)
        reason += "; " + std::to_string(frame.shape.areaLights) + " area lights";
    const AreaLightSet& areaLights = frame.scene.areaLights();
    if (frame.shape.emittersAsAreaLights && areaLights.clusteredEmitters > 0)
        reason += " (" + std::to_string(areaLights.clusteredEmitters) + " separate emitters merged into "
            + std::to_string(areaLights.emitterLightCount()) + ", each shadowed as one)";
    if (!frame.scene.areaLights().note.empty())
        reason += "; " + frame.scene.areaLights().note;
    if (!frame.shape.emission)
        reason += "; no emission to inject";
    if (!frame.shape.lightSources)
        reason += "; no light sources: opacity only";
    return { PassDecision::Action::Run, reason };
}

void InjectLightPass::buildOpacity(FrameContext& frame)
{
    VoxelVolume& v = frame.voxels;
    // Only the area lights' shadow cones read the volume: scenes without them do not keep it.
    if (v.opacityVersion == v.materialsVersion && v.opacity.serial() == m_opacitySerial)
        return;
    m_opacitySerial = v.opacity.serial();
    if (!m_markOpacity) {
        m_markOpacity = &frame.shaders.program({ "mark opacity", { "inject/MarkOpacity.comp" }, {} });
        m_downsampleOpacity
            = &frame.shaders.program({ "downsample opacity", { "inject/DownsampleOpacity.comp" }, {} });
    }
    const float zero[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
    glClearTexImage(v.opacity.id(), 0, GL_RGBA, GL_FLOAT, zero);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    m_markOpacity->use();
    v.opacity.bindImage(0, 0, GL_WRITE_ONLY);
    for (const OccupiedCellList* voxels : v.occupiedVoxels(frame.scene.hasDynamicMeshes()))
        voxels->dispatchOverCells();
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    m_downsampleOpacity->use();
    v.opacity.bindUnit(0);
    for (int level = 1; level < v.opacity.levels(); ++level) {
        const int side = std::max(1, v.opacity.width() >> level);
        m_downsampleOpacity->set("uSourceLevel", level - 1);
        v.opacity.bindImage(0, level, GL_WRITE_ONLY);
        const GLuint groups = GLuint((side + 3) / 4);
        glDispatchCompute(groups, groups, groups);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
    v.opacityVersion = v.materialsVersion;
}

void InjectLightPass::execute(FrameContext& frame)
{
    const Scene& scene = frame.scene.scene();
    const int points = std::min<int>(int(scene.pointLights.size()), kMaxPointLights);
    const int directionals = std::min<int>(int(scene.directionalLights.size()), kMaxDirectionalLights);
    const int areas = frame.shape.areaLights;
    std::vector<std::string> defines { "POINT_LIGHT_COUNT " + std::to_string(points),
        "DIRECTIONAL_LIGHT_COUNT " + std::to_string(directionals),
        "AREA_LIGHT_COUNT " + std::to_string(areas) };
    if (softShadowsUsed(scene))
        defines.emplace_back("SOFT_SHADOWS");
    addAreaShadowDefines(defines, frame);
    defines.emplace_back("ONE_SHADOW_CONE"); // common/AreaLights.glsl: one shadow cone per light and voxel
    const gl::Program& program
        = frame.shaders.program({ "inject light", { "inject/InjectLight.comp" }, std::move(defines) });
    if (areas > 0)
        buildOpacity(frame);
    const std::vector<VoxelRegion> regions = regionsToInject(frame);
    VoxelVolume& v = frame.voxels;
    const bool whole = coversWholeGrid(regions, v.frame.resolution);
    if (!whole && v.shiftedBy)
        VolumeShift::apply(v.radiance, nullptr, *v.shiftedBy);
    m_key = keyOf(frame);
    m_grid = v.frame;
    m_radianceSerial = v.radiance.serial();
    // The regions are cleared to zero radiance; the lighting then writes the occupied voxels only. Over the
    // whole grid the voxelizer's lists name them; smaller regions are searched.
    // llvmpipe (Mesa 22.3) let this dispatch sample the shadow maps before the queued depth rendering into
    // them had finished (tests/gl/tst_RenderPlan caught stale shadows after a light moved). A barrier here,
    // where they are read, replaces the glFinish the shadow pass used to end with: the voxelizer's draws can
    // be set up while the shadow faces are still being rasterised.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    if (whole) {
        const float zero[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
        glClearTexImage(v.radiance.id(), 0, GL_RGBA, GL_FLOAT, zero);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    }

    program.use();
    applyLightUniforms(program, scene, frame.shadows);
    program.set("uGridOrigin", v.frame.origin);
    program.set("uVoxelSize", v.frame.voxelSize());
    program.set("uEmissionEnabled", frame.shape.voxelEmission ? 1 : 0);
    applyAreaLightUniforms(program, frame);
    program.set("uDirectEnabled", frame.settings.direct ? 1 : 0);
    v.albedo.bindUnit(0);
    v.normal.bindUnit(1);
    v.emission.bindUnit(2);
    v.radiance.bindImage(0, 0, GL_WRITE_ONLY);
    if (whole) {
        // A voxel both layers reach is lit twice, with the same result.
        for (const OccupiedCellList* voxels : v.occupiedVoxels(frame.scene.hasDynamicMeshes()))
            voxels->dispatchOverCells();
    } else {
        for (const VoxelRegion& region : regions) {
            if (region.isEmpty())
                continue;
            clearLevel0(v, v.radiance, region);
            glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
            if (v.sparse)
                m_occupied.capCapacity(v.bricks.allocatedBricks() * BrickPool::kVoxelsPerBrick);
            m_occupied.build(frame.shaders, v.albedo, region, 1);
            program.use();
            m_occupied.dispatchOverCells();
            glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
        }
    }
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    ++v.radianceVersion;
}

} // namespace vct::render
