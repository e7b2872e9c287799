#pragma once

#include "core/AreaLightSet.h"
#include "core/ClosedSurface.h"
#include "core/Frustum.h"
#include "core/ListedTriangles.h"
#include "core/MeshClusters.h"
#include "gl/Buffer.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "gl/VertexArray.h"
#include "scene/Scene.h"

#include <functional>
#include <memory>
#include <vector>

// The GLSL file is the single definition of the shared texture units and light limits.
#include "common/Bindings.glsl"

namespace vct::render {

/** Texture unit of the material table in the passes that read the g-buffer. */
constexpr GLuint kMaterialTableUnit = MATERIAL_TABLE_UNIT;
/** Texture units of the area-light table and the opacity volume its visibility cones trace
 * (common/AreaLights.glsl). */
constexpr GLuint kAreaLightTableUnit = AREA_LIGHT_UNIT;
constexpr GLuint kOpacityUnit = OPACITY_UNIT;

/** Which meshes a draw covers: the voxelizer draws static and dynamic meshes into separate layers. */
enum class MeshFilter { All, Static, Dynamic };

/** A further choice of meshes by their material, so a pass can draw each kind with its own shader variant. */
using MaterialFilter = std::function<bool(const Material&)>;

/** The eye of a perspective view, and how far from it the corners of its near clip plane lie (metres). */
struct Viewpoint {
    glm::vec3 position { 0.0f };
    float nearRadius = 0.0f;
};

/** How GpuScene::dispatchTriangles runs a compute shader over triangles. */
struct TriangleDispatch {
    GLuint vertexBinding = 0; ///< the first of the storage buffers it binds
    GLuint groupSize = 64; ///< the shader's local_size_x
    ListedTriangles* listed = nullptr; ///< where the shader may list triangles for GpuScene::drawListed
    /// Most workgroups a dispatch: a run that needs more goes in parts (GL promises at least 65,535).
    GLuint maxGroups = 65535;
};

/** What one GpuScene::draw covers and in which order. */
struct DrawOptions {
    MeshFilter layer = MeshFilter::All;
    MaterialFilter materials; ///< empty: every material
    /// Clusters of triangles wholly outside it are not drawn (core/MeshClusters); null: all are.
    const Frustum* visibleIn = nullptr;
    /// With a viewpoint, clusters are drawn nearest first, so early depth testing rejects what they hide, and
    /// solid meshes (core/ClosedSurface) the view sees from outside, and meshes of single-sided materials,
    /// are drawn without their back faces.
    /// Only for depth-tested views whose result does not depend on hidden faces.
    const Viewpoint* from = nullptr;
    /// Sets the stencil reference to each mesh's pixel class (core/PixelClass.h) before drawing it.
    bool stencilPixelClass = false;
};

/** The scene's meshes, materials and textures on the GPU. Created with a current context. */
class GpuScene {
public:
    explicit GpuScene(const Scene& scene);

    /**
     * Draws every mesh the options select with `program` bound, setting the per-mesh uniforms the shaders in
     * shaders/common/Material.glsl read (uModel, uNormalMatrix, material fields) and binding the albedo
     * texture at unit `albedoUnit`.
     */
    void draw(const gl::Program& program, const DrawOptions& options, GLuint albedoUnit) const;
    /**
     * Runs `program`, a compute shader of `dispatch.groupSize` invocations a workgroup, with one invocation
     * per triangle of what draw() would draw with the same options (its `from` is ignored). Per run of
     * triangles it sets the uniforms draw() sets, binds the mesh's vertices (eight floats each: position,
     * normal, uv) and indices as storage buffers `dispatch.vertexBinding` and the next, and sets uFirstIndex,
     * uTriangleCount and uVertexCount. A shader that lists triangles for drawListed() needs `dispatch.listed`
     * (without it, it would write to whatever buffers are bound there): its index buffer and commands are
     * bound as the two storage buffers after those, and uListRun (the run's command) and uListFirst (its
     * segment's first index) are set.
     */
    void dispatchTriangles(const gl::Program& program, const DrawOptions& options, GLuint albedoUnit,
        const TriangleDispatch& dispatch) const;
    /** Draws what a dispatchTriangles() listed, run by run, with the uniforms draw() sets. */
    void drawListed(const gl::Program& program, const ListedTriangles& listed, GLuint albedoUnit) const;
    /**
     * Binds the material table (shaders/common/MaterialTable.glsl) to texture unit `unit`: the per-material
     * values the g-buffer does not store per pixel, found through the material index it does.
     */
    void bindMaterialTable(GLuint unit) const;
    /** The emissive triangles as area lights (rebuilt when an emitter moves or an emission changes). */
    const AreaLightSet& areaLights() const { return m_areaLights; }
    /** Grows each time the area lights are rebuilt. */
    std::uint64_t areaLightsVersion() const { return m_areaLightsVersion; }
    /** Binds the area-light table (shaders/common/AreaLights.glsl) to texture unit `unit`. */
    void bindAreaLightTable(GLuint unit) const;
    void setTransform(std::size_t mesh, const glm::mat4& transform);
    /** Shows or hides a mesh (Mesh::visible); its buffers stay. */
    void setVisible(std::size_t mesh, bool visible);
    void setMaterial(std::size_t index, const Material& material);
    void setLights(const std::vector<PointLight>& points, const std::vector<DirectionalLight>& directionals,
        const std::vector<SurfaceLight>& surfaces);
    const Scene& scene() const { return m_scene; }
    /** The material a mesh is drawn with: its own, or the default one when its index is out of range. */
    const Material& materialOf(std::size_t mesh) const;
    std::size_t meshCount() const { return m_meshes.size(); }
    bool hasDynamicMeshes() const;

private:
    struct GpuMesh {
        gl::Buffer vertices;
        gl::Buffer indices; ///< in cluster order
        gl::VertexArray vao;
        GLsizei indexCount = 0;
        std::vector<MeshCluster> clusters;
        std::unique_ptr<ClosedSurface> surface;
        // The last answer of cullsBackFaces(), for the six faces of a cube map and for repeated frames.
        mutable glm::vec3 cullViewpoint { 0.0f };
        mutable glm::mat4 cullTransform { 0.0f };
        mutable bool cullBack = false;
    };
    /** Consecutive triangles of one mesh that one draw call covers. */
    struct Run {
        std::size_t mesh;
        std::uint32_t firstIndex, indexCount;
        float distance; ///< from DrawOptions::from, for the order of draws
    };
    /** The runs draw() covers with these options, in its order. */
    std::vector<Run> runsOf(const DrawOptions& options) const;
    void bindMesh(const gl::Program& program, std::size_t mesh, GLuint albedoUnit) const;
    /** Whether back faces of the mesh can be left out of a view from @p from without changing what it sees.
     */
    bool cullsBackFaces(std::size_t mesh, const Viewpoint& from) const;
    /** Whether the mesh's material shows front faces only (Material::doubleSided off). */
    bool showsFrontOnly(std::size_t mesh) const;
    void uploadMaterialTable();
    void rebuildAreaLights();

    Scene m_scene; // a copy: transforms and materials change through setters, meshes never
    std::vector<GpuMesh> m_meshes;
    std::vector<gl::Texture> m_textures;
    gl::Texture m_whiteTexture;
    gl::Buffer m_materialTable; // one entry per material, then the fallback for meshes without a valid one
    gl::Texture m_materialTableView; // rgba32f buffer texture over m_materialTable
    std::size_t m_materialTableBytes = 0;
    AreaLightSet m_areaLights;
    std::uint64_t m_areaLightsVersion = 0;
    gl::Buffer m_areaLightTable;
    gl::Texture m_areaLightTableView; // rgba32f buffer texture over m_areaLightTable
};

} // namespace vct::render
