#include "RemoveLightCommand.h"

#include "Document.h"

#include <QCoreApplication>

namespace vct::doc {

RemoveLightCommand::RemoveLightCommand(Document* document, int index)
    : m_document(document)
    , m_index(index)
    , m_light(document->state().lights.at(std::size_t(index)))
{
    setText(QCoreApplication::translate("RemoveLightCommand", "Remove light %1").arg(m_light.name));
}

void RemoveLightCommand::redo()
{
    DocumentState& state = m_document->mutableState();
    state.lights.erase(state.lights.begin() + m_index);
    m_document->notify({ ChangeEvent::Kind::Lights, m_index });
}

void RemoveLightCommand::undo()
{
    DocumentState& state = m_document->mutableState();
    state.lights.insert(state.lights.begin() + m_index, m_light);
    m_document->notify({ ChangeEvent::Kind::Lights, m_index });
}

} // namespace vct::doc
