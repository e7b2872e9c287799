#pragma once

#include "LightNode.h"

#include <QUndoCommand>

namespace vct::doc {

class Document;

/** Removes one light; undo puts it back at the same index. */
class RemoveLightCommand : public QUndoCommand {
public:
    RemoveLightCommand(Document* document, int index);

    void redo() override;
    void undo() override;

private:
    Document* m_document;
    int m_index;
    LightNode m_light;
};

} // namespace vct::doc
