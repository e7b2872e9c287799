#pragma once

#include "scene/Material.h"

#include <QUndoCommand>

namespace vct::doc {

class Document;

/** Replaces one material. Consecutive edits of the same material merge (colour pickers, sliders). */
class SetMaterialCommand : public QUndoCommand {
public:
    SetMaterialCommand(Document* document, int index, const render::Material& material);

    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    void apply(const render::Material& material);

    Document* m_document;
    int m_index;
    render::Material m_before;
    render::Material m_after;
};

} // namespace vct::doc
