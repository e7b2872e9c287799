#pragma once

#include "LightNode.h"

#include <QUndoCommand>

namespace vct::doc {

class Document;

/** Appends a light with a fresh id (the document's next id); undo removes it and restores the next id. */
class AddLightCommand : public QUndoCommand {
public:
    AddLightCommand(Document* document, const LightNode& light);

    void redo() override;
    void undo() override;

private:
    Document* m_document;
    LightNode m_light;
    quint64 m_nextIdBefore;
};

} // namespace vct::doc
