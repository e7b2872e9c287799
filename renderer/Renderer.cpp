#include "Renderer.h"

#include "scene/CameraBasis.h"
#include "scene/DirectionalStackLayout.h"

#include "core/ConeSet.h"
#include "core/FrameContext.h"
#include "core/Pipeline.h"
#include "core/ResourceNames.h"
#include "core/ShaderLibrary.h"
#include "core/VoxelMipBuilder.h"
#include "debug/ConeSampleCounter.h"
#include "debug/FiniteCheck.h"
#include "debug/VoxelInspector.h"
#include "gl/DebugOutput.h"
#include "passes/AreaLightPass.h"
#include "passes/CompositePass.h"
#include "passes/ConeTracePass.h"
#include "passes/EnclosurePass.h"
#include "passes/GBufferPass.h"
#include "passes/InjectLightPass.h"
#include "passes/MipmapPass.h"
#include "passes/ShadowMapPass.h"
#include "passes/VoxelBouncePass.h"
#include "passes/VoxelIrradiancePass.h"
#include "passes/VoxelizePass.h"

#include <glad/gl.h>
#include <glm/gtc/matrix_transform.hpp>

#include "core/ClipLevelPass.h"
#include "core/ClipmapLayout.h"
#include "scene/VoxelTextureEstimate.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace vct::render {

struct Renderer::State {
    std::unique_ptr<ShaderLibrary> shaders;
    std::unique_ptr<GpuScene> scene;
    std::uint64_t sceneUploads = 0; ///< setScene() calls (Renderer::sceneUploads)
    ChangeVersions versions;
    VoxelVolume voxels;
    EnclosureMap enclosure;
    ShadowMaps shadows;
    ScreenTargets screen;
    ConeSet cones = ConeSet::diffuse(5);
    Aabb gridBounds; ///< empty: fit the scene
    VoxelGridFrame sceneGrid; ///< fitted around gridBounds or the scene: the dense grid, a clipmap's coarsest
    Aabb staticMaterialEdits; ///< since the last frame
    VoxelInspector inspector;
    FiniteCheck finiteCheck;
    gl::VertexArray emptyVao;
    std::unique_ptr<Pipeline> pipeline;
    /// A clipmap's levels coarser than `voxels` (RenderSettings::voxelMode), finest first: passes of the
    /// pipeline, which owns them. Empty for a dense grid.
    std::vector<ClipLevelPass*> clipLevels;
    bool timesFromPreviousFrame = false;
    bool stagedRebuilds = false;
    VoxelMipBuilder
        boxMips; ///< the box-filtered levels when anisotropic mips skip them (ensureInspectionMips)
    std::unique_ptr<ConeSampleCounter> coneSampleCounter; ///< only while a benchmark counts cone fetches
    std::uint64_t coneSamples = 0; ///< counted in the last frame
    int bounceIterationsPerFrame = 0;
    bool phaseTimes = false;

    /** Grid @p grid (Renderer::gridCount(), clamped): 0 the frame's own voxels, k clip level k. */
    VoxelVolume& volumeOf(int grid)
    {
        grid = std::clamp(grid, 0, int(clipLevels.size()));
        return grid == 0 ? voxels : clipLevels[std::size_t(grid - 1)]->volume();
    }
    /** The table holding grid @p grid's textures. */
    ResourceTable& resourcesOf(int grid)
    {
        grid = std::clamp(grid, 0, int(clipLevels.size()));
        return grid == 0 ? pipeline->resources() : clipLevels[std::size_t(grid - 1)]->pipeline().resources();
    }
    /** Grid @p grid's box-filtered levels for looking at (ensureInspectionMips), made if they are stale. */
    void ensureInspectionMipsOf(int grid);
};

namespace {

// The box-filtered levels of the volume cones trace, for the voxel inspector, readVoxels and the NaN check.
// With anisotropic mips the volume has level 0 only (cones read the directional chains above it), so they are
// made in VoxelVolume::inspectionMips when something looks, and kept while the light stays the same.
void ensureInspectionMips(const ShaderLibrary& shaders, VoxelMipBuilder& builder, ResourceTable& resources,
    VoxelVolume& v, bool dynamicMeshes)
{
    const gl::Texture& source = v.coneRadiance();
    const int levels = v.frame.levelCount();
    const bool needed = source && source.levels() != levels;
    const auto make = [&](bool building) {
        // The cell marks are scratch for building the levels: they go once the levels are built.
        resources.apply("voxel inspector",
            { { resource::kInspectionMips, ResourceGroup::Voxels, &v.inspectionMips,
                  needed ? gl::TextureDesc::volume(GL_RGBA16F, v.frame.resolution, levels)
                         : gl::TextureDesc {} },
                { resource::kInspectionCellMarks, ResourceGroup::Voxels, &builder.marks(),
                    building ? VoxelMipBuilder::marksDesc(v.frame.resolution) : gl::TextureDesc {} } });
    };
    make(false);
    const std::uint64_t key = v.coneRadianceKey();
    if (!needed || (v.inspectionMips.serial() == v.inspectionMipsSerial && v.inspectionMipsKey == key))
        return;
    make(true);
    const int side = v.frame.resolution;
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    if (v.sparse) {
        const gl::Program& dense
            = shaders.program({ "sparse level 0, dense", { "inspector/DenseLevel0.comp" }, {} });
        dense.use();
        v.brickTable.bindUnit(BRICK_TABLE_UNIT);
        source.bindUnit(0);
        v.inspectionMips.bindImage(0, 0, GL_WRITE_ONLY);
        const GLuint groups = GLuint((side + 3) / 4);
        glDispatchCompute(groups, groups, groups);
    } else {
        glCopyImageSubData(source.id(), GL_TEXTURE_3D, 0, 0, 0, 0, v.inspectionMips.id(), GL_TEXTURE_3D, 0, 0,
            0, 0, side, side, side);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    builder.listCells(shaders, v.frame.resolution, levels, v.occupiedVoxels(dynamicMeshes));
    builder.buildBox(shaders, v.inspectionMips);
    make(false);
    v.inspectionMipsKey = key;
    v.inspectionMipsSerial = v.inspectionMips.serial();
}

} // namespace

void Renderer::State::ensureInspectionMipsOf(int grid)
{
    ensureInspectionMips(*shaders, boxMips, resourcesOf(grid), volumeOf(grid), scene->hasDynamicMeshes());
}

namespace {

/**
 * The frame's passes. With a clipmap of @p gridLevels levels the coarser levels come after the shadow maps,
 * coarsest first, each able to trace on into those already done; their passes are listed in @p clipLevels,
 * finest first.
 */
std::unique_ptr<Pipeline> makePipeline(int gridLevels, std::vector<ClipLevelPass*>& clipLevels)
{
    std::vector<std::unique_ptr<RenderPass>> passes;
    passes.push_back(std::make_unique<ShadowMapPass>());
    // Before every grid's passes: the clip levels' bounce gathers read it too.
    passes.push_back(std::make_unique<EnclosurePass>());
    clipLevels.assign(std::size_t(std::max(gridLevels - 1, 0)), nullptr);
    std::vector<const VoxelVolume*> coarser;
    for (int level = gridLevels - 1; level >= 1; --level) {
        auto clip = std::make_unique<ClipLevelPass>(level, coarser);
        clipLevels[std::size_t(level - 1)] = clip.get();
        coarser.insert(coarser.begin(), &clip->volume());
        passes.push_back(std::move(clip));
    }
    passes.push_back(std::make_unique<VoxelizePass>());
    passes.push_back(std::make_unique<InjectLightPass>());
    passes.push_back(std::make_unique<MipmapPass>());
    passes.push_back(std::make_unique<VoxelBouncePass>());
    // Before the irradiance cache: its traced pixels decide which cells it gathers.
    passes.push_back(std::make_unique<GBufferPass>());
    passes.push_back(std::make_unique<VoxelIrradiancePass>());
    passes.push_back(std::make_unique<ConeTracePass>());
    passes.push_back(std::make_unique<AreaLightPass>());
    passes.push_back(std::make_unique<CompositePass>());
    return std::make_unique<Pipeline>(std::move(passes));
}

// The output's size and its traced grids' divisors; the passes that draw into them make the targets.
void resizeScreen(ScreenTargets& s, int width, int height, int divisor, int specularDivisor, int areaDivisor)
{
    s.width = width;
    s.height = height;
    s.indirectDivisor = divisor;
    s.specularDivisor = specularDivisor;
    s.areaDivisor = areaDivisor;
}

std::vector<float> readTextureLevel(const gl::Texture& texture, int level, int& size)
{
    if (level < 0 || level >= texture.levels())
        throw std::invalid_argument("voxel level " + std::to_string(level) + " out of range");
    size = std::max(1, texture.width() >> level);
    std::vector<float> data(std::size_t(size) * std::size_t(size) * std::size_t(size) * 4);
    glGetTextureImage(
        texture.id(), level, GL_RGBA, GL_FLOAT, GLsizei(data.size() * sizeof(float)), data.data());
    return data;
}

// A sparse grid's level 0 as a dense grid's reads (common/VoxelBricks.glsl): each voxel from its brick's
// place in the pool, and where there is none what a dense texture holds there (zero, alpha 1 for a format
// without alpha). The pool is read a layer of bricks at a time, so that no one read is larger than GL's
// GLsizei counts.
std::vector<float> readSparseLevel0(const VoxelVolume& v, const gl::Texture& pool, int& size)
{
    size = v.frame.resolution;
    const float emptyAlpha = pool.format() == GL_R11F_G11F_B10F ? 1.0f : 0.0f;
    std::vector<float> data(std::size_t(size) * std::size_t(size) * std::size_t(size) * 4, 0.0f);
    for (std::size_t i = 3; i < data.size(); i += 4)
        data[i] = emptyAlpha;
    constexpr int kTexels = BrickPool::kBrickTexels;
    const std::size_t layerTexels = std::size_t(pool.width()) * std::size_t(pool.height()) * kTexels;
    std::vector<float> layer(layerTexels * 4);
    for (int brickZ = 0; brickZ < v.poolBricks.z; ++brickZ) {
        glGetTextureSubImage(pool.id(), 0, 0, 0, brickZ * kTexels, pool.width(), pool.height(), kTexels,
            GL_RGBA, GL_FLOAT, GLsizei(layer.size() * sizeof(float)), layer.data());
        const int bricks = v.bricks.bricksPerSide();
        for (int bz = 0; bz < bricks; ++bz)
            for (int by = 0; by < bricks; ++by)
                for (int bx = 0; bx < bricks; ++bx) {
                    const glm::ivec3 brick(bx, by, bz);
                    const std::uint32_t slot = v.bricks.slot(brick);
                    const glm::ivec3 corner = BrickPool::slotPosition(slot, v.poolBricks);
                    if (slot == 0 || corner.z != brickZ)
                        continue;
                    for (int z = 0; z < BrickPool::kBrickVoxels; ++z)
                        for (int y = 0; y < BrickPool::kBrickVoxels; ++y)
                            for (int x = 0; x < BrickPool::kBrickVoxels; ++x) {
                                const glm::ivec3 voxel
                                    = brick * BrickPool::kBrickVoxels + glm::ivec3(x, y, z);
                                if (glm::any(glm::greaterThanEqual(voxel, glm::ivec3(size))))
                                    continue;
                                const std::size_t from = ((std::size_t(z) * std::size_t(pool.height())
                                                              + std::size_t(corner.y * kTexels + y))
                                                                 * std::size_t(pool.width())
                                                             + std::size_t(corner.x * kTexels + x))
                                    * 4;
                                const std::size_t to
                                    = ((std::size_t(voxel.z) * size + std::size_t(voxel.y)) * size
                                          + std::size_t(voxel.x))
                                    * 4;
                                std::copy(layer.begin() + std::ptrdiff_t(from),
                                    layer.begin() + std::ptrdiff_t(from + 4),
                                    data.begin() + std::ptrdiff_t(to));
                            }
                }
    }
    return data;
}

struct CameraMatrices {
    glm::mat4 view;
    glm::mat4 projection;
};

CameraMatrices cameraMatrices(const Camera& camera, float aspect, const Aabb& bounds)
{
    // Only a guard against a point-sized scene; an absolute floor near real sizes would break tiny scenes.
    const float sceneRadius = std::max(0.5f * glm::length(bounds.size()), 1e-20f);
    const float farPlane = glm::length(camera.position - bounds.center()) + 2.0f * sceneRadius;
    const float nearPlane = std::max(camera.nearPlane, farPlane * 1e-5f);
    return { glm::lookAt(camera.position, camera.lookAt, camera.up),
        glm::perspective(glm::radians(camera.fovYDeg), aspect, nearPlane, farPlane) };
}

glm::mat3 pixelToRay(const Camera& camera, int width, int height)
{
    const CameraBasis b = CameraBasis::of(camera);
    const float tanY = b.tanHalfFovY;
    const float tanX = tanY * float(width) / float(height);
    // Pixel x in [0, width] maps to ndc -1..1, times tanX along right, and likewise y; forward stays 1.
    return glm::mat3(b.right * (2.0f * tanX / float(width)), b.up * (2.0f * tanY / float(height)),
        b.forward - b.right * tanX - b.up * tanY);
}

} // namespace

Renderer::Renderer(gl::ProcAddressFunction getProcAddress)
    : Renderer(getProcAddress, std::make_unique<ShaderLibrary>())
{
}

Renderer::Renderer(gl::ProcAddressFunction getProcAddress, std::unique_ptr<ShaderLibrary> shaders)
    : m_state(std::make_unique<State>())
{
    if (!gl::loadGl(getProcAddress))
        throw std::runtime_error("OpenGL 4.5 core is not available in the current context");
    // Averaging voxel fragments needs float image atomics; every driver we target has them.
    bool atomicFloat = false;
    GLint extensions = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &extensions);
    for (GLint i = 0; i < extensions; ++i)
        if (std::strcmp(reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i))),
                "GL_NV_shader_atomic_float")
            == 0)
            atomicFloat = true;
    if (!atomicFloat)
        throw std::runtime_error(
            "the GL driver lacks GL_NV_shader_atomic_float, needed to average voxel fragments");
    gl::DebugOutput::enable();
    m_state->shaders = std::move(shaders);
    m_state->pipeline = makePipeline(1, m_state->clipLevels);
    m_state->scene = std::make_unique<GpuScene>(Scene {});
}

Renderer::~Renderer()
{
    // Let the driver finish the work it has queued before the programs and textures it reads are deleted.
    // CI once aborted in Mesa's free() while a test's renderer deleted its programs at exit, right after its
    // last frame (not reproduced in 40 runs of that test nor in 12 runs of the GL suite from an empty shader
    // cache); with nothing in flight, deletion cannot race llvmpipe's rasterizer threads.
    glFinish();
}

void Renderer::setScene(const Scene& scene)
{
    // A build left by a frame that threw reads the meshes about to go.
    m_state->enclosure.abandon();
    m_state->scene = std::make_unique<GpuScene>(scene);
    ++m_state->sceneUploads;
    ++m_state->versions.staticGeometry;
    ++m_state->versions.dynamicGeometry;
    ++m_state->versions.lightPlacement;
    ++m_state->versions.lightValues;
}

void Renderer::setGridBounds(const Aabb& bounds)
{
    m_state->gridBounds = bounds;
}

void Renderer::setSettings(const RenderSettings& settings)
{
    if (std::string problem = settings.validate(); !problem.empty())
        throw std::invalid_argument(problem);
    // What a setting invalidates is decided by the passes: each one's reuse key holds the settings it reads.
    if (settings.diffuseConeCount != m_state->cones.size())
        m_state->cones = ConeSet::diffuse(settings.diffuseConeCount);
    const bool sparse = settings.voxelMode == VoxelMode::Sparse;
    if (settings.gridLevels() != m_settings.gridLevels() || !m_state->pipeline
        || sparse != (m_settings.voxelMode == VoxelMode::Sparse)) {
        // Another number of grids is another set of passes, and a sparse grid's passes address level 0
        // through its bricks (common/VoxelBricks.glsl): everything is made again.
        m_state->shaders->setSharedDefines(
            sparse ? std::vector<std::string> { "SPARSE_VOXELS" } : std::vector<std::string> {});
        m_state->pipeline = makePipeline(settings.gridLevels(), m_state->clipLevels);
        m_state->voxels = VoxelVolume {};
        m_state->inspector = VoxelInspector {};
        applyPipelineModes();
    }
    m_settings = settings;
}

void Renderer::setMeshTransform(std::size_t mesh, const glm::mat4& transform)
{
    if (mesh >= m_state->scene->meshCount())
        return;
    const bool dynamic = m_state->scene->scene().meshes[mesh].dynamic;
    m_state->scene->setTransform(mesh, transform);
    // The shadow pass keys on geometry versions too, so the maps follow the move.
    ++(dynamic ? m_state->versions.dynamicGeometry : m_state->versions.staticGeometry);
}

void Renderer::setMeshVisible(std::size_t mesh, bool visible)
{
    if (mesh >= m_state->scene->meshCount() || m_state->scene->scene().meshes[mesh].visible == visible)
        return;
    m_state->scene->setVisible(mesh, visible);
    // The scene's bounds, and with them the grid, may change: a static rebuild (which redoes the dynamic
    // layer too) is what a new scene would get, minus the upload.
    ++m_state->versions.staticGeometry;
    ++m_state->versions.dynamicGeometry;
    if (m_state->scene->materialOf(mesh).isEmissive()) {
        ++m_state->versions.lightPlacement;
        ++m_state->versions.lightValues;
    }
}

std::uint64_t Renderer::sceneUploads() const
{
    return m_state->sceneUploads;
}

void Renderer::setMaterial(std::size_t index, const Material& material)
{
    const std::vector<Material>& materials = m_state->scene->scene().materials;
    // Voxels hold albedo and emission only: a specular or gloss edit changes per-pixel shading alone.
    const bool voxelsAffected = index >= materials.size() || materials[index].albedo != material.albedo
        || materials[index].emission != material.emission
        || materials[index].albedoTexture != material.albedoTexture;
    // Single-sided surfaces leave their back faces out of the shadow maps too: redraw them, and the light.
    if (index < materials.size() && materials[index].doubleSided != material.doubleSided) {
        ++m_state->versions.lightPlacement;
        ++m_state->versions.lightValues;
    }
    m_state->scene->setMaterial(index, material);
    if (!voxelsAffected)
        return;
    // Only the voxel layers holding a mesh of this material are redone.
    bool usedStatic = false, usedDynamic = false;
    for (const Mesh& mesh : m_state->scene->scene().meshes)
        if (mesh.material == int(index)) {
            (mesh.dynamic ? usedDynamic : usedStatic) = true;
            if (!mesh.dynamic)
                for (const glm::vec3& p : mesh.positions)
                    m_state->staticMaterialEdits.extend(glm::vec3(mesh.transform * glm::vec4(p, 1.0f)));
        }
    // Materials do not move geometry: shadow maps stay.
    if (usedStatic)
        ++m_state->versions.staticMaterials;
    if (usedDynamic)
        ++m_state->versions.dynamicMaterials;
}

void Renderer::setLights(const std::vector<PointLight>& points,
    const std::vector<DirectionalLight>& directionals, const std::vector<SurfaceLight>& surfaces)
{
    const Scene& old = m_state->scene->scene();
    // The document sends its lights whole after any light edit: renaming one changes nothing drawn.
    if (points == old.pointLights && directionals == old.directionalLights && surfaces == old.surfaceLights)
        return;
    // A change of colour or intensity alone keeps the shadow maps.
    bool placementChanged
        = points.size() != old.pointLights.size() || directionals.size() != old.directionalLights.size();
    for (std::size_t i = 0; !placementChanged && i < points.size(); ++i)
        placementChanged = points[i].position != old.pointLights[i].position
            || points[i].castsShadows != old.pointLights[i].castsShadows;
    // A spot's cone changes light values only: its shadow cube map is the same.
    for (std::size_t i = 0; !placementChanged && i < directionals.size(); ++i)
        placementChanged = directionals[i].direction != old.directionalLights[i].direction
            || directionals[i].castsShadows != old.directionalLights[i].castsShadows;
    // Rectangle and disk lights are no geometry and cast through no shadow map: their change is one of light
    // values, and the area-light table's version tells the passes that read it.
    m_state->scene->setLights(points, directionals, surfaces);
    if (placementChanged)
        ++m_state->versions.lightPlacement;
    ++m_state->versions.lightValues;
}

void Renderer::invalidate()
{
    m_state->pipeline->invalidate();
}

std::vector<std::string> Renderer::reloadShaders(const std::string& folder)
{
    std::vector<std::string> failures = m_state->shaders->reload(ShaderLibrary::folderLookup(folder));
    // New shader text may change any pass's output, the voxels' too.
    invalidate();
    return failures;
}

FrameStats Renderer::renderFrame(const Camera& camera, int width, int height)
{
    State& st = *m_state;
    width = std::max(1, width);
    height = std::max(1, height);
    const Scene& scene = st.scene->scene();
    // A clipmap's coarsest level keeps a dense grid's margin of one of its own cells: geometry on the bounds
    // must not fall in its outermost layer, where the voxelizer drops what a triangle's enlargement reaches
    // beyond the grid (the atrium's outer walls read 0.067 instead of 0.062 with a finest cell's margin).
    const VoxelGridFrame sceneGrid = VoxelGridFrame::fit(
        st.gridBounds.isEmpty() ? scene.bounds() : st.gridBounds, m_settings.voxelResolution);
    if (!(sceneGrid == st.sceneGrid)) {
        // Dynamic meshes are part of the bounds: the grid follows them, so a move may refit the whole grid.
        st.sceneGrid = sceneGrid;
        ++st.versions.staticGeometry;
    }
    // The finest level of a clipmap follows the camera; its voxelize pass notices when it moves.
    st.voxels.frame = ClipmapLayout::level(sceneGrid, m_settings.gridLevels(), 0, camera.position);
    resizeScreen(st.screen, width, height, m_settings.indirectDivisor, m_settings.specularDivisor,
        m_settings.areaShadowDivisor);
    // Every pass that reads level 0 of a sparse grid looks its bricks up there (common/VoxelBricks.glsl);
    // another context (the editor's widgets) may have used the unit since.
    if (st.voxels.sparse && st.voxels.brickTable)
        st.voxels.brickTable.bindUnit(BRICK_TABLE_UNIT);

    const CameraMatrices matrices = cameraMatrices(camera, float(width) / float(height), scene.bounds());
    FrameContext frame { *st.shaders, *st.scene, m_settings, st.versions, st.voxels, st.shadows, st.screen,
        st.cones, st.staticMaterialEdits, camera, matrices.view, matrices.projection,
        pixelToRay(camera, width, height), st.coneSampleCounter.get(),
        // A staged rebuild gives the bounce solve's frames one iteration each, so that none holds the event
        // loop for the solve's start and the screen passes together with several iterations.
        st.pipeline->rebuilding() && st.bounceIterationsPerFrame > 0 ? 1 : st.bounceIterationsPerFrame,
        FrameShape {}, &st.pipeline->resources(), sceneGrid, {}, &st.enclosure };
    for (const ClipLevelPass* level : st.clipLevels)
        frame.coarserLevels.push_back(&level->volume());
    frame.phaseTimes = st.phaseTimes;
    frame.shape = FrameShape::of(frame);

    if (st.coneSampleCounter)
        st.coneSampleCounter->reset();
    FrameStats stats = st.pipeline->execute(frame);
    st.coneSamples = st.coneSampleCounter ? st.coneSampleCounter->read() : 0;
    st.staticMaterialEdits = Aabb {};
    std::vector<VoxelVolume*> volumes { &st.voxels };
    for (ClipLevelPass* level : st.clipLevels)
        volumes.push_back(&level->volume());
    // Box levels made for inspecting light that has since changed are remade when next looked at.
    for (VoxelVolume* v : volumes)
        if (v->inspectionMips
            && (v->inspectionMipsKey != v->coneRadianceKey()
                || v->inspectionMips.width() != v->frame.resolution))
            v->inspectionMips = gl::Texture();
    stats.voxelBytes = voxelBytes();
    stats.occupiedVoxels = 0;
    for (VoxelVolume* v : volumes) {
        if (v->occupiedCountStale) {
            // The static list names every static voxel, the dynamic one those only moving objects reach
            // (static meshes are drawn first, and a list takes a voxel from the first fragment to reach it):
            // together, each once. Read after the whole frame is queued, not inside the voxelize pass, so the
            // readback does not hold back the passes after it.
            v->occupiedCount
                = v->staticVoxels.count() + (st.scene->hasDynamicMeshes() ? v->dynamicVoxels.count() : 0);
            v->occupiedCountStale = false;
        }
        stats.occupiedVoxels += v->occupiedCount;
    }
    stats.gridLevels = m_settings.gridLevels();
    if (st.voxels.sparse) {
        stats.storedBricks = st.voxels.bricks.allocatedBricks();
        stats.gridBricks = std::size_t(st.voxels.bricks.bricksPerSide())
            * std::size_t(st.voxels.bricks.bricksPerSide()) * std::size_t(st.voxels.bricks.bricksPerSide());
    }
    stats.width = width;
    stats.height = height;
    stats.voxelResolution = st.voxels.frame.resolution;
    stats.voxelSize = st.voxels.frame.voxelSize();
    stats.bounceIterations = st.voxels.bounceProgress.iterations;
    stats.bounceResidual = st.voxels.bounceProgress.residual;
    // In a clipmap the light has converged when every level's solve has (a finer level's also waits for the
    // coarser ones', whose light it gathers: VoxelBouncePass).
    stats.lightConverged = st.voxels.bounceProgress.converged;
    stats.bounceStoppedAtLimit = st.voxels.bounceProgress.stoppedAtLimit;
    for (const ClipLevelPass* level : st.clipLevels) {
        stats.lightConverged = stats.lightConverged && level->volume().bounceProgress.converged;
        stats.bounceStoppedAtLimit
            = stats.bounceStoppedAtLimit || level->volume().bounceProgress.stoppedAtLimit;
    }
    stats.bounceExtrapolated = st.voxels.bounceProgress.extrapolated;
    // A build no pass read this frame (none traced a diffuse cone) is taken now, while its scene stands.
    st.enclosure.finish();
    if (st.enclosure.inUse) {
        const std::size_t side = std::size_t(st.enclosure.grid.resolution);
        stats.enclosedCells = st.enclosure.enclosedCells;
        stats.enclosureCells = side * side * side;
    }
    return stats;
}

void Renderer::present(unsigned framebuffer, int x, int y, int width, int height, float exposure)
{
    State& st = *m_state;
    if (!st.screen.final || width <= 0 || height <= 0)
        return;
    if (!st.emptyVao)
        st.emptyVao = gl::VertexArray::create();
    const gl::Program& program
        = st.shaders->program({ "present", { "common/FullScreen.vert", "present/Present.frag" }, {} });
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glViewport(x, y, width, height);
    glDisable(GL_DEPTH_TEST);
    program.use();
    program.set("uExposure", exposure);
    program.set("uTarget", glm::vec4(float(x), float(y), float(width), float(height)));
    st.screen.final.bindUnit(0);
    st.emptyVao.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
}

const VoxelListing& Renderer::listVoxels(int level, VoxelChannel channel, int grid)
{
    grid = std::clamp(grid, 0, gridCount() - 1);
    m_state->ensureInspectionMipsOf(grid);
    return m_state->inspector.list(*m_state->shaders, m_state->volumeOf(grid), level, channel, grid);
}

std::size_t Renderer::drawVoxelCubes(const Camera& camera, int level, VoxelChannel channel,
    unsigned framebuffer, int x, int y, int width, int height, float exposure, int grid)
{
    State& st = *m_state;
    if (width <= 0 || height <= 0)
        return 0;
    listVoxels(level, channel, grid);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glViewport(x, y, width, height);
    glEnable(GL_SCISSOR_TEST);
    glScissor(x, y, width, height);
    glClearColor(0.16f, 0.16f, 0.18f, 1.0f);
    glClearDepth(1.0);
    glDepthMask(GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glEnable(GL_CULL_FACE);
    const CameraMatrices matrices
        = cameraMatrices(camera, float(width) / float(height), st.scene->scene().bounds());
    const std::size_t drawn = st.inspector.draw(*st.shaders, matrices.projection * matrices.view, exposure);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
    return drawn;
}

void Renderer::setTimesFromPreviousFrame(bool previousFrame)
{
    m_state->timesFromPreviousFrame = previousFrame;
    applyPipelineModes();
}

void Renderer::setStagedRebuilds(bool staged)
{
    m_state->stagedRebuilds = staged;
    applyPipelineModes();
}

void Renderer::applyPipelineModes()
{
    const Pipeline::TimingReadback readback = m_state->timesFromPreviousFrame
        ? Pipeline::TimingReadback::PreviousFrame
        : Pipeline::TimingReadback::ThisFrame;
    m_state->pipeline->setTimingReadback(readback);
    m_state->pipeline->setStagedRebuilds(m_state->stagedRebuilds);
    for (ClipLevelPass* level : m_state->clipLevels)
        level->pipeline().setTimingReadback(readback);
}

void Renderer::setBounceIterationsPerFrame(int iterations)
{
    m_state->bounceIterationsPerFrame = std::max(0, iterations);
}

void Renderer::setPhaseTimes(bool on)
{
    m_state->phaseTimes = on;
}

std::vector<NonFiniteCount> Renderer::countNonFinite()
{
    m_state->ensureInspectionMipsOf(0);
    std::vector<NonFiniteCount> counts
        = m_state->finiteCheck.run(*m_state->shaders, m_state->pipeline->resources());
    for (const ClipLevelPass* level : m_state->clipLevels)
        for (NonFiniteCount count :
            m_state->finiteCheck.run(*m_state->shaders, level->pipeline().resources())) {
            count.resource = clipLevelName(level->level(), count.resource);
            counts.push_back(std::move(count));
        }
    return counts;
}

int Renderer::voxelLevelCount() const
{
    return m_state->voxels.radiance ? m_state->voxels.frame.levelCount() : 0;
}

int Renderer::gridCount() const
{
    return 1 + int(m_state->clipLevels.size());
}

RadianceImage Renderer::readFrame() const
{
    const ScreenTargets& s = m_state->screen;
    RadianceImage image(s.width, s.height);
    if (!s.final)
        return image;
    std::vector<float> rgba(std::size_t(s.width) * std::size_t(s.height) * 4);
    glGetTextureImage(s.final.id(), 0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * sizeof(float)), rgba.data());
    // GL rows run bottom to top.
    for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) {
            const float* p
                = &rgba[(std::size_t(s.height - 1 - y) * std::size_t(s.width) + std::size_t(x)) * 4];
            image.at(x, y) = glm::vec3(p[0], p[1], p[2]);
        }
    return image;
}

std::vector<float> Renderer::readVoxels(const std::string& channel, int level, int& size, int grid) const
{
    if (grid < 0 || grid >= gridCount())
        throw std::invalid_argument(
            "no grid " + std::to_string(grid) + " (there are " + std::to_string(gridCount()) + ")");
    m_state->ensureInspectionMipsOf(grid);
    const VoxelVolume& v = m_state->volumeOf(grid);
    static const char* const kDirections[6] = { "+x", "-x", "+y", "-y", "+z", "-z" };
    for (const bool bounced : { false, true })
        for (std::size_t d = 0; d < 6; ++d) {
            if (channel != std::string(bounced ? "bounced" : "radiance") + kDirections[d])
                continue;
            const gl::Texture& chains = bounced ? v.bouncedDirectional : v.directional;
            if (!chains || level < 1 || level - 1 >= chains.levels())
                throw std::invalid_argument("no " + channel + " level " + std::to_string(level)
                    + (bounced ? " (needs anisotropic mips and bounces in the voxels, levels from 1)"
                               : " (needs anisotropic mips, levels from 1)"));
            // Tile d starts d strides in (scene/DirectionalStackLayout.h).
            size = std::max(1, chains.width() >> (level - 1));
            std::vector<float> data(std::size_t(size) * std::size_t(size) * std::size_t(size) * 4);
            glGetTextureSubImage(chains.id(), level - 1, 0, 0,
                GLint(d) * DirectionalStackLayout::of(v.frame.resolution).stride(level - 1), size, size, size,
                GL_RGBA, GL_FLOAT, GLsizei(data.size() * sizeof(float)), data.data());
            return data;
        }
    if (channel == "emission" && !v.emission && v.albedo) {
        // A scene without emissive materials keeps no emission volume: nothing is emitted anywhere.
        size = std::max(1, v.frame.resolution >> level);
        return std::vector<float>(std::size_t(size) * std::size_t(size) * std::size_t(size) * 4, 0.0f);
    }
    // The channels are the voxel textures of those names in the resource table: the voxels' own, which a
    // sparse grid keeps in its brick pool, and the bounce solve's cells, a dense grid of texels either way.
    const gl::Texture* texture = nullptr;
    bool pooled = false;
    for (const char* name : { resource::kAlbedo, resource::kNormal, resource::kEmission, resource::kRadiance,
             resource::kBounced })
        if (channel == name) {
            texture = m_state->resourcesOf(grid).find(name);
            pooled = true;
        }
    for (const char* name :
        { resource::kBounceCells, resource::kBounceCellsBack, resource::kBounceCellNormals })
        if (channel == name)
            texture = m_state->resourcesOf(grid).find(name);
    if (!texture || !*texture)
        throw std::invalid_argument("no voxel channel '" + channel
            + "' (albedo, normal, emission, radiance, bounced; with bounces in the voxels bounce cells, "
              "bounce "
              "cells, back faces, bounce cell normals)");
    // The cone volume's box levels, where it keeps none of its own.
    if (level > 0 && texture == &v.coneRadiance() && v.inspectionMips)
        texture = &v.inspectionMips;
    if (level == 0 && v.sparse && pooled)
        return readSparseLevel0(v, *texture, size);
    return readTextureLevel(*texture, level, size);
}

const Scene& Renderer::scene() const
{
    return m_state->scene->scene();
}

float Renderer::voxelSize() const
{
    return m_state->voxels.frame.voxelSize();
}
int Renderer::voxelResolution() const
{
    return m_state->voxels.frame.resolution;
}
glm::vec3 Renderer::gridOrigin() const
{
    return m_state->voxels.frame.origin;
}
std::size_t Renderer::voxelBytes() const
{
    std::size_t bytes = m_state->pipeline->resources().byteSize(ResourceGroup::Voxels);
    for (const ClipLevelPass* level : m_state->clipLevels)
        bytes += level->pipeline().resources().byteSize(ResourceGroup::Voxels);
    return bytes;
}
std::vector<VoxelTextureMemory> Renderer::voxelMemory() const
{
    std::vector<VoxelTextureMemory> list = describeVoxelMemory(m_state->pipeline->resources());
    for (const ClipLevelPass* level : m_state->clipLevels)
        for (VoxelTextureMemory texture : describeVoxelMemory(level->pipeline().resources())) {
            texture.name = clipLevelName(level->level(), texture.name);
            list.push_back(std::move(texture));
        }
    return list;
}

std::vector<BrickOccupancy> Renderer::brickOccupancy(int brickSize) const
{
    if (brickSize < 1)
        throw std::invalid_argument("brick size must be at least 1");
    std::vector<BrickOccupancy> grids;
    for (int grid = 0; grid < gridCount(); ++grid) {
        const VoxelVolume& v = m_state->volumeOf(grid);
        BrickOccupancy o;
        o.grid = grid;
        o.resolution = v.frame.resolution;
        o.brickSize = brickSize;
        const int bricks = (o.resolution + brickSize - 1) / brickSize;
        o.totalBricks = std::size_t(bricks) * std::size_t(bricks) * std::size_t(bricks);
        // The static list and the moving objects' list name each voxel once between them (renderFrame).
        std::vector<bool> occupied(o.totalBricks, false);
        for (const OccupiedCellList* list : v.occupiedVoxels(m_state->scene->hasDynamicMeshes()))
            for (const glm::ivec3& c : list->cells()) {
                const glm::ivec3 b = c / brickSize;
                occupied[(std::size_t(b.z) * std::size_t(bricks) + std::size_t(b.y)) * std::size_t(bricks)
                    + std::size_t(b.x)]
                    = true;
                ++o.occupiedVoxels;
            }
        o.occupiedBricks = std::size_t(std::count(occupied.begin(), occupied.end(), true));
        if (v.sparse && brickSize == BrickPool::kBrickVoxels) {
            o.storedBricks = v.bricks.allocatedBricks();
            o.poolSlots
                = std::size_t(v.poolBricks.x) * std::size_t(v.poolBricks.y) * std::size_t(v.poolBricks.z);
        }
        grids.push_back(o);
    }
    return grids;
}

void Renderer::setConeSampleCounting(bool enabled)
{
    if (!enabled)
        m_state->coneSampleCounter.reset();
    else if (!m_state->coneSampleCounter)
        m_state->coneSampleCounter = std::make_unique<ConeSampleCounter>();
    m_state->coneSamples = 0;
}

std::uint64_t Renderer::coneSampleCount() const
{
    return m_state->coneSamples;
}

std::vector<std::string> Renderer::takeGlErrors()
{
    return gl::DebugOutput::takeErrors();
}

} // namespace vct::render
