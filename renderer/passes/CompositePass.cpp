#include "passes/CompositePass.h"

#include "core/ConeTracingSetup.h"
#include "core/FrameContext.h"
#include "core/LightUniforms.h"
#include "core/PixelClass.h"
#include "core/ResourceNames.h"
#include "scene/PhongLtcTable.h"

#include "common/Bindings.glsl"

#include <algorithm>
#include <set>

namespace vct::render {

using namespace resource;

PassDeclaration CompositePass::declare() const
{
    return { { kSurface, kDepth, kIndirectDiffuse, kIndirectGuide, kSpecular, kSpecularGuide, kAreaShadow,
                 kAreaShadowGuide, kPointShadows, kDirectionalShadows },
        { kFinal, kPhongLtc, kPhongLtcAlbedo } };
}

std::vector<TextureSlot> CompositePass::textures(const FrameContext& frame)
{
    ScreenTargets& s = frame.screen;
    // The glossy lobe's fits are read only where area lights are.
    const bool areaLights = frame.shape.areaLights > 0;
    const auto table = [&](GLenum format) {
        return areaLights ? gl::TextureDesc::plane(format, PhongLtcTable::kSize, PhongLtcTable::kSize)
                          : gl::TextureDesc {};
    };
    return { { kFinal, ResourceGroup::Screen, &s.final,
                 gl::TextureDesc::plane(GL_RGBA32F, s.width, s.height) },
        { kPhongLtc, ResourceGroup::PassState, &m_phongLtc, table(GL_RGBA32F) },
        { kPhongLtcAlbedo, ResourceGroup::PassState, &m_phongLtcAlbedo, table(GL_R32F) } };
}

void CompositePass::uploadPhongLtc()
{
    if (!m_phongLtc || m_phongLtcUploaded == m_phongLtc.serial())
        return;
    std::vector<float> fits, albedos;
    for (const PhongLtcTable::Cell& cell : PhongLtcTable::cells()) {
        fits.insert(fits.end(), { cell.m00, cell.m02, cell.m20, cell.m22 });
        albedos.push_back(cell.albedo);
    }
    constexpr int n = PhongLtcTable::kSize;
    glTextureSubImage2D(m_phongLtc.id(), 0, 0, 0, n, n, GL_RGBA, GL_FLOAT, fits.data());
    glTextureSubImage2D(m_phongLtcAlbedo.id(), 0, 0, 0, n, n, GL_RED, GL_FLOAT, albedos.data());
    m_phongLtc.setWrap(GL_CLAMP_TO_EDGE);
    m_phongLtcAlbedo.setWrap(GL_CLAMP_TO_EDGE);
    m_phongLtcUploaded = m_phongLtc.serial();
}

std::vector<std::string> CompositePass::variantDefines(const FrameContext& frame, std::uint32_t pixelClass)
{
    const RenderSettings& settings = frame.settings;
    const Scene& scene = frame.scene.scene();
    const int points = std::min<int>(int(scene.pointLights.size()), kMaxPointLights);
    const int directionals = std::min<int>(int(scene.directionalLights.size()), kMaxDirectionalLights);
    const int areas = frame.shape.areaLights;
    std::vector<std::string> defines { "POINT_LIGHT_COUNT " + std::to_string(points),
        "DIRECTIONAL_LIGHT_COUNT " + std::to_string(directionals),
        "AREA_LIGHT_COUNT " + std::to_string(areas), "VIEW " + std::to_string(int(settings.view)) };
    if (settings.direct && points + directionals + areas > 0)
        defines.emplace_back("DIRECT");
    if (softShadowsUsed(scene))
        defines.emplace_back("SOFT_SHADOWS");
    // The indirect targets hold this frame's light only when the cone pass ran for them.
    if (settings.indirectDiffuse && frame.shape.diffuseCones)
        defines.emplace_back("INDIRECT_DIFFUSE");
    if (frame.shape.specularCones)
        defines.emplace_back("INDIRECT_SPECULAR");
    if (frame.shape.ambientOcclusion)
        defines.emplace_back("AO_AVAILABLE");
    if ((pixelClass & PIXEL_GLOSSY) != 0)
        defines.emplace_back("GLOSSY");
    if ((pixelClass & PIXEL_EMISSIVE) != 0 && frame.shape.emission)
        defines.emplace_back("EMISSION");
    if (frame.screen.indirectDivisor > 1)
        defines.emplace_back("UPSAMPLE");
    if (frame.screen.specularDivisor > 1)
        defines.emplace_back("SPECULAR_UPSAMPLE");
    if (frame.screen.areaDivisor > 1)
        defines.emplace_back("AREA_UPSAMPLE");
    return defines;
}

void CompositePass::execute(FrameContext& frame)
{
    if (!m_emptyVao)
        m_emptyVao = gl::VertexArray::create();
    ScreenTargets& s = frame.screen;
    s.surface.bindUnit(1);
    frame.scene.bindMaterialTable(kMaterialTableUnit);
    s.indirectDiffuse.bindUnit(5);
    s.specular.bindUnit(6);
    s.indirectGuide.bindUnit(7);
    s.specularGuide.bindUnit(10);
    s.areaShadow.bindUnit(2);
    s.areaShadowGuide.bindUnit(4);
    uploadPhongLtc();
    if (m_phongLtc) {
        m_phongLtc.bindUnit(PHONG_LTC_UNIT);
        m_phongLtcAlbedo.bindUnit(PHONG_LTC_ALBEDO_UNIT);
    }
    // The g-buffer's depth and stencil come along, read only: its pixel classes pick each variant's pixels.
    s.finalTarget.follow({ &s.final }, &s.depth);
    s.finalTarget.bind();
    glViewport(0, 0, s.width, s.height);
    const float sky[4] = { 0.0f, 0.0f, 0.0f, 1.0f };
    glClearNamedFramebufferfv(s.finalTarget.id(), GL_COLOR, 0, sky);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilMask(0x00);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    m_emptyVao.bind();
    const Scene& scene = frame.scene.scene();
    std::set<std::uint32_t> classes;
    for (std::size_t mesh = 0; mesh < frame.scene.meshCount(); ++mesh)
        classes.insert(pixelClassOf(frame.scene.materialOf(mesh)));
    for (const std::uint32_t pixelClass : classes) {
        std::vector<std::string> defines = variantDefines(frame, pixelClass);
        const gl::Program& program = frame.shaders.program(
            { "composite", { "common/FullScreen.vert", "composite/Composite.frag" }, std::move(defines) });
        program.use();
        applyLightUniforms(program, scene, frame.shadows);
        program.set("uCameraPosition", frame.camera.position);
        program.set("uPixelToRay", frame.pixelToRay);
        program.set("uDivisor", s.indirectDivisor);
        program.set("uSpecularDivisor", s.specularDivisor);
        program.set("uAreaDivisor", s.areaDivisor);
        // The upsampler measures how far a traced surface lies from this pixel in voxels.
        program.set("uVoxelSize", frame.voxels.frame.voxelSize());
        program.set("uAreaShadowOffset", ConeTracingSetup::coneOffsetMetres(frame));
        applyAreaLightUniforms(program, frame);
        program.set("uPhongLtcSize", float(PhongLtcTable::kSize));
        program.set("uPhongLtcMinWidth", float(PhongLtcTable::minWidth()));
        glStencilFunc(GL_EQUAL, GLint(pixelClass), 0xFF);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glStencilMask(0xFF);
    glDisable(GL_STENCIL_TEST);
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace vct::render
