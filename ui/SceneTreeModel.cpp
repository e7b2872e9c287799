#include "SceneTreeModel.h"

#include "document/Document.h"

#include <QFont>
#include <QGuiApplication>
#include <QPalette>

namespace vct::ui {

namespace {

// internalId of an item: its group's children carry the group + 1; top-level items carry 0.
constexpr quintptr kTopLevel = 0;
constexpr quintptr kNodeItem = 1 + SceneTreeModel::SceneGroup;
constexpr quintptr kLightItem = 1 + SceneTreeModel::LightsGroup;

QString lightTypeName(doc::LightType type)
{
    switch (type) {
    case doc::LightType::Directional:
        return SceneTreeModel::tr("Directional");
    case doc::LightType::Spot:
        return SceneTreeModel::tr("Spot");
    case doc::LightType::Rect:
        return SceneTreeModel::tr("Rect");
    case doc::LightType::Disk:
        return SceneTreeModel::tr("Disk");
    case doc::LightType::Point:
        break;
    }
    return SceneTreeModel::tr("Point");
}

/** What the light's scalar measures, with its unit: "intensity %1 W/sr". */
QString lightQuantity(const doc::LightNode& light)
{
    if (light.isSurface())
        return SceneTreeModel::tr("radiance %1 W/(m² sr)").arg(double(light.intensity));
    if (light.type == doc::LightType::Directional)
        return SceneTreeModel::tr("intensity %1 W/m²").arg(double(light.intensity));
    return SceneTreeModel::tr("intensity %1 W/sr").arg(double(light.intensity));
}

/**
 * ", 1 × 0.5 m" for a rect, ", 0.3 m across" for a disk, ", radius 0.05 m" or ", 0.53° across" for a point,
 * spot or directional light with a size; nothing for one without.
 */
QString lightSize(const doc::LightNode& light)
{
    if (light.type == doc::LightType::Rect)
        return SceneTreeModel::tr(", %1 × %2 m").arg(double(light.areaWidth)).arg(double(light.areaHeight));
    if (light.type == doc::LightType::Disk)
        return SceneTreeModel::tr(", %1 m across").arg(double(light.areaWidth));
    if (light.isPointLike() && light.radius > 0.0f)
        return SceneTreeModel::tr(", radius %1 m").arg(double(light.radius));
    if (light.type == doc::LightType::Directional && light.angularDiameterDeg > 0.0f)
        return SceneTreeModel::tr(", %1° across").arg(double(light.angularDiameterDeg));
    return {};
}

} // namespace

SceneTreeModel::SceneTreeModel(QObject* parent)
    : QAbstractItemModel(parent)
{
}

void SceneTreeModel::setDocument(doc::Document* document)
{
    if (m_document == document)
        return;
    disconnect(m_connection);
    m_document = document;
    if (m_document)
        m_connection = connect(m_document, &doc::Document::changed, this, &SceneTreeModel::onDocumentChanged);
    reset();
}

int SceneTreeModel::nodeIndex(const QModelIndex& index)
{
    return index.isValid() && index.internalId() == kNodeItem ? index.row() : -1;
}

int SceneTreeModel::lightIndex(const QModelIndex& index)
{
    return index.isValid() && index.internalId() == kLightItem ? index.row() : -1;
}

QModelIndex SceneTreeModel::indexForNode(int node, int column) const
{
    if (node < 0 || node >= int(m_nodeIds.size()) || column < 0 || column >= ColumnCount)
        return {};
    return createIndex(node, column, kNodeItem);
}

QModelIndex SceneTreeModel::indexForLight(int light, int column) const
{
    if (light < 0 || light >= int(m_lightIds.size()) || column < 0 || column >= ColumnCount)
        return {};
    return createIndex(light, column, kLightItem);
}

QModelIndex SceneTreeModel::groupIndex(Group group) const
{
    return createIndex(int(group), NameColumn, kTopLevel);
}

QModelIndex SceneTreeModel::index(int row, int column, const QModelIndex& parent) const
{
    if (!hasIndex(row, column, parent))
        return {};
    if (!parent.isValid())
        return createIndex(row, column, kTopLevel);
    return createIndex(row, column, quintptr(1 + parent.row()));
}

QModelIndex SceneTreeModel::parent(const QModelIndex& child) const
{
    if (!child.isValid() || child.internalId() == kTopLevel)
        return {};
    return createIndex(int(child.internalId() - 1), NameColumn, kTopLevel);
}

int SceneTreeModel::rowCount(const QModelIndex& parent) const
{
    if (!parent.isValid())
        return GroupCount;
    // Only column 0 has children, as QAbstractItemModelTester and the views expect of a tree.
    if (parent.internalId() != kTopLevel || parent.column() != NameColumn)
        return 0;
    switch (parent.row()) {
    case SceneGroup:
        return int(m_nodeIds.size());
    case LightsGroup:
        return int(m_lightIds.size());
    default:
        return 0;
    }
}

int SceneTreeModel::columnCount(const QModelIndex&) const
{
    return ColumnCount;
}

QVariant SceneTreeModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid())
        return {};
    if (role == NodeIndexRole)
        return nodeIndex(index);
    if (role == LightIndexRole)
        return lightIndex(index);

    if (index.internalId() == kNodeItem) {
        if (role == ItemKindRole)
            return int(ItemKind::Node);
        return nodeData(documentNode(index.row()), index.column(), role);
    }
    if (index.internalId() == kLightItem) {
        if (role == ItemKindRole)
            return int(ItemKind::Light);
        return lightData(documentLight(index.row()), index.column(), role);
    }

    const bool camera = index.row() == CameraGroup;
    if (role == ItemKindRole)
        return int(camera ? ItemKind::Camera : ItemKind::Group);
    if (index.column() != NameColumn)
        return {};
    switch (role) {
    case Qt::DisplayRole:
        switch (index.row()) {
        case SceneGroup:
            return tr("Scene");
        case LightsGroup:
            return tr("Lights");
        default:
            return tr("Camera");
        }
    case Qt::FontRole:
        if (!camera) {
            QFont font;
            font.setBold(true);
            return font;
        }
        return {};
    case Qt::ToolTipRole:
        if (camera && m_document) {
            const auto& c = m_document->state().camera;
            return tr("Camera at (%1, %2, %3) m, looking at (%4, %5, %6) m")
                .arg(double(c.position.x), 0, 'f', 2)
                .arg(double(c.position.y), 0, 'f', 2)
                .arg(double(c.position.z), 0, 'f', 2)
                .arg(double(c.lookAt.x), 0, 'f', 2)
                .arg(double(c.lookAt.y), 0, 'f', 2)
                .arg(double(c.lookAt.z), 0, 'f', 2);
        }
        return index.row() == SceneGroup ? tr("Mesh nodes: check to show, Dynamic to re-voxelize when moved")
                                         : tr("Point and directional lights");
    default:
        return {};
    }
}

QVariant SceneTreeModel::nodeData(int node, int column, int role) const
{
    if (!m_document || node < 0)
        return {};
    const doc::DocumentState& state = m_document->state();
    const doc::SceneNode& n = state.nodes[std::size_t(node)];

    if (column == DynamicColumn) {
        if (role == Qt::CheckStateRole)
            return n.dynamic ? Qt::Checked : Qt::Unchecked;
        if (role == Qt::ToolTipRole)
            return tr("Dynamic nodes are re-voxelized every frame they move; static ones are voxelized once");
        return {};
    }

    switch (role) {
    case Qt::DisplayRole:
        return n.name.isEmpty() ? tr("Node %1").arg(node) : n.name;
    case Qt::EditRole:
        return n.name;
    case Qt::CheckStateRole:
        return n.visible ? Qt::Checked : Qt::Unchecked;
    case Qt::ForegroundRole:
        if (!n.visible)
            return QGuiApplication::palette().brush(QPalette::Disabled, QPalette::Text);
        return {};
    case Qt::ToolTipRole: {
        QString material = tr("none");
        if (n.material >= 0 && n.material < int(state.materials.size()))
            material = QString::fromStdString(state.materials[std::size_t(n.material)].name);
        return tr("%1\nMaterial: %2\n%3, %4")
            .arg(n.name, material, n.visible ? tr("visible") : tr("hidden"),
                n.dynamic ? tr("dynamic") : tr("static"));
    }
    default:
        return {};
    }
}

QVariant SceneTreeModel::lightData(int light, int column, int role) const
{
    if (!m_document || light < 0)
        return {};
    const doc::LightNode& l = m_document->state().lights[std::size_t(light)];
    if (column == DynamicColumn)
        return role == Qt::DisplayRole ? QVariant(lightTypeName(l.type)) : QVariant();
    switch (role) {
    case Qt::DisplayRole:
        return l.name.isEmpty() ? tr("%1 light %2").arg(lightTypeName(l.type)).arg(light + 1) : l.name;
    case Qt::ToolTipRole:
        return tr("%1 light, %2%3%4")
            .arg(lightTypeName(l.type), lightQuantity(l), lightSize(l),
                l.castsShadows ? tr(", casts shadows") : QString());
    default:
        return {};
    }
}

bool SceneTreeModel::setData(const QModelIndex& index, const QVariant& value, int role)
{
    const int node = nodeIndex(index) >= 0 ? documentNode(index.row()) : -1;
    if (!m_document || node < 0)
        return false;
    const doc::SceneNode& n = m_document->state().nodes[std::size_t(node)];

    if (index.column() == NameColumn && role == Qt::EditRole) {
        const QString name = value.toString().trimmed();
        if (name.isEmpty())
            return false;
        if (name != n.name)
            m_document->setNodeName(node, name);
        return true;
    }
    if (role == Qt::CheckStateRole) {
        const bool checked = value.toInt() == Qt::Checked;
        if (index.column() == NameColumn && checked != n.visible)
            m_document->setNodeVisible(node, checked);
        else if (index.column() == DynamicColumn && checked != n.dynamic)
            m_document->setNodeDynamic(node, checked);
        return true;
    }
    return false;
}

Qt::ItemFlags SceneTreeModel::flags(const QModelIndex& index) const
{
    if (!index.isValid())
        return Qt::NoItemFlags;
    const Qt::ItemFlags base = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    if (index.internalId() == kNodeItem) {
        if (index.column() == NameColumn)
            return base | Qt::ItemIsEditable | Qt::ItemIsUserCheckable | Qt::ItemNeverHasChildren;
        return base | Qt::ItemIsUserCheckable | Qt::ItemNeverHasChildren;
    }
    if (index.internalId() == kLightItem || index.row() == CameraGroup)
        return base | Qt::ItemNeverHasChildren;
    return base;
}

QVariant SceneTreeModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    return section == NameColumn ? tr("Name") : tr("Dynamic");
}

void SceneTreeModel::onDocumentChanged(const doc::ChangeEvent& event)
{
    using Kind = doc::ChangeEvent::Kind;
    switch (event.kind) {
    case Kind::Reset:
        reset();
        break;
    case Kind::Structure:
        syncGroup(SceneGroup, currentNodeIds());
        break;
    case Kind::NodeProperty:
        if (event.index >= 0 && event.index < int(m_nodeIds.size())
            && m_nodeIds.size() == m_document->state().nodes.size())
            emit dataChanged(indexForNode(event.index, NameColumn), indexForNode(event.index, DynamicColumn));
        else
            syncGroup(SceneGroup, currentNodeIds());
        break;
    case Kind::Lights:
        syncGroup(LightsGroup, currentLightIds());
        break;
    case Kind::Camera: {
        const QModelIndex camera = groupIndex(CameraGroup);
        emit dataChanged(camera, camera, { Qt::ToolTipRole });
        break;
    }
    default:
        break;
    }
}

void SceneTreeModel::reset()
{
    beginResetModel();
    m_nodeIds = currentNodeIds();
    m_lightIds = currentLightIds();
    endResetModel();
}

void SceneTreeModel::syncGroup(Group group, const std::vector<quint64>& now)
{
    std::vector<quint64>& cached = cachedIds(group);
    const QModelIndex parent = groupIndex(group);
    const auto refreshAll = [&] {
        if (!cached.empty())
            emit dataChanged(
                index(0, NameColumn, parent), index(int(cached.size()) - 1, DynamicColumn, parent));
    };

    if (cached == now) {
        refreshAll();
        return;
    }
    // One row added or removed (duplicate, delete, add light, and their undos): the first differing
    // position is the row, provided everything after it lines up.
    const std::size_t shorter = std::min(cached.size(), now.size());
    std::size_t row = 0;
    while (row < shorter && cached[row] == now[row])
        ++row;
    if (now.size() == cached.size() + 1
        && std::equal(cached.begin() + row, cached.end(), now.begin() + row + 1)) {
        beginInsertRows(parent, int(row), int(row));
        cached = now;
        endInsertRows();
        refreshAll();
        return;
    }
    if (cached.size() == now.size() + 1
        && std::equal(now.begin() + row, now.end(), cached.begin() + row + 1)) {
        beginRemoveRows(parent, int(row), int(row));
        cached = now;
        endRemoveRows();
        refreshAll();
        return;
    }
    reset();
}

int SceneTreeModel::documentNode(int row) const
{
    if (!m_document || row < 0 || row >= int(m_nodeIds.size()))
        return -1;
    const auto& nodes = m_document->state().nodes;
    if (row < int(nodes.size()) && nodes[std::size_t(row)].id == m_nodeIds[std::size_t(row)])
        return row;
    for (std::size_t i = 0; i < nodes.size(); ++i)
        if (nodes[i].id == m_nodeIds[std::size_t(row)])
            return int(i);
    return -1;
}

int SceneTreeModel::documentLight(int row) const
{
    if (!m_document || row < 0 || row >= int(m_lightIds.size()))
        return -1;
    const auto& lights = m_document->state().lights;
    if (row < int(lights.size()) && lights[std::size_t(row)].id == m_lightIds[std::size_t(row)])
        return row;
    for (std::size_t i = 0; i < lights.size(); ++i)
        if (lights[i].id == m_lightIds[std::size_t(row)])
            return int(i);
    return -1;
}

std::vector<quint64> SceneTreeModel::currentNodeIds() const
{
    std::vector<quint64> ids;
    if (m_document)
        for (const doc::SceneNode& n : m_document->state().nodes)
            ids.push_back(n.id);
    return ids;
}

std::vector<quint64> SceneTreeModel::currentLightIds() const
{
    std::vector<quint64> ids;
    if (m_document)
        for (const doc::LightNode& l : m_document->state().lights)
            ids.push_back(l.id);
    return ids;
}

} // namespace vct::ui
