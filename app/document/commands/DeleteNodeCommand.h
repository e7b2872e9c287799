#pragma once

#include "SceneNode.h"

#include <QUndoCommand>

namespace vct::doc {

class Document;

/**
 * Removes a node. If it was selected the selection becomes empty; other selections follow their node.
 * Undo puts the node back at its index and restores the selection. Materials stay (other nodes may use them).
 */
class DeleteNodeCommand : public QUndoCommand {
public:
    DeleteNodeCommand(Document* document, int node);

    void redo() override;
    void undo() override;

private:
    Document* m_document;
    int m_index;
    SceneNode m_node;
    quint64 m_selectedBefore = 0;
};

} // namespace vct::doc
