#include "SceneGraphDock.h"

#include "SceneTreeModel.h"

#include "document/Document.h"

#include <QAction>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QMenu>
#include <QToolButton>
#include <QTreeView>
#include <QVBoxLayout>

namespace vct::ui {

namespace {

QAction* makeAction(QWidget* owner, const QString& text, const QKeySequence& shortcut, const QString& tip)
{
    auto* action = new QAction(text, owner);
    action->setShortcut(shortcut);
    // Only while the outliner has focus: Del or H typed elsewhere (viewport, a spin box) must not delete or
    // hide nodes.
    action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    action->setToolTip(QStringLiteral("%1 (%2)").arg(tip, shortcut.toString(QKeySequence::NativeText)));
    owner->addAction(action);
    return action;
}

QToolButton* makeButton(QAction* action)
{
    auto* button = new QToolButton;
    button->setDefaultAction(action);
    button->setAutoRaise(true);
    return button;
}

} // namespace

SceneGraphDock::SceneGraphDock(QWidget* parent)
    : QDockWidget(tr("Scene"), parent)
{
    setObjectName(QStringLiteral("SceneGraphDock"));

    auto* body = new QWidget(this);
    m_model = new SceneTreeModel(this);
    m_view = new QTreeView(body);
    m_view->setObjectName(QStringLiteral("sceneTree"));
    m_view->setModel(m_model);
    m_view->setUniformRowHeights(true);
    m_view->setAllColumnsShowFocus(true);
    m_view->setSelectionMode(QAbstractItemView::SingleSelection);
    m_view->setEditTriggers(QAbstractItemView::EditKeyPressed | QAbstractItemView::SelectedClicked);
    m_view->setContextMenuPolicy(Qt::CustomContextMenu);
    m_view->header()->setStretchLastSection(false);
    m_view->header()->setSectionResizeMode(SceneTreeModel::NameColumn, QHeaderView::Stretch);
    m_view->header()->setSectionResizeMode(SceneTreeModel::DynamicColumn, QHeaderView::ResizeToContents);
    m_view->expandAll();

    m_rename = makeAction(this, tr("Rename"), Qt::Key_F2, tr("Rename the selected node"));
    m_toggleVisible = makeAction(this, tr("Hide"), Qt::Key_H, tr("Hide or show the selected node"));
    m_duplicate = makeAction(this, tr("Duplicate"), QKeySequence(Qt::CTRL | Qt::Key_D),
        tr("Duplicate the selected node (shares its mesh and material)"));
    m_delete = makeAction(this, tr("Delete"), QKeySequence::Delete, tr("Delete the selected node"));
    m_dynamic = makeAction(this, tr("Dynamic"), QKeySequence(),
        tr("Dynamic: re-voxelized every frame it moves; static: voxelized once"));
    m_dynamic->setToolTip(tr("Dynamic: re-voxelized every frame it moves; static: voxelized once"));
    m_dynamic->setCheckable(true);

    connect(m_rename, &QAction::triggered, this, [this] {
        const QModelIndex index = m_model->indexForNode(currentNode());
        if (index.isValid())
            m_view->edit(index);
    });
    connect(m_toggleVisible, &QAction::triggered, this, [this] {
        const int node = currentNode();
        if (m_document && node >= 0)
            m_document->setNodeVisible(node, !m_document->state().nodes[std::size_t(node)].visible);
    });
    connect(m_duplicate, &QAction::triggered, this, [this] {
        if (m_document && currentNode() >= 0)
            m_document->duplicateNode(currentNode());
    });
    connect(m_delete, &QAction::triggered, this, [this] {
        if (m_document && currentNode() >= 0)
            m_document->deleteNode(currentNode());
    });
    connect(m_dynamic, &QAction::triggered, this, [this](bool checked) {
        if (m_document && currentNode() >= 0)
            m_document->setNodeDynamic(currentNode(), checked);
    });

    connect(m_view, &QWidget::customContextMenuRequested, this, [this](const QPoint& pos) {
        if (currentNode() < 0)
            return;
        QMenu menu(this);
        menu.addAction(m_rename);
        menu.addAction(m_toggleVisible);
        menu.addAction(m_duplicate);
        menu.addAction(m_dynamic);
        menu.addSeparator();
        menu.addAction(m_delete);
        menu.exec(m_view->viewport()->mapToGlobal(pos));
    });

    connect(m_view->selectionModel(), &QItemSelectionModel::currentChanged, this,
        [this](const QModelIndex& current) { onCurrentChanged(current); });
    // A reset forgets expansion and selection; put both back from the document.
    connect(m_model, &QAbstractItemModel::modelReset, this, [this] {
        m_view->expandAll();
        if (m_document)
            selectNodeInView(m_document->selectedNode());
        updateActions();
    });
    connect(m_model, &QAbstractItemModel::dataChanged, this, &SceneGraphDock::updateActions);
    connect(m_model, &QAbstractItemModel::rowsInserted, this,
        [this](const QModelIndex& parent) { m_view->expand(parent); });

    auto* buttons = new QHBoxLayout;
    buttons->setContentsMargins(0, 0, 0, 0);
    buttons->setSpacing(2);
    for (QAction* action : { m_rename, m_toggleVisible, m_duplicate, m_dynamic, m_delete })
        buttons->addWidget(makeButton(action));
    buttons->addStretch();

    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->setSpacing(2);
    layout->addLayout(buttons);
    layout->addWidget(m_view);
    setWidget(body);
    updateActions();
}

void SceneGraphDock::setDocument(doc::Document* document)
{
    disconnect(m_selectionConnection);
    disconnect(m_changedConnection);
    m_document = document;
    m_model->setDocument(document);
    if (m_document) {
        m_selectionConnection = connect(
            m_document, &doc::Document::selectionChanged, this, &SceneGraphDock::onDocumentSelection);
        // Deleting or duplicating moves the selection in the document; actions follow it.
        m_changedConnection
            = connect(m_document, &doc::Document::changed, this, &SceneGraphDock::updateActions);
        selectNodeInView(m_document->selectedNode());
    }
    updateActions();
}

int SceneGraphDock::currentNode() const
{
    return SceneTreeModel::nodeIndex(m_view->currentIndex());
}

void SceneGraphDock::onCurrentChanged(const QModelIndex& current)
{
    updateActions();
    if (m_syncingSelection || !m_document)
        return;
    const int node = SceneTreeModel::nodeIndex(current);
    if (node != m_document->selectedNode())
        m_document->setSelectedNode(node);
    if (const int light = SceneTreeModel::lightIndex(current); light >= 0)
        emit lightSelected(light);
    else if (current.isValid()
        && current.data(SceneTreeModel::ItemKindRole).toInt() == int(SceneTreeModel::ItemKind::Camera))
        emit cameraSelected();
}

void SceneGraphDock::onDocumentSelection(int node)
{
    if (SceneTreeModel::nodeIndex(m_view->currentIndex()) != node)
        selectNodeInView(node);
}

void SceneGraphDock::selectLight(int light)
{
    const QModelIndex index = m_model->indexForLight(light);
    if (!index.isValid())
        return;
    m_view->selectionModel()->setCurrentIndex(
        index, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    m_view->scrollTo(index);
}

void SceneGraphDock::selectNodeInView(int node)
{
    m_syncingSelection = true;
    const QModelIndex index = m_model->indexForNode(node);
    if (index.isValid()) {
        m_view->selectionModel()->setCurrentIndex(
            index, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
        m_view->scrollTo(index);
    } else if (SceneTreeModel::nodeIndex(m_view->currentIndex()) >= 0) {
        // The document deselected (or the node is gone): a light or camera row stays selected.
        m_view->selectionModel()->clearSelection();
        m_view->selectionModel()->setCurrentIndex(QModelIndex(), QItemSelectionModel::NoUpdate);
    }
    m_syncingSelection = false;
    updateActions();
}

void SceneGraphDock::updateActions()
{
    const int node = currentNode();
    const bool valid = m_document && node >= 0 && node < int(m_document->state().nodes.size());
    for (QAction* action : { m_rename, m_toggleVisible, m_duplicate, m_delete, m_dynamic })
        action->setEnabled(valid);
    const bool visible = valid && m_document->state().nodes[std::size_t(node)].visible;
    m_toggleVisible->setText(valid && !visible ? tr("Show") : tr("Hide"));
    const QSignalBlocker block(m_dynamic);
    m_dynamic->setChecked(valid && m_document->state().nodes[std::size_t(node)].dynamic);
}

} // namespace vct::ui
