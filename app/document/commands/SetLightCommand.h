#pragma once

#include "LightField.h"
#include "LightNode.h"

#include <QUndoCommand>

namespace vct::doc {

class Document;

/**
 * Replaces one light. Consecutive edits of the same field of the same light (by id) within one gesture
 * (Document::editGesture) merge into one undo step; an edit of another field is a step of its own. Name,
 * type and shadow edits never merge: each is a step. The text names the field ("Light intensity of Sun").
 */
class SetLightCommand : public QUndoCommand {
public:
    SetLightCommand(
        Document* document, int index, const LightNode& light, LightField field = LightField::Whole);

    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    void apply(const LightNode& light);

    Document* m_document;
    LightField m_field;
    quint64 m_gesture;
    LightNode m_before;
    LightNode m_after;
};

} // namespace vct::doc
