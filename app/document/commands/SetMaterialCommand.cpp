#include "SetMaterialCommand.h"

#include "CommandIds.h"
#include "Document.h"

#include <QCoreApplication>

namespace vct::doc {

SetMaterialCommand::SetMaterialCommand(Document* document, int index, const render::Material& material)
    : m_document(document)
    , m_index(index)
    , m_before(document->state().materials.at(std::size_t(index)))
    , m_after(material)
{
    setText(QCoreApplication::translate("SetMaterialCommand", "Edit material %1")
                .arg(QString::fromStdString(m_before.name)));
}

void SetMaterialCommand::redo()
{
    apply(m_after);
}

void SetMaterialCommand::undo()
{
    apply(m_before);
}

int SetMaterialCommand::id() const
{
    return int(CommandId::SetMaterial);
}

bool SetMaterialCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = static_cast<const SetMaterialCommand*>(other);
    if (next->m_index != m_index)
        return false;
    m_after = next->m_after;
    setObsolete(sameMaterial(m_after, m_before));
    return true;
}

void SetMaterialCommand::apply(const render::Material& material)
{
    // Materials are only ever appended or removed from the end (import and its undo), and the undo stack
    // replays in order, so the index still names the same material here.
    m_document->mutableState().materials[std::size_t(m_index)] = material;
    m_document->notify({ ChangeEvent::Kind::Material, m_index });
}

} // namespace vct::doc
