#pragma once

#include "SceneNode.h"

#include <QUndoCommand>

namespace vct::doc {

class Document;

/**
 * Inserts a copy of a node (new id, name + " copy") right after it and selects the copy; undo removes it and
 * restores the previous selection and the document's next id.
 */
class DuplicateNodeCommand : public QUndoCommand {
public:
    DuplicateNodeCommand(Document* document, int node);

    void redo() override;
    void undo() override;

private:
    Document* m_document;
    int m_index; ///< Where the copy goes.
    SceneNode m_copy;
    quint64 m_nextIdBefore;
    quint64 m_selectedBefore = 0;
};

} // namespace vct::doc
