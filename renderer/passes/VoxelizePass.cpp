#include "passes/VoxelizePass.h"

#include "core/FrameContext.h"
#include "core/Frustum.h"
#include "core/Level0Clear.h"
#include "core/ResourceNames.h"
#include "core/VolumeShift.h"

#include "common/Bindings.glsl"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>

namespace vct::render {

namespace {

// Margin around a moving object's bounds: conservative enlargement and depth spread reach one voxel out.
constexpr int kDynamicMargin = 2;

/** Where the grid sits on the lattice it steps on (Voxelize.vert): the scene grid's corner for a clip level,
 * its own otherwise. */
struct LatticePlacement {
    glm::vec3 origin;
    glm::ivec3 offset;
};

LatticePlacement latticeOf(const FrameContext& frame)
{
    const VoxelGridFrame& grid = frame.voxels.frame;
    const glm::vec3 voxels = (grid.origin - frame.sceneGrid.origin) / grid.voxelSize();
    const glm::vec3 whole = glm::round(voxels);
    // A clip level's corner is whole voxels from the scene grid's (core/ClipmapLayout); any other grid is
    // its own lattice.
    if (frame.sceneGrid.extent > 0.0f && glm::all(glm::lessThan(glm::abs(voxels - whole), glm::vec3(1e-3f))))
        return { frame.sceneGrid.origin, glm::ivec3(whole) };
    return { grid.origin, glm::ivec3(0) };
}

} // namespace

std::optional<glm::ivec3> VoxelizePass::gridStep(const FrameContext& frame) const
{
    // Only a grid that moved alone: any other change voxelizes the whole grid anyway.
    if (m_grid == frame.voxels.frame || m_staticGeometry != frame.versions.staticGeometry
        || modeChanged(frame))
        return std::nullopt;
    return VolumeShift::between(m_grid, frame.voxels.frame);
}

PassDecision VoxelizePass::plan(const FrameContext& frame) const
{
    if (m_staticGeometry == 0)
        return { PassDecision::Action::Run, "no valid output yet" };
    if (m_staticGeometry != frame.versions.staticGeometry)
        return { PassDecision::Action::Run, "static geometry or grid changed" };
    if (modeChanged(frame))
        return { PassDecision::Action::Run, "voxelization mode changed" };
    if (!(m_grid == frame.voxels.frame)) {
        if (const std::optional<glm::ivec3> step = gridStep(frame))
            return { PassDecision::Action::Run,
                "the grid stepped (" + std::to_string(step->x) + ", " + std::to_string(step->y) + ", "
                    + std::to_string(step->z)
                    + ") voxels with the camera: moving the voxels it keeps, voxelizing the slabs it newly "
                      "covers" };
        return { PassDecision::Action::Run, "the grid moved with the camera" };
    }
    if (m_staticMaterials != frame.versions.staticMaterials)
        return { PassDecision::Action::Run,
            "a static material changed: re-voxelizing the objects that use it" };
    if (m_dynamicVersion != frame.versions.dynamicVoxels())
        return { PassDecision::Action::Run, "a dynamic object moved: redoing the voxels around it" };
    return { PassDecision::Action::Reuse, "geometry unchanged" };
}

PassDeclaration VoxelizePass::declare() const
{
    return { {}, { resource::kAlbedo, resource::kNormal, resource::kEmission, resource::kBrickTable } };
}

void VoxelizePass::refuseOverBudget(const FrameContext& frame, const glm::ivec3& pool)
{
    // The settings could not count the pools before the bricks were known (RenderSettings::validate): the
    // budget holds them now, before anything is allocated.
    const VoxelVolume& v = frame.voxels;
    const double grid = std::pow(double(v.bricks.bricksPerSide()), 3.0);
    const double slots = double(pool.x) * double(pool.y) * double(pool.z);
    VoxelSceneNeeds needs { frame.scene.scene().hasEmissiveMaterial(), frame.shape.areaLights > 0,
        frame.shape.lightSources, slots / grid };
    const std::uint64_t bytes = frame.settings.voxelMemoryBytes(needs);
    if (bytes <= std::uint64_t(frame.settings.voxelBudgetMiB) << 20)
        return;
    char text[320];
    std::snprintf(text, sizeof text,
        "voxel_mode=sparse: the %zu bricks of 8^3 voxels the surfaces reach (%.1f%% of the grid) need %.2f "
        "GiB "
        "of voxel textures at voxel_res=%d, more than voxel_budget_mb=%d allows; lower voxel_res or raise "
        "voxel_budget_mb if the GL has the memory",
        v.bricks.allocatedBricks(), 100.0 * double(v.bricks.allocatedBricks()) / grid,
        double(bytes) / double(1u << 30), v.frame.resolution, frame.settings.voxelBudgetMiB);
    throw std::runtime_error(text);
}

void VoxelizePass::updateBricks(const FrameContext& frame)
{
    VoxelVolume& v = frame.voxels;
    const int res = v.frame.resolution;
    const Scene& scene = frame.scene.scene();
    // How far from a triangle the voxelizer writes: the geometry shader's conservative enlargement reaches
    // under a voxel beside it, and its depth spread up to a voxel more along the projection axis on a
    // triangle sloped across both others (1.43 voxels found by a model of the voxelizer); a plain raster
    // writes the voxel under each pixel centre.
    const float reach = frame.settings.conservativeVoxelization ? 2.0f : 1.0f;
    const bool whole = v.bricks.resolution() != res || !(m_brickGrid == v.frame)
        || m_brickStatic != frame.versions.staticGeometry || m_brickReach != reach;
    if (!whole && m_brickDynamic == frame.versions.dynamicVoxels()
        && m_brickBudget == frame.settings.voxelBudgetMiB)
        return;
    // Should the budget refuse the pool, nothing stays half done: the next frame allocates every brick again.
    m_brickStatic = 0;
    const glm::mat4 toGrid = glm::scale(glm::mat4(1.0f), glm::vec3(1.0f / v.frame.voxelSize()))
        * glm::translate(glm::mat4(1.0f), -v.frame.origin);
    if (whole) {
        v.bricks = BrickPool(res);
        ++v.brickLayout;
    }
    int added = 0;
    for (const Mesh& mesh : scene.meshes)
        if (mesh.visible && (whole || mesh.dynamic))
            added += v.bricks.addMesh(mesh.positions, mesh.indices, toGrid * mesh.transform, reach);
    // A moving object's new bricks take free slots: room for twice the bricks the moving objects take where
    // they are when the pool is sized, so that a drag over their own size fits; the pool grows, and
    // everything is made again, only when the room runs out. Bricks an object left keep their slots until the
    // next whole rebuild. Room in proportion to the whole scene's bricks would cost the Sponza at 512^3 a
    // fifth of its pools for a statue.
    glm::ivec3 pool = v.poolBricks;
    if (whole
        || std::size_t(pool.x) * std::size_t(pool.y) * std::size_t(pool.z) < v.bricks.allocatedBricks() + 1) {
        BrickPool moving(res);
        for (const Mesh& mesh : scene.meshes)
            if (mesh.visible && mesh.dynamic)
                moving.addMesh(mesh.positions, mesh.indices, toGrid * mesh.transform, reach);
        const std::size_t bricks = v.bricks.allocatedBricks();
        const std::size_t room
            = bricks + (frame.scene.hasDynamicMeshes() ? 2 * moving.allocatedBricks() + 64 : 0);
        pool = BrickPool::poolBricksFor(std::min(room,
            std::size_t(v.bricks.bricksPerSide()) * v.bricks.bricksPerSide() * v.bricks.bricksPerSide()));
        if (pool == glm::ivec3(0))
            throw std::runtime_error("voxel_mode=sparse: " + std::to_string(v.bricks.allocatedBricks())
                + " bricks do not fit one pool texture; use a lower voxel_res or voxel_mode=clipmap");
    }
    // Every time, so that a lower budget refuses what is already allocated too.
    refuseOverBudget(frame, pool);
    v.brickTableStale = v.brickTableStale || whole || added > 0 || pool != v.poolBricks;
    v.poolBricks = pool;
    m_brickGrid = v.frame;
    m_brickStatic = frame.versions.staticGeometry;
    m_brickDynamic = frame.versions.dynamicVoxels();
    m_brickBudget = frame.settings.voxelBudgetMiB;
    m_brickReach = reach;
}

std::vector<TextureSlot> VoxelizePass::textures(const FrameContext& frame)
{
    using gl::TextureDesc;
    VoxelVolume& v = frame.voxels;
    // Formats chosen by measured cost and error (docs/DESIGN.md, "Lean voxels"); common/VoxelWords.glsl.
    // Only scenes with emissive materials keep an emission volume. Made when a material starts to emit, it
    // holds no light yet anywhere, which is right: nothing emitted before, and the voxels of the material's
    // meshes are redone now.
    const bool emission = frame.scene.scene().hasEmissiveMaterial();
    v.sparse = frame.settings.voxelMode == VoxelMode::Sparse;
    if (v.sparse)
        updateBricks(frame);
    return { { resource::kAlbedo, ResourceGroup::Voxels, &v.albedo, v.level0(GL_RGBA8) },
        { resource::kNormal, ResourceGroup::Voxels, &v.normal, v.level0(GL_RGBA8_SNORM) },
        { resource::kEmission, ResourceGroup::Voxels, &v.emission,
            emission ? v.level0(GL_R11F_G11F_B10F).sampled(TextureDesc::Sampling::Nearest).zeroedWhenMade()
                     : TextureDesc {} },
        { resource::kBrickTable, ResourceGroup::Voxels, &v.brickTable,
            v.sparse ? TextureDesc::volume(GL_R32UI, v.bricks.bricksPerSide())
                           .sampled(TextureDesc::Sampling::Nearest)
                           .zeroedWhenMade()
                     : TextureDesc {} } };
}

bool VoxelizePass::redoesWholeGrid(const FrameContext& frame) const
{
    // As execute() decides: a static change or a new mode rebuilds everything, a grid that stepped the slabs
    // it newly covers, anything else a region.
    return m_staticGeometry != frame.versions.staticGeometry || modeChanged(frame)
        || (!(m_grid == frame.voxels.frame) && !gridStep(frame));
}

bool VoxelizePass::modeChanged(const FrameContext& frame) const
{
    return m_conservative != frame.settings.conservativeVoxelization
        || m_smallByCompute != frame.settings.smallTrianglesByCompute;
}

void VoxelizePass::ensureResources(FrameContext& frame)
{
    if (!m_resolve) {
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
    // The voxelizer averages into what the region holds, so it starts empty.
    const VoxelVolume& v = frame.voxels;
    for (const gl::Texture* t : { &v.albedo, &v.normal, &v.emission })
        clearLevel0(v, *t, region);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void VoxelizePass::accumulate(FrameContext& frame, MeshFilter layer, const VoxelRegion& region,
    OccupiedCellList& touched, bool appendToTouched)
{
    VoxelVolume& v = frame.voxels;
    const int res = v.frame.resolution;
    const glm::ivec3 size = region.size();
    // A sparse grid's voxels all lie in its bricks: a list as long as the region could not be afforded at
    // 512^3.
    std::size_t capacity = std::size_t(size.x) * std::size_t(size.y) * std::size_t(size.z);
    if (v.sparse)
        capacity = std::min(capacity, v.bricks.allocatedBricks() * BrickPool::kVoxelsPerBrick);
    if (appendToTouched)
        touched.bindForAppending();
    else
        touched.reset(capacity);
    m_framebuffer.bind();
    glViewport(0, 0, res, res);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    // Depth is clamped, not clipped: the fragment shader takes its own unclipped depth (Voxelize.geom).
    glEnable(GL_DEPTH_CLAMP);
    const bool nvConservative = GLAD_GL_NV_conservative_raster && frame.settings.conservativeVoxelization;
    if (nvConservative)
        glEnable(GL_CONSERVATIVE_RASTERIZATION_NV);
    // The three material textures are written as 32-bit words (common/VoxelWords.glsl).
    v.albedo.bindImage(0, 0, GL_READ_WRITE, GL_R32UI);
    v.normal.bindImage(1, 0, GL_READ_WRITE, GL_R32UI);
    if (v.emission)
        v.emission.bindImage(2, 0, GL_READ_WRITE, GL_R32UI);
    // Clusters of triangles that cannot reach the region are not drawn; conservative enlargement and the
    // depth spread reach up to two voxels beyond a triangle (updateBricks).
    const float voxel = v.frame.voxelSize();
    const Aabb reach { v.frame.origin + glm::vec3(region.lo - 2) * voxel,
        v.frame.origin + glm::vec3(region.hi + 2) * voxel };
    const Frustum regionBox = Frustum::ofBox(reach);
    const LatticePlacement lattice = latticeOf(frame);
    // With hardware conservative raster the geometry shader need not enlarge triangles itself.
    const bool conservative = frame.settings.conservativeVoxelization && !nvConservative;
    // The compute path is held to llvmpipe's rasteriser with the geometry shader's enlargement. Hardware
    // conservative rasterisation covers the same pixels but its fragments spread no depth: mixing the two
    // would put small and large triangles in differently deep voxels, and a GPU with that extension
    // rasterises small triangles cheaply anyway.
    const bool smallByCompute = frame.settings.smallTrianglesByCompute && !nvConservative;
    for (const int kind : { 0, 1, 2, 3 }) {
        const bool emissive = kind & 1, textured = kind & 2;
        DrawOptions options;
        options.layer = layer;
        options.materials = [emissive, textured](const Material& m) {
            return m.isEmissive() == emissive && (m.albedoTexture >= 0) == textured;
        };
        options.visibleIn = &regionBox;
        const auto setUniforms = [&](const gl::Program& program) {
            program.use();
            program.set("uLatticeOrigin", lattice.origin);
            program.set("uLatticeOffset", lattice.offset);
            program.set("uVoxelSize", voxel);
            program.set("uResolution", res);
            program.set("uRegionLo", region.lo);
            program.set("uRegionHi", region.hi);
            program.set("uGroupSize", OccupiedCellList::kGroupSize);
        };
        const gl::Program& raster = voxelizer(frame, { emissive, textured, conservative, false });
        if (!smallByCompute) {
            setUniforms(raster);
            frame.scene.draw(raster, options, 0);
            continue;
        }
        const gl::Program& small
            = voxelizer(frame, { emissive, textured, frame.settings.conservativeVoxelization, true });
        setUniforms(small);
        TriangleDispatch dispatch;
        dispatch.vertexBinding = kVertexBinding;
        dispatch.groupSize = kTriangleGroupSize;
        dispatch.listed = &m_largeTriangles;
        frame.scene.dispatchTriangles(small, options, 0, dispatch);
        glMemoryBarrier(
            GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_ELEMENT_ARRAY_BARRIER_BIT);
        setUniforms(raster);
        frame.scene.drawListed(raster, m_largeTriangles, 0);
    }
    if (nvConservative)
        glDisable(GL_CONSERVATIVE_RASTERIZATION_NV);
    glDisable(GL_DEPTH_CLAMP);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glMemoryBarrier(
        GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

const gl::Program& VoxelizePass::voxelizer(FrameContext& frame, const VoxelizerVariant& variant)
{
    // What a frame leaves out is a define, not a uniform: with the emission volume's compare-and-swap and the
    // conservative tests in every variant, chosen by uniforms, the atrium's voxelization took about a fifth
    // longer on llvmpipe in three pairs of four (docs/BENCHMARKS.md).
    std::vector<std::string> defines;
    std::string name = variant.smallByCompute ? "voxelize small triangles" : "voxelize";
    if (variant.emissive) {
        defines.emplace_back("EMISSIVE");
        name += " (emissive)";
    }
    if (variant.textured) {
        defines.emplace_back("TEXTURED");
        name += ", textured";
    }
    if (frame.voxels.emission) {
        defines.emplace_back("EMISSION_VOLUME");
        name += ", emission volume";
    }
    if (variant.conservative) {
        defines.emplace_back("CONSERVATIVE");
        name += ", conservative";
    }
    if (variant.smallByCompute)
        return frame.shaders.program({ name, { "voxelize/VoxelizeSmall.comp" }, defines });
    return frame.shaders.program(
        { name, { "voxelize/Voxelize.vert", "voxelize/Voxelize.geom", "voxelize/Voxelize.frag" }, defines });
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
    if (v.sparse && v.brickTableStale) {
        const std::vector<std::uint32_t> table = v.bricks.table(v.poolBricks);
        const int side = v.bricks.bricksPerSide();
        glTextureSubImage3D(
            v.brickTable.id(), 0, 0, 0, 0, side, side, side, GL_RED_INTEGER, GL_UNSIGNED_INT, table.data());
        v.brickTableStale = false;
    }
    if (v.sparse)
        v.brickTable.bindUnit(BRICK_TABLE_UNIT);
    const bool hasDynamic = frame.scene.hasDynamicMeshes();
    const Aabb dynamicBounds = frame.scene.scene().bounds(true);
    const std::optional<glm::ivec3> step = gridStep(frame);
    const bool staticChanged = m_staticGeometry != frame.versions.staticGeometry || modeChanged(frame)
        || (!(m_grid == v.frame) && !step);
    const bool dynamicMoved = hasDynamic && m_dynamicVersion != frame.versions.dynamicVoxels();
    // What to redo: the whole grid after a static change; else around the static meshes whose material
    // changed, and around the moving objects, now and before a move. The region is cleared and everything in
    // it voxelized again, static and dynamic meshes together, so a voxel both reach holds the mean of both,
    // as after a full rebuild. There is no static layer to copy back from: redrawing the static triangles
    // near the region (culled by cluster, then by triangle in the geometry shader) costs less memory than
    // keeping a copy of the whole grid.
    VoxelRegion region;
    std::vector<VoxelRegion> slabs;
    if (staticChanged) {
        region = VoxelRegion::whole(v.frame.resolution);
    } else {
        if (step)
            slabs = moveWithGrid(frame, *step);
        if (m_staticMaterials != frame.versions.staticMaterials)
            region = VoxelRegion::around(frame.staticMaterialEdits, v.frame, kDynamicMargin);
        if (hasDynamic)
            region = region.united(VoxelRegion::around(dynamicBounds, v.frame, kDynamicMargin));
        if (dynamicMoved)
            region = region.united(VoxelRegion::around(v.dynamicBounds, v.frame, kDynamicMargin));
    }
    // The dynamic list is made again over the region around the objects, below; a grid that stepped away from
    // them keeps none of their voxels, and its list must not name cells by where the grid was.
    if (step && hasDynamic && region.isEmpty())
        v.dynamicVoxels.reset(1);
    // The new slabs' static voxels join the static list, which the step moved: it names every static voxel
    // as a full rebuild's would.
    for (const VoxelRegion& slab : slabs) {
        clear(frame, slab);
        accumulate(frame, MeshFilter::Static, slab, v.staticVoxels, true);
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
    // Resolving marks a voxel done and is idempotent, so the moved list is resolved whole once all slabs
    // and the region are in: a voxel resolved earlier would take no more fragments.
    if (!slabs.empty())
        resolve(frame, v.staticVoxels);
    m_staticGeometry = frame.versions.staticGeometry;
    m_staticMaterials = frame.versions.staticMaterials;
    m_conservative = frame.settings.conservativeVoxelization;
    m_smallByCompute = frame.settings.smallTrianglesByCompute;
    m_grid = v.frame;
    v.occupiedCountStale = v.occupiedCountStale || !region.isEmpty() || !slabs.empty();
    v.changedRegions = slabs;
    if (!region.isEmpty())
        v.changedRegions.push_back(region);
    v.partialRewrite = !staticChanged;
    v.shiftedBy = staticChanged ? std::nullopt : step;
    v.dynamicMoved = dynamicMoved;
    v.previousDynamicBounds = v.dynamicBounds;
    v.dynamicBounds = dynamicBounds;
    m_dynamicVersion = frame.versions.dynamicVoxels();
    ++v.materialsVersion;
}

std::vector<VoxelRegion> VoxelizePass::moveWithGrid(FrameContext& frame, const glm::ivec3& step)
{
    // A clip level that follows the camera (core/ClipmapLayout) keeps most of its voxels at each step:
    // copying them within their textures costs a small part of voxelizing the triangles that reach them.
    VoxelVolume& v = frame.voxels;
    const int res = v.frame.resolution;
    for (const gl::Texture* t : { &v.albedo, &v.normal, &v.emission })
        if (*t)
            VolumeShift::apply(*t, nullptr, step);
    std::swap(v.staticVoxels, m_movedStaticVoxels);
    v.staticVoxels.assignShifted(frame.shaders, m_movedStaticVoxels, step, VolumeShift::kept(step, res),
        std::size_t(res) * std::size_t(res) * std::size_t(res));
    return VolumeShift::newSlabs(step, res);
}

} // namespace vct::render
