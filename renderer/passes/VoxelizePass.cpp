#include "passes/VoxelizePass.h"

#include "core/FrameContext.h"

namespace vct::render {

namespace {

// Margin around a moving object's bounds: conservative enlargement and depth spread reach one voxel out.
constexpr int kDynamicMargin = 2;

} // namespace

PassDecision VoxelizePass::plan(const FrameContext& frame)
{
    if (m_staticGeometry == 0)
        return {PassDecision::Action::Run, "no valid output yet"};
    if (m_staticGeometry != frame.versions.staticGeometry)
        return {PassDecision::Action::Run, "static geometry or grid changed"};
    if (m_staticMaterials != frame.versions.staticMaterials)
        return {PassDecision::Action::Run, "a static material changed: re-voxelizing the objects that use it"};
    if (m_dynamicVersion != frame.versions.dynamicVoxels())
        return {PassDecision::Action::Run, "a dynamic object moved: static voxels kept, dynamic ones redone"};
    return {PassDecision::Action::Reuse, "geometry unchanged"};
}

void VoxelizePass::ensureResources(FrameContext& frame)
{
    if (!m_voxelize) {
        m_voxelize = frame.shaders.build(
            {"voxelize", {"voxelize/Voxelize.vert", "voxelize/Voxelize.geom", "voxelize/Voxelize.frag"}, {}});
        m_resolve = frame.shaders.build({"voxel resolve", {"voxelize/Resolve.comp"}, {}});
        m_listResolve = frame.shaders.build({"voxel resolve: touched voxels", {"voxelize/ListResolve.comp"}, {}});
    }
    VoxelVolume& v = frame.voxels;
    const int res = v.frame.resolution;
    if (v.albedo && v.albedo.width() == res)
        return;
    const int levels = v.frame.levelCount();
    // One r32f atlas of 2 x 2 x 3 slots holds the ten running sums (see common/VoxelAccumulators.glsl).
    v.accumulators = gl::Texture::create3D(GL_R32F, 2 * res, 2 * res, 3 * res);
    v.dynamicBounds = Aabb{};
    v.staticAlbedo = gl::Texture::create3D(GL_RGBA8, res);
    v.staticNormal = gl::Texture::create3D(GL_RGBA16F, res);
    v.staticEmission = gl::Texture::create3D(GL_RGBA16F, res);
    v.albedo = gl::Texture::create3D(GL_RGBA8, res);
    v.normal = gl::Texture::create3D(GL_RGBA16F, res);
    v.emission = gl::Texture::create3D(GL_RGBA16F, res);
    v.radiance = gl::Texture::create3D(GL_RGBA16F, res, levels);
    for (gl::Texture* t : {&v.staticAlbedo, &v.staticNormal, &v.staticEmission, &v.albedo, &v.normal, &v.emission})
        t->setFilter(GL_NEAREST, GL_NEAREST);
    m_framebuffer = gl::Framebuffer::createEmpty(res, res);
}

void VoxelizePass::accumulate(FrameContext& frame, bool dynamicMeshes, const VoxelRegion& region)
{
    VoxelVolume& v = frame.voxels;
    const int res = v.frame.resolution;
    // Only the region the meshes can touch needs zero sums: clearing the whole atlas costs more than drawing.
    const float zero = 0.0f;
    for (int slot = 0; slot < 10; ++slot) {
        const glm::ivec3 origin = region.lo + res * glm::ivec3(slot % 2, (slot / 2) % 2, slot / 4);
        const glm::ivec3 size = region.size();
        glClearTexSubImage(v.accumulators.id(), 0, origin.x, origin.y, origin.z, size.x, size.y, size.z, GL_RED, GL_FLOAT, &zero);
    }
    m_framebuffer.bind();
    glViewport(0, 0, res, res);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    const bool nvConservative = GLAD_GL_NV_conservative_raster && frame.settings.conservativeVoxelization;
    if (nvConservative)
        glEnable(GL_CONSERVATIVE_RASTERIZATION_NV);
    m_voxelize.set("uGridOrigin", v.frame.origin);
    m_voxelize.set("uGridExtent", v.frame.extent);
    m_voxelize.set("uResolution", res);
    m_voxelize.set("uRegionLo", region.lo);
    m_voxelize.set("uRegionHi", region.hi);
    // With hardware conservative raster the geometry shader need not enlarge triangles itself.
    m_voxelize.set("uConservative", frame.settings.conservativeVoxelization && !nvConservative ? 1 : 0);
    v.accumulators.bindImage(0, 0, GL_READ_WRITE);
    frame.scene.draw(m_voxelize, dynamicMeshes ? MeshFilter::Dynamic : MeshFilter::Static, 0);
    if (nvConservative)
        glDisable(GL_CONSERVATIVE_RASTERIZATION_NV);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void VoxelizePass::resolve(FrameContext& frame, bool mergeStatic, bool intoStaticLayer, const VoxelRegion& region)
{
    VoxelVolume& v = frame.voxels;
    // Untouched voxels take the static layer's values (merging) or none: a copy or a clear of the region, far
    // cheaper on llvmpipe than a shader writing three images per voxel. Then the touched ones are listed and
    // averaged.
    const glm::ivec3 lo = region.lo, size = region.size();
    const gl::Texture* outputs[3] = {intoStaticLayer ? &v.staticAlbedo : &v.albedo,
        intoStaticLayer ? &v.staticNormal : &v.normal, intoStaticLayer ? &v.staticEmission : &v.emission};
    const gl::Texture* statics[3] = {&v.staticAlbedo, &v.staticNormal, &v.staticEmission};
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    for (int i = 0; i < 3; ++i) {
        if (mergeStatic)
            glCopyImageSubData(statics[i]->id(), GL_TEXTURE_3D, 0, lo.x, lo.y, lo.z, outputs[i]->id(), GL_TEXTURE_3D, 0,
                lo.x, lo.y, lo.z, size.x, size.y, size.z);
        else
            glClearTexSubImage(outputs[i]->id(), 0, lo.x, lo.y, lo.z, size.x, size.y, size.z, GL_RGBA, GL_FLOAT, zero);
    }
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    v.accumulators.bindImage(0, 0, GL_READ_ONLY);
    m_listResolve.set("uResolution", v.frame.resolution);
    m_touched.buildWith(m_listResolve, region);
    for (int i = 0; i < 3; ++i)
        outputs[i]->bindImage(GLuint(1 + i), 0, GL_WRITE_ONLY);
    m_resolve.use();
    m_resolve.set("uResolution", v.frame.resolution);
    m_touched.dispatchOverCells();
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

void VoxelizePass::execute(FrameContext& frame)
{
    ensureResources(frame);
    VoxelVolume& v = frame.voxels;
    const VoxelRegion whole = VoxelRegion::whole(v.frame.resolution);
    const bool hasDynamic = frame.scene.hasDynamicMeshes();
    const Aabb dynamicBounds = frame.scene.scene().bounds(true);
    const bool staticChanged = m_staticGeometry != frame.versions.staticGeometry;
    const bool staticMaterialChanged = !staticChanged && m_staticMaterials != frame.versions.staticMaterials;
    // A material edit redoes the static voxels around the meshes that use it: every static mesh is drawn, but
    // fragments outside that box are dropped and only the box is resolved.
    const VoxelRegion staticRegion = staticChanged ? whole
        : staticMaterialChanged                    ? VoxelRegion::around(frame.staticMaterialEdits, v.frame, kDynamicMargin)
                                                   : VoxelRegion{};
    if (!staticRegion.isEmpty()) {
        accumulate(frame, false, staticRegion);
        // Without dynamic meshes the static layer is the final one: resolve straight into it.
        resolve(frame, false, hasDynamic, staticRegion);
    }
    m_staticGeometry = frame.versions.staticGeometry;
    m_staticMaterials = frame.versions.staticMaterials;
    VoxelRegion changed = staticRegion;
    bool dynamicMoved = false;
    if (hasDynamic) {
        // After a static rebuild every voxel is new; otherwise where the objects were and are now, plus
        // wherever the static layer changed (the final textures merge both there).
        const VoxelRegion dynamicRegion = VoxelRegion::around(dynamicBounds, v.frame, kDynamicMargin)
                                              .united(VoxelRegion::around(v.dynamicBounds, v.frame, kDynamicMargin));
        const VoxelRegion region = staticChanged ? whole
            : m_dynamicVersion != frame.versions.dynamicVoxels() ? dynamicRegion.united(staticRegion)
                                                                 : staticRegion;
        dynamicMoved = m_dynamicVersion != frame.versions.dynamicVoxels();
        if (!region.isEmpty()) {
            accumulate(frame, true, region);
            resolve(frame, true, false, region);
        }
        changed = region;
    }
    v.changedRegion = changed;
    v.onlyDynamicChanged = !staticChanged;
    v.dynamicMoved = dynamicMoved;
    v.previousDynamicBounds = v.dynamicBounds;
    v.dynamicBounds = dynamicBounds;
    m_dynamicVersion = frame.versions.dynamicVoxels();
    ++v.materialsVersion;
}
} // namespace vct::render
