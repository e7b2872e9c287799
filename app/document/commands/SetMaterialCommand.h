#pragma once

#include "MaterialField.h"

#include "scene/Material.h"

#include <QUndoCommand>

namespace vct::doc {

class Document;

/**
 * Replaces one material. Consecutive edits of the same field of the same material within one gesture
 * (Document::editGesture) merge into one undo step, so a spin box's steps or a colour dialog's live preview
 * are undone at once, while an edit of another field is a step of its own. The emissive and double-sided
 * switches never merge: each click is a step. The text names the field ("Albedo of white").
 */
class SetMaterialCommand : public QUndoCommand {
public:
    SetMaterialCommand(Document* document, int index, const render::Material& material,
        MaterialField field = MaterialField::Whole);

    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    void apply(const render::Material& material);

    Document* m_document;
    int m_index;
    MaterialField m_field;
    quint64 m_gesture;
    render::Material m_before;
    render::Material m_after;
};

} // namespace vct::doc
