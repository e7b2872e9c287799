#include "passes/ConeTracePass.h"

#include "core/ConeTracingSetup.h"
#include "core/FrameContext.h"
#include "core/LightUniforms.h"
#include "core/PixelClass.h"
#include "core/ResourceNames.h"
#include "debug/ConeSampleCounter.h"
#include "passes/VoxelIrradiancePass.h"

#include <tuple>

#include <glm/trigonometric.hpp>

#include <cmath>

namespace vct::render {

using namespace resource;

PassDeclaration ConeTracePass::declare() const
{
    return { { kSurface, kRadiance, kRadianceDirectional, kBounced, kBouncedDirectional, kIrradiance,
                 kIrradianceBack, kIrradianceNormals, kEnclosure },
        { kIndirectDiffuse, kIndirectGuide, kIndirectStencil, kSpecular, kSpecularGuide, kSpecularStencil } };
}

std::vector<TextureSlot> ConeTracePass::textures(const FrameContext& frame)
{
    ScreenTargets& s = frame.screen;
    // The diffuse grid carries the composite's upsampling guide whenever the pass runs.
    const bool runs = frame.shape.diffuseCones || frame.shape.specularCones;
    std::vector<TextureSlot> slots = s.tracedGrid({ kIndirectDiffuse, kIndirectGuide, kIndirectStencil },
        s.indirectDiffuse, s.indirectGuide, s.indirectStencil, s.indirectDivisor, runs);
    for (TextureSlot& slot : s.tracedGrid({ kSpecular, kSpecularGuide, kSpecularStencil }, s.specular,
             s.specularGuide, s.specularStencil, s.specularDivisor, frame.shape.specularCones))
        slots.push_back(slot);
    return slots;
}

PassDecision ConeTracePass::plan(const FrameContext& frame) const
{
    const bool diffuse = frame.shape.diffuseCones;
    const bool specular = frame.shape.specularCones;
    if (!diffuse && !specular) {
        if (!frame.shape.lightSources)
            return { PassDecision::Action::Skip, "no lights and no emission: no indirect light at all" };
        return { PassDecision::Action::Skip, "indirect diffuse off, no glossy material, AO not shown" };
    }
    std::string reason = "per-frame: ";
    reason += diffuse ? (specular ? "diffuse and specular cones" : "diffuse cones") : "specular cones";
    if (!specular)
        reason += frame.settings.indirectSpecular ? " (no glossy material: no specular cones)"
                                                  : " (specular off)";
    if (diffuse && !frame.shape.ambientOcclusion)
        reason += ", no AO";
    if (diffuse && frame.shape.irradianceCache)
        reason += ", diffuse looked up in the irradiance cache";
    return { PassDecision::Action::Run, reason };
}

namespace {

const gl::Program& variant(
    const FrameContext& frame, const char* name, const char* file, bool anisotropic, bool counting)
{
    std::vector<std::string> defines;
    ConeTracingSetup::addDefines(defines, frame);
    std::string label = name;
    if (anisotropic) {
        defines.emplace_back("ANISOTROPIC");
        label += " (anisotropic)";
    }
    if (counting) {
        defines.emplace_back("COUNT_SAMPLES");
        label += ", counting samples";
    }
    return frame.shaders.program({ label, { "common/FullScreen.vert", file }, defines });
}

} // namespace

void ConeTracePass::execute(FrameContext& frame)
{
    const RenderSettings& settings = frame.settings;
    const VoxelVolume& v = frame.voxels;
    const bool anisotropic = settings.anisotropicMips && v.coneDirectional();
    const bool counting = frame.coneSampleCounter != nullptr;
    const bool cached = frame.shape.irradianceCache && v.irradiance;
    const bool diffuse = frame.shape.diffuseCones;
    const bool specular = frame.shape.specularCones;
    if (!m_emptyVao)
        m_emptyVao = gl::VertexArray::create();
    ScreenTargets& s = frame.screen;
    s.surface.bindUnit(1);
    frame.scene.bindMaterialTable(kMaterialTableUnit);
    if (counting)
        frame.coneSampleCounter->bind();
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    m_emptyVao.bind();

    // Each grid: first the classify draw, whose own stencil value (ARB_shader_stencil_export) replaces what
    // was there, then the cones on the pixels of their class only.
    const auto classifyGrid = [&](const gl::Program& classify, int divisor) {
        glStencilMask(0xFF);
        glStencilFunc(GL_ALWAYS, 0, 0xFF);
        glStencilOp(GL_REPLACE, GL_REPLACE, GL_REPLACE);
        classify.use();
        classify.set("uDivisor", divisor);
        classify.set("uFullSize", glm::ivec3(s.width, s.height, 0));
        classify.set("uCameraPosition", frame.camera.position);
        classify.set("uPixelToRay", frame.pixelToRay);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glStencilMask(0x00);
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    };
    const auto traceClass = [&](const gl::Program& cones, int divisor, std::uint32_t pixelClass) {
        glStencilFunc(GL_EQUAL, GLint(pixelClass), GLuint(pixelClass));
        ConeTracingSetup::apply(cones, frame, anisotropic);
        cones.set("uDivisor", divisor);
        cones.set("uFullSize", glm::ivec3(s.width, s.height, 0));
        cones.set("uCameraPosition", frame.camera.position);
        cones.set("uPixelToRay", frame.pixelToRay);
        cones.use();
        glDrawArrays(GL_TRIANGLES, 0, 3);
    };

    // The diffuse grid: the guide always (the composite upsamples it), diffuse light where needed.
    const gl::Program& classify = frame.shaders.program(
        { cached ? "cone trace: classify pixels, irradiance cache" : "cone trace: classify pixels",
            { "common/FullScreen.vert", "cone/ClassifyPixels.frag" },
            cached ? std::vector<std::string> { "IRRADIANCE_CACHE" } : std::vector<std::string> {} });
    if (cached) {
        v.irradiance.bindUnit(kIrradianceUnit);
        v.irradianceNormal.bindUnit(kCellNormalUnit);
        v.irradianceBack.bindUnit(kIrradianceBackUnit);
        classify.set("uCells", v.irradiance.width());
        classify.set("uCellSize", v.frame.extent / float(v.irradiance.width()));
        ConeTracingSetup::applyCacheBand(classify, frame);
    }
    classify.set("uGridOrigin", v.frame.origin);
    classify.set("uDiffuseEnabled", diffuse ? 1 : 0);
    s.indirectTarget.follow({ &s.indirectDiffuse, &s.indirectGuide }, &s.indirectStencil);
    s.indirectTarget.bind();
    glViewport(0, 0, s.indirectDiffuse.width(), s.indirectDiffuse.height());
    s.indirectTarget.drawTo({ 0, 1 });
    classifyGrid(classify, s.indirectDivisor);
    if (diffuse) {
        const gl::Program& cones
            = variant(frame, "cone trace: diffuse cones", "cone/DiffuseCones.frag", anisotropic, counting);
        s.indirectTarget.drawTo({ 0 });
        cones.set("uAoEnabled", frame.shape.ambientOcclusion ? 1 : 0);
        cones.set("uAoDistance", 0.1f * frame.sceneGrid.extent);
        traceClass(cones, s.indirectDivisor, PIXEL_NEEDS_CONES);
    }
    s.indirectTarget.drawTo({ 0, 1 });

    // The specular grid, when some material is glossy: pixels no cone reaches read as no specular light.
    if (specular) {
        const gl::Program& classifySpecular
            = frame.shaders.program({ "cone trace: classify pixels, specular grid",
                { "common/FullScreen.vert", "cone/ClassifyPixels.frag" }, { "SPECULAR_GRID" } });
        const gl::Program& cone
            = variant(frame, "cone trace: specular cone", "cone/SpecularCone.frag", anisotropic, counting);
        s.specularTarget.follow({ &s.specular, &s.specularGuide }, &s.specularStencil);
        s.specularTarget.bind();
        glViewport(0, 0, s.specular.width(), s.specular.height());
        const float none[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
        glClearNamedFramebufferfv(s.specularTarget.id(), GL_COLOR, 0, none);
        s.specularTarget.drawTo({ 1 });
        classifyGrid(classifySpecular, s.specularDivisor);
        s.specularTarget.drawTo({ 0 });
        cone.set("uSpecularMinTanHalf", std::tan(glm::radians(settings.specularApertureDeg * 0.5f)));
        cone.set("uCameraPosition", frame.camera.position);
        cone.set("uAoEnabled", 0);
        traceClass(cone, s.specularDivisor, PIXEL_GLOSSY);
        s.specularTarget.drawTo({ 0, 1 });
    }
    glStencilMask(0xFF);
    glDisable(GL_STENCIL_TEST);
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace vct::render
