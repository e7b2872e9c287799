#include "passes/VoxelizePass.h"

#include "core/FrameContext.h"
#include "core/Frustum.h"
#include "core/ResourceNames.h"

namespace vct::render {

namespace {

// Margin around a moving object's bounds: conservative enlargement and depth spread reach one voxel out.
constexpr int kDynamicMargin = 2;

} // namespace

PassDecision VoxelizePass::plan(const FrameContext& frame) const
{
    if (m_staticGeometry == 0)
        return { PassDecision::Action::Run, "no valid output yet" };
    if (m_staticGeometry != frame.versions.staticGeometry)
        return { PassDecision::Action::Run, "static geometry or grid changed" };
    if (!(m_grid == frame.voxels.frame))
        return { PassDecision::Action::Run, "the grid moved with the camera" };
    if (m_conservative != frame.settings.conservativeVoxelization)
        return { PassDecision::Action::Run, "voxelization mode changed" };
    if (m_staticMaterials != frame.versions.staticMaterials)
        return { PassDecision::Action::Run,
            "a static material changed: re-voxelizing the objects that use it" };
    if (m_dynamicVersion != frame.versions.dynamicVoxels())
        return { PassDecision::Action::Run, "a dynamic object moved: redoing the voxels around it" };
    return { PassDecision::Action::Reuse, "geometry unchanged" };
}

PassDeclaration VoxelizePass::declare() const
{
    return { {}, { resource::kAlbedo, resource::kNormal, resource::kEmission } };
}

std::vector<TextureSlot> VoxelizePass::textures(const FrameContext& frame)
{
    using gl::TextureDesc;
    VoxelVolume& v = frame.voxels;
    const int res = v.frame.resolution;
    // Formats chosen by measured cost and error (docs/DESIGN.md, "Lean voxels"); common/VoxelWords.glsl.
    // Only scenes with emissive materials keep an emission volume. Made when a material starts to emit, it
    // holds no light yet anywhere, which is right: nothing emitted before, and the voxels of the material's
    // meshes are redone now.
    const bool emission = frame.scene.scene().hasEmissiveMaterial();
    return { { resource::kAlbedo, ResourceGroup::Voxels, &v.albedo, TextureDesc::volume(GL_RGBA8, res) },
        { resource::kNormal, ResourceGroup::Voxels, &v.normal, TextureDesc::volume(GL_RGBA8_SNORM, res) },
        { resource::kEmission, ResourceGroup::Voxels, &v.emission,
            emission ? TextureDesc::volume(GL_R11F_G11F_B10F, res)
                           .sampled(TextureDesc::Sampling::Nearest)
                           .zeroedWhenMade()
                     : TextureDesc {} } };
}

bool VoxelizePass::redoesWholeGrid(const FrameContext& frame) const
{
    // As execute() decides: a static change or a new mode rebuilds everything, anything else a region.
    return m_staticGeometry != frame.versions.staticGeometry
        || m_conservative != frame.settings.conservativeVoxelization || !(m_grid == frame.voxels.frame);
}

void VoxelizePass::ensureResources(FrameContext& frame)
{
    if (!m_voxelize) {
        const std::vector<std::string> stages { "voxelize/Voxelize.vert", "voxelize/Voxelize.geom",
            "voxelize/Voxelize.frag" };
        m_voxelize = &frame.shaders.program({ "voxelize", stages, {} });
        m_voxelizeEmissive = &frame.shaders.program({ "voxelize (emissive)", stages, { "EMISSIVE" } });
        m_resolve = &frame.shaders.program({ "voxel resolve", { "voxelize/Resolve.comp" }, {} });
    }
    VoxelVolume& v = frame.voxels;
    if (v.albedo.serial() == m_albedoSerial)
        return;
    // New textures (the pipeline invalidated the pass, so it rebuilds them whole): nothing moved in them yet.
    v.dynamicBounds = Aabb {};
    m_framebuffer = gl::Framebuffer::createEmpty(v.frame.resolution, v.frame.resolution);
    m_albedoSerial = v.albedo.serial();
}

void VoxelizePass::clear(FrameContext& frame, const VoxelRegion& region)
{
    // The voxelizer averages into what the region holds, so it starts empty. A clear is far cheaper on
    // llvmpipe than a shader writing three images per voxel.
    const VoxelVolume& v = frame.voxels;
    const glm::ivec3 lo = region.lo, size = region.size();
    const float zero[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
    for (const gl::Texture* t : { &v.albedo, &v.normal, &v.emission })
        if (*t)
            glClearTexSubImage(t->id(), 0, lo.x, lo.y, lo.z, size.x, size.y, size.z,
                t == &v.emission ? GL_RGB : GL_RGBA, GL_FLOAT, zero);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void VoxelizePass::accumulate(
    FrameContext& frame, MeshFilter layer, const VoxelRegion& region, OccupiedCellList& touched)
{
    VoxelVolume& v = frame.voxels;
    const int res = v.frame.resolution;
    const glm::ivec3 size = region.size();
    touched.reset(std::size_t(size.x) * std::size_t(size.y) * std::size_t(size.z));
    m_framebuffer.bind();
    glViewport(0, 0, res, res);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    const bool nvConservative = GLAD_GL_NV_conservative_raster && frame.settings.conservativeVoxelization;
    if (nvConservative)
        glEnable(GL_CONSERVATIVE_RASTERIZATION_NV);
    // The three material textures are written as 32-bit words (common/VoxelWords.glsl).
    v.albedo.bindImage(0, 0, GL_READ_WRITE, GL_R32UI);
    v.normal.bindImage(1, 0, GL_READ_WRITE, GL_R32UI);
    if (v.emission)
        v.emission.bindImage(2, 0, GL_READ_WRITE, GL_R32UI);
    // Clusters of triangles that cannot reach the region are not drawn; conservative enlargement and the
    // depth spread reach one voxel beyond a triangle.
    const float voxel = v.frame.voxelSize();
    const Aabb reach { v.frame.origin + glm::vec3(region.lo - 1) * voxel,
        v.frame.origin + glm::vec3(region.hi + 1) * voxel };
    const Frustum regionBox = Frustum::ofBox(reach);
    for (const bool emissive : { false, true }) {
        const gl::Program& program = emissive ? *m_voxelizeEmissive : *m_voxelize;
        program.use();
        program.set("uGridOrigin", v.frame.origin);
        program.set("uGridExtent", v.frame.extent);
        program.set("uResolution", res);
        program.set("uEmissionVolume", v.emission ? 1 : 0);
        program.set("uRegionLo", region.lo);
        program.set("uRegionHi", region.hi);
        program.set("uGroupSize", OccupiedCellList::kGroupSize);
        // With hardware conservative raster the geometry shader need not enlarge triangles itself.
        program.set("uConservative", frame.settings.conservativeVoxelization && !nvConservative ? 1 : 0);
        DrawOptions options;
        options.layer = layer;
        options.materials = [emissive](const Material& m) { return m.isEmissive() == emissive; };
        options.visibleIn = &regionBox;
        frame.scene.draw(program, options, 0);
    }
    if (nvConservative)
        glDisable(GL_CONSERVATIVE_RASTERIZATION_NV);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glMemoryBarrier(
        GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

void VoxelizePass::resolve(FrameContext& frame, const OccupiedCellList& touched)
{
    frame.voxels.albedo.bindImage(0, 0, GL_READ_WRITE, GL_R32UI);
    frame.voxels.normal.bindImage(1, 0, GL_READ_WRITE, GL_R32UI);
    m_resolve->use();
    touched.dispatchOverCells();
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

void VoxelizePass::execute(FrameContext& frame)
{
    ensureResources(frame);
    VoxelVolume& v = frame.voxels;
    const bool hasDynamic = frame.scene.hasDynamicMeshes();
    const Aabb dynamicBounds = frame.scene.scene().bounds(true);
    const bool staticChanged = m_staticGeometry != frame.versions.staticGeometry
        || m_conservative != frame.settings.conservativeVoxelization || !(m_grid == v.frame);
    const bool dynamicMoved = hasDynamic && m_dynamicVersion != frame.versions.dynamicVoxels();
    // What to redo: the whole grid after a static change; else around the static meshes whose material
    // changed, and around the moving objects, now and before a move. The region is cleared and everything in
    // it voxelized again, static and dynamic meshes together, so a voxel both reach holds the mean of both,
    // as after a full rebuild. There is no static layer to copy back from: redrawing the static triangles
    // near the region (culled by cluster, then by triangle in the geometry shader) costs less memory than
    // keeping a copy of the whole grid.
    VoxelRegion region;
    if (staticChanged) {
        region = VoxelRegion::whole(v.frame.resolution);
    } else {
        if (m_staticMaterials != frame.versions.staticMaterials)
            region = VoxelRegion::around(frame.staticMaterialEdits, v.frame, kDynamicMargin);
        if (hasDynamic)
            region = region.united(VoxelRegion::around(dynamicBounds, v.frame, kDynamicMargin));
        if (dynamicMoved)
            region = region.united(VoxelRegion::around(v.dynamicBounds, v.frame, kDynamicMargin));
    }
    if (!region.isEmpty()) {
        clear(frame, region);
        // A full rebuild lists every static voxel; a partial one finds only voxels that list already names.
        OccupiedCellList& staticTouched = staticChanged ? v.staticVoxels : m_regionStaticVoxels;
        accumulate(frame, MeshFilter::Static, region, staticTouched);
        // The dynamic list names every dynamic voxel: the region always holds the objects as they are now.
        if (hasDynamic)
            accumulate(frame, MeshFilter::Dynamic, region, v.dynamicVoxels);
        resolve(frame, staticTouched);
        if (hasDynamic)
            resolve(frame, v.dynamicVoxels);
    }
    m_staticGeometry = frame.versions.staticGeometry;
    m_staticMaterials = frame.versions.staticMaterials;
    m_conservative = frame.settings.conservativeVoxelization;
    m_grid = v.frame;
    v.occupiedCountStale = v.occupiedCountStale || !region.isEmpty();
    v.changedRegion = region;
    v.onlyDynamicChanged = !staticChanged;
    v.dynamicMoved = dynamicMoved;
    v.previousDynamicBounds = v.dynamicBounds;
    v.dynamicBounds = dynamicBounds;
    m_dynamicVersion = frame.versions.dynamicVoxels();
    ++v.materialsVersion;
}
} // namespace vct::render
