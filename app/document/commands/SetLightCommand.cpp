#include "SetLightCommand.h"

#include "CommandIds.h"
#include "Document.h"

#include <QCoreApplication>

namespace vct::doc {

SetLightCommand::SetLightCommand(Document* document, int index, const LightNode& light)
    : m_document(document)
    , m_before(document->state().lights.at(std::size_t(index)))
    , m_after(light)
{
    // The id is what identifies the light; an edit never changes it.
    m_after.id = m_before.id;
    setText(QCoreApplication::translate("SetLightCommand", "Edit light %1").arg(m_before.name));
}

void SetLightCommand::redo()
{
    apply(m_after);
}

void SetLightCommand::undo()
{
    apply(m_before);
}

int SetLightCommand::id() const
{
    return int(CommandId::SetLight);
}

bool SetLightCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = static_cast<const SetLightCommand*>(other);
    if (next->m_before.id != m_before.id)
        return false;
    m_after = next->m_after;
    setObsolete(m_after == m_before);
    return true;
}

void SetLightCommand::apply(const LightNode& light)
{
    const int index = m_document->lightIndex(light.id);
    if (index < 0)
        return;
    m_document->mutableState().lights[std::size_t(index)] = light;
    m_document->notify({ ChangeEvent::Kind::Lights, index });
}

} // namespace vct::doc
