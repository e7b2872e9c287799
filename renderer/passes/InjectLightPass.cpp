#include "passes/InjectLightPass.h"

#include "core/FrameContext.h"
#include "core/FrameRules.h"
#include "core/LightUniforms.h"

namespace vct::render {

std::array<std::uint64_t, 4> InjectLightPass::keyOf(const FrameContext& frame) const
{
    return {frame.voxels.materialsVersion, frame.versions.lightValues, frame.versions.shading, frame.shadows.version};
}

PassDecision InjectLightPass::plan(const FrameContext& frame)
{
    if (keyOf(frame) == m_key)
        return {PassDecision::Action::Reuse, "voxels, lights and shadows unchanged"};
    std::string reason = m_key == decltype(m_key){} ? "no valid output yet" : "voxels or lights changed";
    if (!FrameRules::emissionNeeded(frame))
        reason += "; no emission to inject";
    if (!FrameRules::hasLightSources(frame))
        reason += "; no light sources: opacity only";
    return {PassDecision::Action::Run, reason};
}

void InjectLightPass::execute(FrameContext& frame)
{
    if (!m_program)
        m_program = frame.shaders.build({"inject light", {"inject/InjectLight.comp"}, {}});
    m_key = keyOf(frame);
    VoxelVolume& v = frame.voxels;
    m_program.use();
    applyLightUniforms(m_program, frame.scene.scene(), frame.shadows);
    m_program.set("uResolution", v.frame.resolution);
    m_program.set("uGridOrigin", v.frame.origin);
    m_program.set("uVoxelSize", v.frame.voxelSize());
    m_program.set("uEmissionEnabled", FrameRules::emissionNeeded(frame) ? 1 : 0);
    m_program.set("uDirectEnabled", frame.settings.direct ? 1 : 0);
    v.albedo.bindUnit(0);
    v.normal.bindUnit(1);
    v.emission.bindUnit(2);
    v.radiance.bindImage(0, 0, GL_WRITE_ONLY);
    const GLuint groups = GLuint((v.frame.resolution + 3) / 4);
    glDispatchCompute(groups, groups, groups);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    ++v.radianceVersion;
}

} // namespace vct::render
