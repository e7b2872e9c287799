#pragma once

// Complete type: QPointer<Document> members are destroyed in code moc generates.
#include "document/Document.h"

#include <QAbstractItemModel>
#include <QPointer>

#include <vector>

namespace vct::ui {

/**
 * The document's outline: three top-level groups, "Scene" (one row per node), "Lights" (one row per light)
 * and "Camera" (a single item, no children). Column 0 is the name; on nodes it is editable (renames through
 * the undo stack) and checkable (visibility). Column 1 "Dynamic" is a check box on nodes.
 *
 * Rows follow the document through Document::changed: an added or removed node or light becomes one row
 * insertion or removal so views keep their selection and expansion; anything else larger resets the model.
 */
class SceneTreeModel : public QAbstractItemModel {
    Q_OBJECT

public:
    enum Group { SceneGroup = 0, LightsGroup = 1, CameraGroup = 2, GroupCount = 3 };
    enum Column { NameColumn = 0, DynamicColumn = 1, ColumnCount = 2 };
    enum Role {
        NodeIndexRole = Qt::UserRole + 1, ///< int: node index, or -1 when the item is not a node
        LightIndexRole, ///< int: light index, or -1 when the item is not a light
        ItemKindRole, ///< int: an ItemKind
    };
    enum class ItemKind { Group, Node, Light, Camera };

    explicit SceneTreeModel(QObject* parent = nullptr);

    /** The model does not own the document; null shows only the empty groups. */
    void setDocument(doc::Document* document);
    doc::Document* document() const { return m_document; }

    /** Node index of `index` (any column), or -1. */
    static int nodeIndex(const QModelIndex& index);
    /** Light index of `index` (any column), or -1. */
    static int lightIndex(const QModelIndex& index);
    /** Item for node `node`, or invalid when out of range. */
    QModelIndex indexForNode(int node, int column = NameColumn) const;
    /** Item for light `light`, or invalid when out of range. */
    QModelIndex indexForLight(int light, int column = NameColumn) const;
    /** The top-level item of a group (column 0). */
    QModelIndex groupIndex(Group group) const;

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

private:
    void onDocumentChanged(const doc::ChangeEvent& event);
    void reset();
    /** Brings the cached ids of one group up to date with the fewest signals it can. */
    void syncGroup(Group group, const std::vector<quint64>& now);
    std::vector<quint64> currentNodeIds() const;
    std::vector<quint64> currentLightIds() const;
    std::vector<quint64>& cachedIds(Group group) { return group == SceneGroup ? m_nodeIds : m_lightIds; }
    /**
     * Document index of the node shown at `row`, or -1. Rows are matched by id, because while a row is
     * being inserted or removed the document already has its new order and the views still the old one.
     */
    int documentNode(int row) const;
    int documentLight(int row) const;
    QVariant nodeData(int node, int column, int role) const;
    QVariant lightData(int light, int column, int role) const;

    QPointer<doc::Document> m_document;
    QMetaObject::Connection m_connection;
    // Row counts come from these caches, not from the document: the document has already changed when its
    // signal arrives, and views must see the old counts until the begin/end signals bracket the change.
    std::vector<quint64> m_nodeIds;
    std::vector<quint64> m_lightIds;
};

} // namespace vct::ui
