#include "passes/VoxelIrradiancePass.h"

#include "core/FrameContext.h"
#include "core/FrameRules.h"
#include "passes/ConeTracingSetup.h"

#include <algorithm>

namespace vct::render {

bool VoxelIrradiancePass::inUse(const FrameContext& frame)
{
    return frame.settings.irradianceCache && FrameRules::diffuseConesNeeded(frame);
}

VoxelIrradiancePass::GatherKey VoxelIrradiancePass::keyOf(const FrameContext& frame)
{
    const RenderSettings& s = frame.settings;
    return {s.anisotropicMips, s.bounces, s.diffuseConeCount, s.diffuseApertureDeg, s.stepFactor, s.maxDistance,
        s.coneOffsetVoxels, frame.voxels.frame.resolution, FrameRules::ambientOcclusionNeeded(frame), s.irradianceCellSize};
}

PassDecision VoxelIrradiancePass::plan(const FrameContext& frame)
{
    VoxelVolume& v = frame.voxels;
    if (!inUse(frame)) {
        v.irradiance = gl::Texture(); // the cone pass traces per pixel; the memory is not needed either
        v.irradianceBack = gl::Texture();
        v.irradianceNormal = gl::Texture();
        m_radianceVersion = 0;
        return {PassDecision::Action::Skip,
            frame.settings.irradianceCache ? "no diffuse light needed" : "irradiance cache off: cones per pixel"};
    }
    if (v.irradiance && v.radianceVersion == m_radianceVersion && keyOf(frame) == m_key)
        return {PassDecision::Action::Reuse, "voxel light unchanged"};
    return {PassDecision::Action::Run, v.irradiance ? "voxel light or a gather setting changed" : "no valid output yet"};
}

void VoxelIrradiancePass::execute(FrameContext& frame)
{
    VoxelVolume& v = frame.voxels;
    const bool anisotropic = frame.settings.anisotropicMips && v.directional;
    gl::Program& program = m_programs[anisotropic ? 1 : 0];
    if (!program) {
        program = frame.shaders.build({anisotropic ? "irradiance cache (anisotropic)" : "irradiance cache",
            {"bounce/GatherIrradiance.comp"}, anisotropic ? std::vector<std::string>{"ANISOTROPIC"} : std::vector<std::string>{}});
    }
    const int res = v.frame.resolution;
    const int cellSize = std::min(frame.settings.irradianceCellSize, res);
    const int cells = res / cellSize;
    if (!v.irradiance || v.irradiance.width() != cells) {
        // Cleared once: the gather writes only cells that hold voxels, and lookups read a cell's irradiance only
        // where its normal says it was gathered, but every texel must be finite for the NaN/Inf check.
        const float none[4] = {0.0f, 0.0f, 0.0f, -1.0f};
        for (gl::Texture* t : {&v.irradiance, &v.irradianceBack, &v.irradianceNormal}) {
            *t = gl::Texture::create3D(GL_RGBA16F, cells);
            t->setFilter(GL_NEAREST, GL_NEAREST);
            glClearTexImage(t->id(), 0, GL_RGBA, GL_FLOAT, none);
        }
    }
    // Cells without voxels get "no surface" (w = 0) in the normals; the gather runs over the others only.
    m_occupied.build(frame.shaders, v.albedo, VoxelRegion::whole(cells), cellSize, &v.irradianceNormal, glm::vec4(0.0f));
    // The same volume the per-pixel cones would trace: after the second bounce when there is one.
    ConeTracingSetup::apply(program, frame, anisotropic, true);
    program.set("uResolution", res);
    program.set("uCellSize", cellSize);
    program.set("uAoEnabled", FrameRules::ambientOcclusionNeeded(frame) ? 1 : 0);
    program.set("uAoDistance", 0.1f * v.frame.extent);
    v.albedo.bindUnit(0);
    v.normal.bindUnit(1);
    v.irradiance.bindImage(0, 0, GL_WRITE_ONLY);
    v.irradianceBack.bindImage(1, 0, GL_WRITE_ONLY);
    v.irradianceNormal.bindImage(2, 0, GL_WRITE_ONLY);
    program.use();
    m_occupied.dispatchOverCells();
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    m_radianceVersion = v.radianceVersion;
    m_key = keyOf(frame);
}

} // namespace vct::render
