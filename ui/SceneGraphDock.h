#pragma once

// Complete type: QPointer<Document> members are destroyed in code moc generates.
#include "document/Document.h"

#include <QDockWidget>
#include <QPointer>

class QAction;
class QModelIndex;
class QTreeView;

namespace vct::ui {

class SceneTreeModel;

/**
 * The outliner: a tree of nodes, lights and the camera. Selection follows Document::selectedNode both ways.
 * Rename (F2), Hide/Show (H), Duplicate (Ctrl+D), Delete (Del) and Dynamic act on the selected node through
 * the document's undo commands; their shortcuts work while the tree has focus, so they do not steal keys
 * from the viewport or text fields.
 */
class SceneGraphDock : public QDockWidget {
    Q_OBJECT

public:
    explicit SceneGraphDock(QWidget* parent = nullptr);

    /** The dock does not own the document; null empties the tree. */
    void setDocument(doc::Document* document);

    SceneTreeModel* model() const { return m_model; }
    QTreeView* view() const { return m_view; }

    QAction* renameAction() const { return m_rename; }
    QAction* toggleVisibleAction() const { return m_toggleVisible; }
    QAction* duplicateAction() const { return m_duplicate; }
    QAction* deleteAction() const { return m_delete; }
    /** Checkable: checked when the selected node is dynamic. */
    QAction* dynamicAction() const { return m_dynamic; }
    /** Makes light @p light the current row, as a click on it would (a click on its icon in the view). */
    void selectLight(int light);

signals:
    /** The user selected a light row (so the main window can show it in the light panel). */
    void lightSelected(int light);
    /** The user selected the camera row. */
    void cameraSelected();

private:
    void onCurrentChanged(const QModelIndex& current);
    void onDocumentSelection(int node);
    void selectNodeInView(int node);
    void updateActions();
    int currentNode() const;

    QPointer<doc::Document> m_document;
    QMetaObject::Connection m_selectionConnection;
    QMetaObject::Connection m_changedConnection;
    SceneTreeModel* m_model = nullptr;
    QTreeView* m_view = nullptr;
    QAction* m_rename = nullptr;
    QAction* m_toggleVisible = nullptr;
    QAction* m_duplicate = nullptr;
    QAction* m_delete = nullptr;
    QAction* m_dynamic = nullptr;
    bool m_syncingSelection = false; ///< True while the view is being moved to the document's selection.
};

} // namespace vct::ui
