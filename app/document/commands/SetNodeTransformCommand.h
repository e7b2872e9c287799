#pragma once

#include "NodeTransform.h"
#include "NodeTransformField.h"

#include <QUndoCommand>

namespace vct::doc {

class Document;

/**
 * Moves, rotates or scales one node. Consecutive commands on the same node and field within one gesture
 * (Document::editGesture) merge into one undo step, so a drag or a spin box's steps are undone at once, while
 * an edit of another field, or a second drag, is a step of its own. The node is found by id, so the command
 * survives index shifts.
 */
class SetNodeTransformCommand : public QUndoCommand {
public:
    SetNodeTransformCommand(Document* document, int node, const NodeTransform& transform,
        NodeTransformField field = NodeTransformField::Whole);

    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    void apply(const NodeTransform& transform);

    Document* m_document;
    quint64 m_nodeId;
    NodeTransformField m_field;
    quint64 m_gesture;
    NodeTransform m_before;
    NodeTransform m_after;
};

} // namespace vct::doc
