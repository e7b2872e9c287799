#include "passes/VoxelBouncePass.h"

#include "core/FrameContext.h"
#include "core/FrameRules.h"
#include "passes/ConeTracingSetup.h"

namespace vct::render {

VoxelBouncePass::GatherKey VoxelBouncePass::keyOf(const FrameContext& frame)
{
    const RenderSettings& s = frame.settings;
    return {s.anisotropicMips, s.diffuseConeCount, s.diffuseApertureDeg, s.stepFactor, s.maxDistance, s.coneOffsetVoxels,
        frame.voxels.frame.resolution};
}

PassDecision VoxelBouncePass::plan(const FrameContext& frame)
{
    VoxelVolume& v = frame.voxels;
    if (frame.settings.bounces < 2 || !FrameRules::hasLightSources(frame)) {
        // Cones must go back to the first-bounce volume; the memory is not needed either.
        v.bounced = gl::Texture();
        v.bouncedDirectional = gl::Texture();
        m_radianceVersion = 0;
        return {PassDecision::Action::Skip, frame.settings.bounces < 2 ? "one bounce: the per-pixel cones gather it" : "no light"};
    }
    if (v.bounced && v.radianceVersion == m_radianceVersion && keyOf(frame) == m_key)
        return {PassDecision::Action::Reuse, "first-bounce radiance unchanged"};
    return {PassDecision::Action::Run, "first-bounce radiance changed"};
}

void VoxelBouncePass::execute(FrameContext& frame)
{
    VoxelVolume& v = frame.voxels;
    const bool anisotropic = frame.settings.anisotropicMips && v.directional;
    gl::Program& program = anisotropic ? m_anisotropicProgram : m_program;
    if (!program)
        program = frame.shaders.build({anisotropic ? "second bounce (anisotropic)" : "second bounce",
            {"bounce/GatherBounce.comp"}, anisotropic ? std::vector<std::string>{"ANISOTROPIC"} : std::vector<std::string>{}});
    const int res = v.frame.resolution;
    if (!v.bounced || v.bounced.width() != res)
        v.bounced = gl::Texture::create3D(GL_RGBA16F, res, v.radiance.levels());

    // Empty voxels stay dark; the gather runs over the occupied ones only (a voxel both layers reach, twice).
    const float dark[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearTexImage(v.bounced.id(), 0, GL_RGBA, GL_FLOAT, dark);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    const std::vector<const OccupiedCellList*> occupied = v.occupiedVoxels(frame.scene.hasDynamicMeshes());
    // Gather from the first-bounce volume, not from last time's second bounce.
    ConeTracingSetup::apply(program, frame, anisotropic, false);
    program.set("uAoEnabled", 0);
    v.albedo.bindUnit(0);
    v.normal.bindUnit(1);
    v.bounced.bindImage(0, 0, GL_WRITE_ONLY);
    program.use();
    for (const OccupiedCellList* voxels : occupied)
        voxels->dispatchOverCells();
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);

    m_builder.listCells(frame.shaders, res, v.bounced.levels(), occupied);
    m_builder.buildBox(frame.shaders, v.bounced);
    if (anisotropic)
        m_builder.buildDirectional(frame.shaders, v.bounced, res, v.bouncedDirectional);
    else
        v.bouncedDirectional = gl::Texture();
    m_radianceVersion = v.radianceVersion;
    m_key = keyOf(frame);
}

} // namespace vct::render
