#pragma once

// Complete type: QPointer<Document> members are destroyed in code moc generates.
#include "document/Document.h"

#include <QDockWidget>
#include <QPointer>

#include <array>
#include <functional>

class QDoubleSpinBox;
class QLabel;

namespace vct::ui {

class MixedSpinBox;

/**
 * Places the selected node: position in metres, rotation as XYZ Euler angles in degrees and scale, exactly as
 * NodeTransform stores them (applied on top of the model's own placement, about the model's origin). The
 * uniform scale sets all three factors to one value; it reads "mixed" while they differ. Each field's edits
 * are one Document::setNodeTransform per change: a run of edits of one field is one undo step, an edit of
 * another field is the next. Without a selection the editors are disabled and hidden.
 */
class TransformDock : public QDockWidget {
    Q_OBJECT

public:
    explicit TransformDock(QWidget* parent = nullptr);

    /** The dock does not own the document; null disables the editors. */
    void setDocument(doc::Document* document);

    /** The node being edited (the document's selection), or -1. */
    int currentNode() const;

private:
    void onDocumentChanged(const doc::ChangeEvent& event);
    /** Shows the current node's transform without emitting edits. */
    void load();
    void applyEdit(doc::NodeTransformField field, const std::function<void(doc::NodeTransform&)>& change);

    QPointer<doc::Document> m_document;
    QMetaObject::Connection m_changedConnection;
    QMetaObject::Connection m_selectionConnection;
    QLabel* m_node = nullptr;
    QWidget* m_editors = nullptr;
    std::array<QDoubleSpinBox*, 3> m_position {};
    std::array<QDoubleSpinBox*, 3> m_rotation {};
    MixedSpinBox* m_uniformScale = nullptr;
    std::array<QDoubleSpinBox*, 3> m_scale {};
};

} // namespace vct::ui
