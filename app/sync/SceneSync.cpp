#include "sync/SceneSync.h"

#include "Renderer.h"
#include "document/Document.h"

namespace vct::sync {

namespace {

void applyLights(const doc::DocumentState& state, render::Renderer& renderer)
{
    std::vector<render::PointLight> points;
    std::vector<render::DirectionalLight> directionals;
    std::vector<render::SurfaceLight> surfaces;
    for (const doc::LightNode& light : state.lights) {
        if (light.isSurface())
            surfaces.push_back(light.surfaceLight());
        else if (light.isPointLike())
            points.push_back(light.pointLight());
        else
            directionals.push_back(light.directionalLight());
    }
    renderer.setLights(points, directionals, surfaces);
}

} // namespace

SceneSync::SceneSync(doc::Document* document, QObject* parent)
    : QObject(parent)
    , m_document(document)
{
    connect(document, &doc::Document::changed, this, &SceneSync::onChanged);
}

void SceneSync::onChanged(const doc::ChangeEvent& event)
{
    using Kind = doc::ChangeEvent::Kind;
    if (event.kind == Kind::Reset)
        m_needsReset = true;
    else if (event.kind == Kind::Structure)
        m_structureChanged = true;
    else if (event.kind != Kind::Camera) // the camera is read every frame
        m_pending.push_back(event);
}

void SceneSync::apply(render::Renderer& renderer, bool fullRebuild)
{
    using Kind = doc::ChangeEvent::Kind;
    const doc::DocumentState& state = m_document->state();
    if (m_needsReset || fullRebuild || (m_structureChanged && !applyVisibility(renderer))) {
        renderer.setSettings(state.settings);
        rebuildScene(renderer);
        m_needsReset = false;
        m_structureChanged = false;
        m_pending.clear();
        return;
    }
    m_structureChanged = false;
    bool lights = false, settings = false;
    std::vector<int> materials, nodes;
    for (const doc::ChangeEvent& event : m_pending) {
        switch (event.kind) {
        case Kind::Lights:
            lights = true;
            break;
        case Kind::Settings:
            settings = true;
            break;
        case Kind::Material:
            materials.push_back(event.index);
            break;
        case Kind::NodeTransform:
            nodes.push_back(event.index);
            break;
        case Kind::NodeProperty:
            // The dynamic flag decides which voxel layer a mesh lives in: rebuild the scene. A rename
            // changes nothing the renderer has.
            if (event.index < 0 || std::size_t(event.index) >= m_nodeDynamic.size()
                || m_nodeDynamic[std::size_t(event.index)] != state.nodes[std::size_t(event.index)].dynamic)
                rebuildScene(renderer);
            break;
        default:
            break;
        }
    }
    m_pending.clear();
    if (settings)
        renderer.setSettings(state.settings);
    if (lights)
        applyLights(state, renderer);
    for (int index : materials)
        if (index >= 0 && std::size_t(index) < state.materials.size())
            renderer.setMaterial(std::size_t(index), state.materials[std::size_t(index)]);
    for (int node : nodes)
        for (std::size_t mesh = 0; mesh < m_meshToNode.size(); ++mesh)
            if (m_meshToNode[mesh] == node)
                renderer.setMeshTransform(mesh, m_document->nodeWorldTransform(node));
}

bool SceneSync::applyVisibility(render::Renderer& renderer)
{
    const std::vector<doc::SceneNode>& nodes = m_document->state().nodes;
    if (nodes.size() != m_nodeIds.size())
        return false;
    for (std::size_t i = 0; i < nodes.size(); ++i)
        if (nodes[i].id != m_nodeIds[i])
            return false;
    for (std::size_t mesh = 0; mesh < m_meshToNode.size(); ++mesh) {
        const std::size_t node = std::size_t(m_meshToNode[mesh]);
        renderer.setMeshVisible(mesh, nodes[node].visible);
    }
    return true;
}

void SceneSync::rebuildScene(render::Renderer& renderer)
{
    // Hidden nodes' meshes go to the renderer too, marked hidden: showing one again is then a flag, not a
    // new scene with every buffer and texture uploaded again.
    renderer.setScene(m_document->buildRenderScene(&m_meshToNode, true));
    m_nodeDynamic.clear();
    m_nodeIds.clear();
    for (const doc::SceneNode& node : m_document->state().nodes) {
        m_nodeDynamic.push_back(node.dynamic);
        m_nodeIds.push_back(node.id);
    }
}

} // namespace vct::sync
