#pragma once

#include "NodeTransform.h"

#include <QUndoCommand>

namespace vct::doc {

class Document;

/**
 * Moves, rotates or scales one node. Consecutive commands on the same node merge into one undo step, so a
 * gizmo or slider drag is undone at once. The node is found by id, so the command survives index shifts.
 */
class SetNodeTransformCommand : public QUndoCommand {
public:
    SetNodeTransformCommand(Document* document, int node, const NodeTransform& transform);

    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    void apply(const NodeTransform& transform);

    Document* m_document;
    quint64 m_nodeId;
    NodeTransform m_before;
    NodeTransform m_after;
};

} // namespace vct::doc
