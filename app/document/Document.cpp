#include "Document.h"

#include "Enclosure.h"
#include "NewLight.h"
#include "ProjectFile.h"
#include "SceneLoader.h"
#include "commands/AddLightCommand.h"
#include "commands/DeleteNodeCommand.h"
#include "commands/DuplicateNodeCommand.h"
#include "commands/ImportModelCommand.h"
#include "commands/RemoveLightCommand.h"
#include "commands/SetBookmarksCommand.h"
#include "commands/SetLightCommand.h"
#include "commands/SetMaterialCommand.h"
#include "commands/SetNodePropertiesCommand.h"
#include "commands/SetNodeTransformCommand.h"
#include "commands/SetRenderSettingsCommand.h"

#include <QDir>
#include <QFileInfo>
#include <QtDebug>

#include <algorithm>
#include <optional>

namespace vct::doc {

namespace {

const QString kBuiltinPrefix = QStringLiteral("builtin:");

/** Model paths become absolute so that a project can store them relative to itself; other specs stay. */
QString normalizedSpec(const QString& spec)
{
    if (spec.startsWith(kBuiltinPrefix) || spec.startsWith(QStringLiteral(":/")) || spec.isEmpty())
        return spec;
    return QDir::cleanPath(QFileInfo(spec).absoluteFilePath());
}

/** Splits an RGB emission into a colour with its largest channel 1 and that channel as the intensity. */
void splitColor(const glm::vec3& value, glm::vec3* color, float* intensity)
{
    const float peak = std::max({ value.x, value.y, value.z });
    if (peak > 0.0f) {
        *color = value / peak;
        *intensity = peak;
    } else {
        *color = glm::vec3(1.0f);
        *intensity = 0.0f;
    }
}

/** The type as the first word of a light's default name ("Rect light 2"). */
QString lightKindName(LightType type)
{
    switch (type) {
    case LightType::Point:
        return QStringLiteral("Point");
    case LightType::Directional:
        return QStringLiteral("Directional");
    case LightType::Spot:
        return QStringLiteral("Spot");
    case LightType::Rect:
        return QStringLiteral("Rect");
    case LightType::Disk:
        return QStringLiteral("Disk");
    }
    return QStringLiteral("Point");
}

int countLights(const std::vector<LightNode>& lights, LightType type)
{
    return int(
        std::count_if(lights.begin(), lights.end(), [type](const LightNode& l) { return l.type == type; }));
}

/**
 * The scene's lights as LightNodes with ids from `nextId` (advanced), named after their type and numbered on
 * from the lights already in `existing`.
 */
std::vector<LightNode> lightsFromScene(
    const render::Scene& scene, const std::vector<LightNode>& existing, quint64* nextId)
{
    std::vector<LightNode> lights;
    int pointNumber = countLights(existing, LightType::Point);
    int spotNumber = countLights(existing, LightType::Spot);
    for (const render::PointLight& p : scene.pointLights) {
        LightNode l;
        l.id = (*nextId)++;
        if (p.isSpot()) {
            l.name = QStringLiteral("Spot light %1").arg(++spotNumber);
            l.type = LightType::Spot;
            l.direction = p.spotDirection;
            l.spotInnerDeg = p.spotInnerDeg;
            l.spotOuterDeg = p.spotOuterDeg;
        } else {
            l.name = QStringLiteral("Point light %1").arg(++pointNumber);
            l.type = LightType::Point;
        }
        l.position = p.position;
        l.radius = p.radius;
        splitColor(p.intensity, &l.color, &l.intensity);
        l.castsShadows = p.castsShadows;
        lights.push_back(l);
    }
    int directionalNumber = countLights(existing, LightType::Directional);
    for (const render::DirectionalLight& d : scene.directionalLights) {
        LightNode l;
        l.id = (*nextId)++;
        l.name = QStringLiteral("Directional light %1").arg(++directionalNumber);
        l.type = LightType::Directional;
        l.direction = d.direction;
        l.angularDiameterDeg = d.angularDiameterDeg;
        splitColor(d.irradiance, &l.color, &l.intensity);
        l.castsShadows = d.castsShadows;
        lights.push_back(l);
    }
    int rectNumber = countLights(existing, LightType::Rect);
    int diskNumber = countLights(existing, LightType::Disk);
    for (const render::SurfaceLight& s : scene.surfaceLights) {
        LightNode l;
        l.id = (*nextId)++;
        if (s.shape == render::SurfaceLight::Shape::Disk) {
            l.name = QStringLiteral("Disk light %1").arg(++diskNumber);
            l.type = LightType::Disk;
        } else {
            l.name = QStringLiteral("Rect light %1").arg(++rectNumber);
            l.type = LightType::Rect;
        }
        l.position = s.centre;
        l.direction = s.direction;
        l.areaWidth = s.width;
        l.areaHeight = s.height;
        l.areaRotationDeg = s.rotationDeg;
        splitColor(s.radiance, &l.color, &l.intensity);
        l.castsShadows = s.castsShadows;
        lights.push_back(l);
    }
    return lights;
}

/**
 * A source's materials as the document keeps them: texture indices moved past the `textureBase` textures of
 * the sources before it, matching the concatenation in Document::buildRenderScene().
 */
std::vector<render::Material> materialsFromScene(const render::Scene& scene, std::size_t textureBase)
{
    std::vector<render::Material> materials = scene.materials;
    for (render::Material& m : materials)
        if (m.albedoTexture >= 0)
            m.albedoTexture += int(textureBase);
    return materials;
}

/** One node per mesh of `scene`, drawing from `source`, material indices shifted by `materialOffset`. */
std::vector<SceneNode> nodesFromScene(
    const render::Scene& scene, int source, int materialOffset, quint64* nextId)
{
    std::vector<SceneNode> nodes;
    for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
        const render::Mesh& mesh = scene.meshes[i];
        SceneNode n;
        n.id = (*nextId)++;
        n.name = mesh.name.empty() ? QStringLiteral("mesh %1").arg(i + 1) : QString::fromStdString(mesh.name);
        n.source = source;
        n.mesh = int(i);
        n.material = mesh.material + materialOffset;
        n.dynamic = mesh.dynamic;
        nodes.push_back(n);
    }
    return nodes;
}

/**
 * Nodes and lights of a model whose up axis is `up`, stood upright: each node turned by its placement (a
 * rotation the Transform panel shows and the project keeps), each light with them.
 */
void standUpright(std::vector<SceneNode>& nodes, std::vector<LightNode>& lights, SceneLoader::UpAxis up)
{
    if (up == SceneLoader::UpAxis::Y)
        return;
    // NodeTransform applies T * Rz * Ry * Rx * S: fresh nodes turned -90 degrees about x alone are exactly
    // SceneLoader::uprightRotation().
    for (SceneNode& node : nodes)
        node.transform.rotationDeg.x -= 90.0f;
    const glm::mat3 turn(SceneLoader::uprightRotation(up));
    for (LightNode& light : lights) {
        light.position = turn * light.position;
        light.direction = turn * light.direction;
    }
}

} // namespace

Document::Document(QObject* parent)
    : QObject(parent)
{
    // Only an undo (or a command dropped as a no-op) lowers the index: a push raises it or merges.
    connect(&m_undoStack, &QUndoStack::indexChanged, this, [this](int index) {
        if (index < m_undoIndex)
            endEditGesture();
        m_undoIndex = index;
    });
}

Document::~Document()
{
    // Commands hold a pointer to this document; drop them while it is still whole.
    m_undoStack.clear();
}

bool Document::newFromScene(const QString& spec, QString* error, float unitScale, SceneLoader::UpAxis up)
{
    const SceneSource source { normalizedSpec(spec), unitScale };
    render::Scene scene;
    SceneLoadInfo info;
    if (!SceneLoader::load(source.spec, scene, error, &info, unitScale))
        return false;

    DocumentState state;
    state.sources.push_back(source);
    state.nodes = nodesFromScene(scene, 0, 0, &state.nextId);
    // Source 0's textures come first in the concatenation, so its texture indices stand as they are.
    state.materials = scene.materials;
    state.lights = lightsFromScene(scene, {}, &state.nextId);
    standUpright(state.nodes, state.lights, up);
    // The scene as the document shows it: the cached geometry stays as the file has it, the nodes turn it.
    std::optional<render::Scene> turned;
    if (up != SceneLoader::UpAxis::Y) {
        turned = SceneLoader::uprightScene(scene, up);
        if (!info.hasCameraFile)
            turned->camera = SceneLoader::frameScene(*turned);
    }
    const render::Scene& shown = turned ? *turned : scene;
    state.camera = shown.camera;
    m_openNote.clear();
    // A model that brings no light would open black: give it one and say so. Under a roof a sun would not
    // reach the camera, so there it is a point light where the camera looks.
    if (!source.spec.startsWith(QStringLiteral("builtin:")) && state.lights.empty()
        && !scene.hasEmissiveMaterial()) {
        const bool inside = Enclosure::insideRoom(shown, shown.camera.position);
        LightNode light = NewLight::make(
            inside ? LightType::Point : LightType::Directional, shown.bounds(), shown.camera.lookAt, {});
        light.id = state.nextId++;
        light.name = QStringLiteral("%1 light 1").arg(lightKindName(light.type));
        state.lights.push_back(light);
        m_openNote = inside
            ? QStringLiteral(
                "The model brings no light: added a point light where the camera looks (Light panel)")
            : QStringLiteral("The model brings no light: added a directional light, a sun (Light panel)");
    }

    m_undoStack.clear();
    m_state = std::move(state);
    m_savedCamera = m_state.camera;
    m_geometry.clear();
    m_geometry.emplace(geometryKey(source), std::move(scene));
    m_undoStack.setClean();
    if (!m_filePath.isEmpty()) {
        m_filePath.clear();
        emit filePathChanged(m_filePath);
    }
    setSelectedNode(-1);
    notify({ ChangeEvent::Kind::Reset, -1 });
    return true;
}

bool Document::openProject(const QString& path, QString* error)
{
    const QString absolutePath = QFileInfo(path).absoluteFilePath();
    DocumentState state;
    WholeSources whole;
    if (!ProjectFile::load(absolutePath, &state, error, m_modelRoot, &whole))
        return false;

    const QString name = QDir::toNativeSeparators(absolutePath);
    auto fail = [&](const QString& field, const QString& problem) {
        if (error)
            *error = QStringLiteral("%1: field '%2': %3").arg(name, field, problem);
        return false;
    };
    std::map<GeometryKey, render::Scene> geometry;
    std::size_t textureCount = 0;
    for (std::size_t i = 0; i < state.sources.size(); ++i) {
        const SceneSource& source = state.sources[i];
        auto it = geometry.find(geometryKey(source));
        if (it == geometry.end()) {
            render::Scene scene;
            QString problem;
            if (!SceneLoader::load(source.spec, scene, &problem, nullptr, source.unitScale))
                return fail(QStringLiteral("sources[%1].spec").arg(i), problem);
            it = geometry.emplace(geometryKey(source), std::move(scene)).first;
        }
        if (whole.used) {
            // As an import in this order would make them; ids follow the project's, from its next_id.
            std::vector<SceneNode> nodes
                = nodesFromScene(it->second, int(i), int(state.materials.size()), &state.nextId);
            for (SceneNode& node : nodes) {
                node.transform = whole.placement[i];
                node.dynamic = whole.dynamic[i];
            }
            std::vector<render::Material> materials = materialsFromScene(it->second, textureCount);
            state.nodes.insert(state.nodes.end(), nodes.begin(), nodes.end());
            state.materials.insert(state.materials.end(), materials.begin(), materials.end());
        }
        textureCount += it->second.textures.size();
    }
    // The checks the project file alone cannot make: they need the geometry.
    for (std::size_t i = 0; i < state.nodes.size(); ++i) {
        const SceneNode& node = state.nodes[i];
        const std::size_t meshes
            = geometry.at(geometryKey(state.sources[std::size_t(node.source)])).meshes.size();
        if (std::size_t(node.mesh) >= meshes)
            return fail(QStringLiteral("nodes[%1].mesh").arg(i),
                QStringLiteral("source %1 has %2 meshes, so %3 is out of range")
                    .arg(node.source)
                    .arg(meshes)
                    .arg(node.mesh));
    }
    for (std::size_t i = 0; i < state.materials.size(); ++i) {
        const int texture = state.materials[i].albedoTexture;
        if (texture >= 0 && std::size_t(texture) >= textureCount)
            return fail(QStringLiteral("materials[%1].albedo_texture").arg(i),
                QStringLiteral("the sources have %1 textures, so %2 is out of range")
                    .arg(textureCount)
                    .arg(texture));
    }

    m_undoStack.clear();
    m_state = std::move(state);
    m_savedCamera = m_state.camera;
    m_geometry = std::move(geometry);
    m_undoStack.setClean();
    m_filePath = absolutePath;
    emit filePathChanged(m_filePath);
    setSelectedNode(-1);
    notify({ ChangeEvent::Kind::Reset, -1 });
    return true;
}

bool Document::recoverProject(const QString& path, QString* error)
{
    if (!openProject(path, error))
        return false;
    // Nothing on the undo stack, yet not what any file holds: no state of the stack is clean until a save.
    m_undoStack.resetClean();
    m_filePath.clear();
    emit filePathChanged(m_filePath);
    return true;
}

bool Document::saveProject(const QString& path, QString* error)
{
    const QString absolutePath = QFileInfo(path).absoluteFilePath();
    if (!ProjectFile::save(absolutePath, m_state, error, m_modelRoot))
        return false;
    m_savedCamera = m_state.camera;
    m_undoStack.setClean();
    m_filePath = absolutePath;
    emit filePathChanged(m_filePath);
    return true;
}

bool Document::importModel(const QString& path, QString* error, float unitScale, SceneLoader::UpAxis up)
{
    const SceneSource source { normalizedSpec(path), unitScale };
    render::Scene scene;
    if (m_geometry.find(geometryKey(source)) == m_geometry.end()
        && !SceneLoader::load(source.spec, scene, error, nullptr, unitScale))
        return false;
    return addImportedModel(path, std::move(scene), unitScale, up);
}

bool Document::addImportedModel(
    const QString& path, render::Scene loaded, float unitScale, SceneLoader::UpAxis up)
{
    // The document could not save or reopen such a source.
    if (const QString problem = SceneLoader::unitScaleProblem(unitScale); !problem.isEmpty()) {
        qWarning("Document::addImportedModel: %s", qPrintable(problem));
        return false;
    }
    const SceneSource source { normalizedSpec(path), unitScale };
    // A model already imported keeps its cached geometry: nodes of the earlier source index into it.
    auto it = m_geometry.find(geometryKey(source));
    if (it == m_geometry.end())
        it = m_geometry.emplace(geometryKey(source), std::move(loaded)).first;
    const render::Scene& scene = it->second;

    std::size_t textureBase = 0;
    for (std::size_t i = 0; i < m_state.sources.size(); ++i)
        textureBase += sourceScene(int(i)).textures.size();
    std::vector<render::Material> materials = materialsFromScene(scene, textureBase);

    quint64 nextId = m_state.nextId;
    std::vector<SceneNode> nodes
        = nodesFromScene(scene, int(m_state.sources.size()), int(m_state.materials.size()), &nextId);
    std::vector<LightNode> lights = lightsFromScene(scene, m_state.lights, &nextId);
    standUpright(nodes, lights, up);
    m_undoStack.push(new ImportModelCommand(
        this, source, std::move(materials), std::move(nodes), std::move(lights), nextId));
    return true;
}

void Document::setNodeTransform(int node, const NodeTransform& transform, NodeTransformField field)
{
    if (node < 0 || std::size_t(node) >= m_state.nodes.size()
        || m_state.nodes[std::size_t(node)].transform == transform)
        return;
    m_undoStack.push(new SetNodeTransformCommand(this, node, transform, field));
}

void Document::setNodeName(int node, const QString& name)
{
    if (node < 0 || std::size_t(node) >= m_state.nodes.size()
        || m_state.nodes[std::size_t(node)].name == name)
        return;
    auto properties = SetNodePropertiesCommand::propertiesOf(*this, node);
    properties.name = name;
    m_undoStack.push(new SetNodePropertiesCommand(this, node, properties));
}

void Document::setNodeVisible(int node, bool visible)
{
    if (node < 0 || std::size_t(node) >= m_state.nodes.size()
        || m_state.nodes[std::size_t(node)].visible == visible)
        return;
    auto properties = SetNodePropertiesCommand::propertiesOf(*this, node);
    properties.visible = visible;
    m_undoStack.push(new SetNodePropertiesCommand(this, node, properties));
}

void Document::setNodeDynamic(int node, bool dynamic)
{
    if (node < 0 || std::size_t(node) >= m_state.nodes.size()
        || m_state.nodes[std::size_t(node)].dynamic == dynamic)
        return;
    auto properties = SetNodePropertiesCommand::propertiesOf(*this, node);
    properties.dynamic = dynamic;
    m_undoStack.push(new SetNodePropertiesCommand(this, node, properties));
}

void Document::duplicateNode(int node)
{
    if (node < 0 || std::size_t(node) >= m_state.nodes.size())
        return;
    m_undoStack.push(new DuplicateNodeCommand(this, node));
}

void Document::deleteNode(int node)
{
    if (node < 0 || std::size_t(node) >= m_state.nodes.size())
        return;
    m_undoStack.push(new DeleteNodeCommand(this, node));
}

void Document::setMaterial(int index, const render::Material& material, MaterialField field)
{
    if (index < 0 || std::size_t(index) >= m_state.materials.size()
        || sameMaterial(m_state.materials[std::size_t(index)], material))
        return;
    m_undoStack.push(new SetMaterialCommand(this, index, material, field));
}

void Document::setLight(int index, const LightNode& light, LightField field)
{
    if (index < 0 || std::size_t(index) >= m_state.lights.size())
        return;
    LightNode edited = light;
    edited.id = m_state.lights[std::size_t(index)].id;
    if (edited == m_state.lights[std::size_t(index)])
        return;
    m_undoStack.push(new SetLightCommand(this, index, edited, field));
}

void Document::addBookmark(const QString& name)
{
    std::vector<CameraBookmark> bookmarks = m_state.bookmarks;
    CameraBookmark bookmark { name.trimmed(), m_state.camera };
    if (bookmark.name.isEmpty())
        bookmark.name = QStringLiteral("View %1").arg(bookmarks.size() + 1);
    bookmarks.push_back(bookmark);
    m_undoStack.push(
        new SetBookmarksCommand(this, std::move(bookmarks), tr("Bookmark %1").arg(bookmark.name)));
}

void Document::removeBookmark(int index)
{
    if (index < 0 || std::size_t(index) >= m_state.bookmarks.size())
        return;
    std::vector<CameraBookmark> bookmarks = m_state.bookmarks;
    const QString name = bookmarks[std::size_t(index)].name;
    bookmarks.erase(bookmarks.begin() + index);
    m_undoStack.push(new SetBookmarksCommand(this, std::move(bookmarks), tr("Remove bookmark %1").arg(name)));
}

void Document::addLight(const LightNode& light)
{
    LightNode added = light;
    if (added.name.isEmpty()) {
        const QString kind = lightKindName(added.type);
        added.name = QStringLiteral("%1 light %2").arg(kind).arg(countLights(m_state.lights, added.type) + 1);
    }
    m_undoStack.push(new AddLightCommand(this, added));
}

void Document::removeLight(int index)
{
    if (index < 0 || std::size_t(index) >= m_state.lights.size())
        return;
    m_undoStack.push(new RemoveLightCommand(this, index));
}

void Document::setSettings(const render::RenderSettings& settings)
{
    if (sameSettings(m_state.settings, settings))
        return;
    if (const std::string problem = settings.validate(); !problem.empty()) {
        qWarning("Document::setSettings: ignoring invalid settings: %s", problem.c_str());
        return;
    }
    m_undoStack.push(new SetRenderSettingsCommand(this, settings));
}

void Document::setCamera(const render::Camera& camera)
{
    if (sameCamera(m_state.camera, camera))
        return;
    m_state.camera = camera;
    notify({ ChangeEvent::Kind::Camera, -1 });
}

void Document::setSelectedNode(int node)
{
    if (node < 0 || std::size_t(node) >= m_state.nodes.size())
        node = -1;
    if (node == m_selectedNode)
        return;
    m_selectedNode = node;
    emit selectionChanged(node);
}

quint64 Document::selectedNodeId() const
{
    if (m_selectedNode < 0 || std::size_t(m_selectedNode) >= m_state.nodes.size())
        return 0;
    return m_state.nodes[std::size_t(m_selectedNode)].id;
}

void Document::selectNodeById(quint64 id)
{
    setSelectedNode(id == 0 ? -1 : nodeIndex(id));
}

int Document::nodeIndex(quint64 id) const
{
    const auto it = std::find_if(
        m_state.nodes.begin(), m_state.nodes.end(), [id](const SceneNode& n) { return n.id == id; });
    return it == m_state.nodes.end() ? -1 : int(it - m_state.nodes.begin());
}

int Document::lightIndex(quint64 id) const
{
    const auto it = std::find_if(
        m_state.lights.begin(), m_state.lights.end(), [id](const LightNode& l) { return l.id == id; });
    return it == m_state.lights.end() ? -1 : int(it - m_state.lights.begin());
}

render::Scene Document::buildRenderScene(std::vector<int>* meshToNode, bool hidden) const
{
    render::Scene scene;
    if (meshToNode)
        meshToNode->clear();
    // Texture indices in the document's materials index the textures of all sources in source order (see
    // importModel), so the concatenation is the whole remapping.
    for (std::size_t i = 0; i < m_state.sources.size(); ++i) {
        const auto& textures = sourceScene(int(i)).textures;
        scene.textures.insert(scene.textures.end(), textures.begin(), textures.end());
    }
    scene.materials = m_state.materials;
    for (std::size_t i = 0; i < m_state.nodes.size(); ++i) {
        const SceneNode& node = m_state.nodes[i];
        if (!node.visible && !hidden)
            continue;
        const render::Scene& source = sourceScene(node.source);
        if (node.mesh < 0 || std::size_t(node.mesh) >= source.meshes.size())
            continue;
        render::Mesh mesh = source.meshes[std::size_t(node.mesh)];
        mesh.transform = node.transform.matrix() * mesh.transform;
        mesh.material = node.material;
        mesh.dynamic = node.dynamic;
        mesh.visible = node.visible;
        scene.meshes.push_back(std::move(mesh));
        if (meshToNode)
            meshToNode->push_back(int(i));
    }
    for (const LightNode& light : m_state.lights) {
        if (light.isSurface())
            scene.surfaceLights.push_back(light.surfaceLight());
        else if (light.isPointLike())
            scene.pointLights.push_back(light.pointLight());
        else
            scene.directionalLights.push_back(light.directionalLight());
    }
    scene.camera = m_state.camera;
    return scene;
}

glm::mat4 Document::nodeWorldTransform(int node) const
{
    if (node < 0 || std::size_t(node) >= m_state.nodes.size())
        return glm::mat4(1.0f);
    const SceneNode& n = m_state.nodes[std::size_t(node)];
    const render::Scene& source = sourceScene(n.source);
    const glm::mat4 imported = n.mesh >= 0 && std::size_t(n.mesh) < source.meshes.size()
        ? source.meshes[std::size_t(n.mesh)].transform
        : glm::mat4(1.0f);
    return n.transform.matrix() * imported;
}

render::Aabb Document::nodeWorldBounds(int node) const
{
    render::Aabb bounds;
    if (node < 0 || std::size_t(node) >= m_state.nodes.size())
        return bounds;
    const SceneNode& n = m_state.nodes[std::size_t(node)];
    const render::Scene& source = sourceScene(n.source);
    if (n.mesh < 0 || std::size_t(n.mesh) >= source.meshes.size())
        return bounds;
    const glm::mat4 world = nodeWorldTransform(node);
    for (const glm::vec3& p : source.meshes[std::size_t(n.mesh)].positions)
        bounds.extend(glm::vec3(world * glm::vec4(p, 1.0f)));
    return bounds;
}

render::Aabb Document::sceneBounds() const
{
    render::Aabb bounds;
    for (std::size_t i = 0; i < m_state.nodes.size(); ++i)
        if (m_state.nodes[i].visible)
            bounds.extend(nodeWorldBounds(int(i)));
    return bounds;
}

const render::Scene& Document::sourceScene(int source) const
{
    static const render::Scene kEmpty;
    if (source < 0 || std::size_t(source) >= m_state.sources.size())
        return kEmpty;
    const auto it = m_geometry.find(geometryKey(m_state.sources[std::size_t(source)]));
    return it == m_geometry.end() ? kEmpty : it->second;
}

void Document::notify(const ChangeEvent& event)
{
    emit changed(event);
}

} // namespace vct::doc
