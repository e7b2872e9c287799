#include "passes/VoxelIrradiancePass.h"

#include "core/ConeTracingSetup.h"
#include "core/FrameContext.h"
#include "core/ResourceNames.h"

#include <algorithm>

namespace vct::render {

VoxelIrradiancePass::GatherKey VoxelIrradiancePass::keyOf(const FrameContext& frame)
{
    return { ConeTraceKey::of(frame), frame.settings.bounces, frame.shape.ambientOcclusion,
        frame.settings.irradianceCellSize, frame.voxels.frame };
}

VoxelIrradiancePass::ViewKey VoxelIrradiancePass::viewOf(const FrameContext& frame)
{
    return { frame.projection * frame.view, frame.screen.width, frame.screen.height,
        frame.screen.indirectDivisor, frame.versions.staticGeometry, frame.versions.dynamicGeometry };
}

PassDecision VoxelIrradiancePass::plan(const FrameContext& frame) const
{
    const VoxelVolume& v = frame.voxels;
    if (!frame.shape.irradianceCache)
        return { PassDecision::Action::Skip,
            !frame.settings.irradianceCache ? "irradiance cache off: cones per pixel"
                                            : "no diffuse light needed" };
    const bool lightKept = v.irradiance && v.radianceVersion == m_radianceVersion
        && v.bouncedVersion == m_bouncedVersion && keyOf(frame) == m_key;
    if (!lightKept)
        return { PassDecision::Action::Run,
            std::string(v.irradiance ? "voxel light or a gather setting changed" : "no valid output yet")
                + ": gathering the cells in view" };
    if (viewOf(frame) == m_view)
        return { PassDecision::Action::Reuse, "voxel light and view unchanged" };
    return { PassDecision::Action::Run, "view changed: gathering only the cells that came into view" };
}

PassDeclaration VoxelIrradiancePass::declare() const
{
    using namespace resource;
    return { { kSurface, kRadiance, kRadianceDirectional, kBounced, kBouncedDirectional, kEnclosure },
        { kIrradiance, kIrradianceBack, kIrradianceNormals, kIrradianceRequested } };
}

std::vector<TextureSlot> VoxelIrradiancePass::textures(const FrameContext& frame)
{
    using gl::TextureDesc;
    using namespace resource;
    VoxelVolume& v = frame.voxels;
    const int res = v.frame.resolution;
    const int cells = res / std::min(frame.settings.irradianceCellSize, res);
    // Without the cache the cone pass traces per pixel: the memory is not needed.
    const bool used = frame.shape.irradianceCache;
    const auto ifUsed = [used](const TextureDesc& desc) { return used ? desc : TextureDesc {}; };
    // Normals and sides fit 8-bit snorm (common/IrradianceLookup.glsl).
    const TextureDesc cell = TextureDesc::volume(GL_RGBA16F, cells).sampled(TextureDesc::Sampling::Nearest);
    return { { kIrradiance, ResourceGroup::Voxels, &v.irradiance, ifUsed(cell) },
        { kIrradianceBack, ResourceGroup::Voxels, &v.irradianceBack, ifUsed(cell) },
        { kIrradianceNormals, ResourceGroup::Voxels, &v.irradianceNormal,
            ifUsed(TextureDesc::volume(GL_RGBA8_SNORM, cells).sampled(TextureDesc::Sampling::Nearest)) },
        { kIrradianceRequested, ResourceGroup::Voxels, &v.irradianceRequested,
            ifUsed(TextureDesc::volume(GL_R32UI, cells)) } };
}

void VoxelIrradiancePass::release(FrameContext& frame)
{
    (void)frame;
    m_radianceVersion = 0;
}

void VoxelIrradiancePass::forgetCells(VoxelVolume& v)
{
    // Every texel must be finite for the NaN/Inf check; lookups never read a cell that was not requested.
    const float none[4] = { 0.0f, 0.0f, 0.0f, -1.0f };
    const float noSurface[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
    glClearTexImage(v.irradiance.id(), 0, GL_RGBA, GL_FLOAT, none);
    glClearTexImage(v.irradianceBack.id(), 0, GL_RGBA, GL_FLOAT, none);
    glClearTexImage(v.irradianceNormal.id(), 0, GL_RGBA, GL_FLOAT, noSurface);
    const GLuint notRequested = 0;
    glClearTexImage(v.irradianceRequested.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &notRequested);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

void VoxelIrradiancePass::requestCells(FrameContext& frame, int cells, int cellVoxels, bool fewNew)
{
    if (!m_emptyVao)
        m_emptyVao = gl::VertexArray::create();
    const std::vector<std::string> stages { "common/FullScreen.vert", "irradiance/RequestCells.frag" };
    const gl::Program& request = fewNew
        ? frame.shaders.program({ "irradiance cache: request and list new cells", stages, { "LIST_NEW" } })
        : frame.shaders.program({ "irradiance cache: request cells", stages, {} });
    const gl::Program& lister = fewNew
        ? frame.shaders.program({ "irradiance cache: list requested cells, from the new ones",
            { "irradiance/ListRequested.comp" }, { "FROM_LIST" } })
        : frame.shaders.program(
            { "irradiance cache: list requested cells", { "irradiance/ListRequested.comp" }, {} });
    const std::size_t capacity = std::size_t(cells) * std::size_t(cells) * std::size_t(cells);
    VoxelVolume& v = frame.voxels;
    const ScreenTargets& s = frame.screen;
    // The traced pixels' grid: the cone pass, which runs after this one, makes its targets at this size.
    const int width = ScreenTargets::tracedSize(s.width, s.indirectDivisor);
    const int height = ScreenTargets::tracedSize(s.height, s.indirectDivisor);
    if (!m_requestTarget || m_requestWidth != width || m_requestHeight != height) {
        m_requestTarget = gl::Framebuffer::createEmpty(width, height);
        m_requestWidth = width;
        m_requestHeight = height;
    }
    if (fewNew)
        m_newCells.reset(capacity);
    request.use();
    request.set("uGroupSize", OccupiedCellList::kGroupSize);
    request.set("uGridOrigin", v.frame.origin);
    request.set("uCellSize", v.frame.extent / float(cells));
    request.set("uCellsPerSide", cells);
    ConeTracingSetup::applyCacheBand(request, frame);
    request.set("uDivisor", s.indirectDivisor);
    request.set("uFullSize", glm::ivec3(s.width, s.height, 0));
    s.surface.bindUnit(1);
    request.set("uCameraPosition", frame.camera.position);
    request.set("uPixelToRay", frame.pixelToRay);
    v.irradianceRequested.bindImage(3, 0, GL_READ_WRITE);
    m_requestTarget.bind();
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    m_emptyVao.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glMemoryBarrier(
        GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);

    v.albedo.bindUnit(0);
    lister.use();
    lister.set("uCellSize", cellVoxels);
    if (fewNew) {
        m_requested.reset(capacity, 2);
        lister.set("uGroupSize", OccupiedCellList::kGroupSize);
        m_newCells.dispatchOverCells();
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    } else {
        m_requested.buildWith(lister, VoxelRegion::whole(cells));
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
}

void VoxelIrradiancePass::execute(FrameContext& frame)
{
    VoxelVolume& v = frame.voxels;
    const bool anisotropic = frame.settings.anisotropicMips && v.coneDirectional();
    std::vector<std::string> defines;
    if (anisotropic)
        defines.emplace_back("ANISOTROPIC");
    ConeTracingSetup::addDefines(defines, frame);
    const std::string name = anisotropic ? "irradiance cache (anisotropic)" : "irradiance cache";
    const gl::Program& program = frame.shaders.program({ name, { "irradiance/GatherCells.comp" }, defines });
    const gl::Program& backSides = frame.shaders.program({ name + ", back sides",
        { "irradiance/GatherCells.comp" }, BackSideCells::backSideDefines(defines) });
    const int res = v.frame.resolution;
    const int cellSize = std::min(frame.settings.irradianceCellSize, res);
    const int cells = res / cellSize;
    const bool fresh = !(v.radianceVersion == m_radianceVersion && v.bouncedVersion == m_bouncedVersion
        && keyOf(frame) == m_key && v.irradiance.serial() == m_cellsSerial);
    if (fresh)
        forgetCells(v);
    m_cellsSerial = v.irradiance.serial();
    requestCells(frame, cells, cellSize, !fresh);

    // The same volume the per-pixel cones would trace: after the second bounce when there is one.
    ConeTracingSetup::applyCellGather(program, frame, anisotropic, cellSize, frame.shape.ambientOcclusion,
        v.irradiance, v.irradianceBack, v.irradianceNormal);
    m_backSides.bindForGather(program, std::size_t(cells) * std::size_t(cells) * std::size_t(cells));
    program.use();
    m_requested.dispatchOverCells();
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT
        | GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    ConeTracingSetup::applyCellGather(backSides, frame, anisotropic, cellSize, frame.shape.ambientOcclusion,
        v.irradiance, v.irradianceBack, v.irradianceNormal);
    v.irradianceNormal.bindUnit(2); // the geometry the first dispatch found
    backSides.use();
    m_backSides.dispatch();
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    m_radianceVersion = v.radianceVersion;
    m_bouncedVersion = v.bouncedVersion;
    m_key = keyOf(frame);
    m_view = viewOf(frame);
}

} // namespace vct::render
