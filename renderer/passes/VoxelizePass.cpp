#include "passes/VoxelizePass.h"

#include "core/FrameContext.h"
#include "core/FrameRules.h"

#include <utility>

namespace vct::render {

namespace {

// Margin around a moving object's bounds: conservative enlargement and depth spread reach one voxel out.
constexpr int kDynamicMargin = 2;

} // namespace

PassDecision VoxelizePass::plan(const FrameContext& frame)
{
    if (m_staticGeometry == 0)
        return { PassDecision::Action::Run, "no valid output yet" };
    if (m_staticGeometry != frame.versions.staticGeometry)
        return { PassDecision::Action::Run, "static geometry or grid changed" };
    if (m_staticMaterials != frame.versions.staticMaterials)
        return { PassDecision::Action::Run,
            "a static material changed: re-voxelizing the objects that use it" };
    if (m_dynamicVersion != frame.versions.dynamicVoxels())
        return { PassDecision::Action::Run,
            "a dynamic object moved: static voxels kept, dynamic ones redone" };
    return { PassDecision::Action::Reuse, "geometry unchanged" };
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
    const int res = v.frame.resolution;
    // The static layer is kept only for moving objects to be redone on top of; without them the static
    // voxels are the final ones.
    const bool staticLayer = frame.scene.hasDynamicMeshes();
    if (v.albedo && v.albedo.width() == res && bool(v.staticAlbedo) == staticLayer)
        return;
    m_staticGeometry = 0; // every layer is rebuilt in its new textures
    v.dynamicBounds = Aabb {};
    // Formats chosen by measured cost and error (docs/DESIGN.md, "Lean voxels"); common/VoxelWords.glsl.
    auto material = [&](gl::Texture* albedo, gl::Texture* normal, gl::Texture* emission) {
        *albedo = gl::Texture::create3D(GL_RGBA8, res);
        *normal = gl::Texture::create3D(GL_RGBA8_SNORM, res);
        *emission = gl::Texture::create3D(GL_R11F_G11F_B10F, res);
        for (gl::Texture* t : { albedo, normal, emission })
            t->setFilter(GL_NEAREST, GL_NEAREST);
    };
    if (staticLayer)
        material(&v.staticAlbedo, &v.staticNormal, &v.staticEmission);
    else
        for (gl::Texture* t : { &v.staticAlbedo, &v.staticNormal, &v.staticEmission })
            *t = gl::Texture {};
    if (v.albedo && v.albedo.width() == res)
        return;
    const int levels = v.frame.levelCount();
    material(&v.albedo, &v.normal, &v.emission);
    // Level 0 alone when the bounced volume carries the levels cones read (MipmapPass).
    v.radiance = gl::Texture::create3D(GL_RGBA16F, res, FrameRules::bounceVolumeUsed(frame) ? 1 : levels);
    v.opacity = gl::Texture {}; // rebuilt at the new size if area lights need it
    m_framebuffer = gl::Framebuffer::createEmpty(res, res);
}

namespace {

struct MaterialTextures {
    const gl::Texture* albedo;
    const gl::Texture* normal;
    const gl::Texture* emission;
};

MaterialTextures materialTextures(const VoxelVolume& v, bool staticLayer)
{
    if (staticLayer)
        return { &v.staticAlbedo, &v.staticNormal, &v.staticEmission };
    return { &v.albedo, &v.normal, &v.emission };
}

} // namespace

void VoxelizePass::prepare(
    FrameContext& frame, bool mergeStatic, bool intoStaticLayer, const VoxelRegion& region)
{
    // The voxelizer averages into what the region holds: nothing (a clear), or the static layer's values
    // (merging), which a moving object's first fragment in a voxel replaces. A copy or a clear is far cheaper
    // on llvmpipe than a shader writing three images per voxel.
    const VoxelVolume& v = frame.voxels;
    const MaterialTextures to = materialTextures(v, intoStaticLayer);
    const MaterialTextures from = materialTextures(v, true);
    const gl::Texture* outputs[3] = { to.albedo, to.normal, to.emission };
    const gl::Texture* statics[3] = { from.albedo, from.normal, from.emission };
    const glm::ivec3 lo = region.lo, size = region.size();
    const float zero[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
    for (int i = 0; i < 3; ++i) {
        if (mergeStatic)
            glCopyImageSubData(statics[i]->id(), GL_TEXTURE_3D, 0, lo.x, lo.y, lo.z, outputs[i]->id(),
                GL_TEXTURE_3D, 0, lo.x, lo.y, lo.z, size.x, size.y, size.z);
        else
            glClearTexSubImage(outputs[i]->id(), 0, lo.x, lo.y, lo.z, size.x, size.y, size.z,
                outputs[i] == to.emission ? GL_RGB : GL_RGBA, GL_FLOAT, zero);
    }
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void VoxelizePass::accumulate(FrameContext& frame, bool dynamicMeshes, bool intoStaticLayer,
    const VoxelRegion& region, OccupiedCellList& touched)
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
    const MaterialTextures target = materialTextures(v, intoStaticLayer);
    int unit = 0;
    for (const gl::Texture* t : { target.albedo, target.normal, target.emission })
        t->bindImage(GLuint(unit++), 0, GL_READ_WRITE, GL_R32UI);
    const MeshFilter layer = dynamicMeshes ? MeshFilter::Dynamic : MeshFilter::Static;
    for (const bool emissive : { false, true }) {
        const gl::Program& program = emissive ? *m_voxelizeEmissive : *m_voxelize;
        program.use();
        program.set("uGridOrigin", v.frame.origin);
        program.set("uGridExtent", v.frame.extent);
        program.set("uResolution", res);
        program.set("uRegionLo", region.lo);
        program.set("uRegionHi", region.hi);
        program.set("uGroupSize", OccupiedCellList::kGroupSize);
        // With hardware conservative raster the geometry shader need not enlarge triangles itself.
        program.set("uConservative", frame.settings.conservativeVoxelization && !nvConservative ? 1 : 0);
        DrawOptions options;
        options.layer = layer;
        options.materials = [emissive](const Material& m) { return m.isEmissive() == emissive; };
        frame.scene.draw(program, options, 0);
    }
    if (nvConservative)
        glDisable(GL_CONSERVATIVE_RASTERIZATION_NV);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glMemoryBarrier(
        GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

void VoxelizePass::resolve(FrameContext& frame, bool intoStaticLayer, const OccupiedCellList& touched)
{
    const MaterialTextures target = materialTextures(frame.voxels, intoStaticLayer);
    target.albedo->bindImage(0, 0, GL_READ_WRITE, GL_R32UI);
    target.normal->bindImage(1, 0, GL_READ_WRITE, GL_R32UI);
    m_resolve->use();
    touched.dispatchOverCells();
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
        : staticMaterialChanged ? VoxelRegion::around(frame.staticMaterialEdits, v.frame, kDynamicMargin)
                                : VoxelRegion {};
    if (!staticRegion.isEmpty()) {
        // A material edit keeps the occupied voxels, so the full rebuild's list of them stays whole.
        OccupiedCellList& touched = staticChanged ? v.staticVoxels : m_editedVoxels;
        // Without dynamic meshes the static layer is the final one: voxelize straight into it.
        prepare(frame, false, hasDynamic, staticRegion);
        accumulate(frame, false, hasDynamic, staticRegion, touched);
        resolve(frame, hasDynamic, touched);
    }
    m_staticGeometry = frame.versions.staticGeometry;
    m_staticMaterials = frame.versions.staticMaterials;
    VoxelRegion changed = staticRegion;
    bool dynamicMoved = false;
    if (hasDynamic) {
        dynamicMoved = m_dynamicVersion != frame.versions.dynamicVoxels();
        // Always where the objects are now, so their list names all their voxels; where they were too after a
        // move; wherever the static layer changed (the final textures merge both there). After a static
        // rebuild the final textures start as a copy of the whole static layer.
        const VoxelRegion now = VoxelRegion::around(dynamicBounds, v.frame, kDynamicMargin);
        VoxelRegion region = now.united(staticRegion);
        if (dynamicMoved)
            region = region.united(VoxelRegion::around(v.dynamicBounds, v.frame, kDynamicMargin));
        if (staticChanged) {
            const glm::ivec3 size(v.frame.resolution);
            for (const auto& [from, to] : { std::pair { &v.staticAlbedo, &v.albedo },
                     std::pair { &v.staticNormal, &v.normal }, std::pair { &v.staticEmission, &v.emission } })
                glCopyImageSubData(from->id(), GL_TEXTURE_3D, 0, 0, 0, 0, to->id(), GL_TEXTURE_3D, 0, 0, 0, 0,
                    size.x, size.y, size.z);
            region = now;
        }
        if (!staticChanged)
            prepare(frame, true, false, region);
        accumulate(frame, true, false, region, v.dynamicVoxels);
        resolve(frame, false, v.dynamicVoxels);
        changed = staticChanged ? whole : region;
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
