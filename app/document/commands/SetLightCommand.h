#pragma once

#include "LightNode.h"

#include <QUndoCommand>

namespace vct::doc {

class Document;

/** Replaces one light. Consecutive edits of the same light (by id) merge. */
class SetLightCommand : public QUndoCommand {
public:
    SetLightCommand(Document* document, int index, const LightNode& light);

    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    void apply(const LightNode& light);

    Document* m_document;
    LightNode m_before;
    LightNode m_after;
};

} // namespace vct::doc
