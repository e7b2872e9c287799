#include "AddLightCommand.h"

#include "Document.h"

#include <QCoreApplication>

namespace vct::doc {

AddLightCommand::AddLightCommand(Document* document, const LightNode& light)
    : m_document(document)
    , m_light(light)
    , m_nextIdBefore(document->state().nextId)
{
    m_light.id = m_nextIdBefore;
    setText(QCoreApplication::translate("AddLightCommand", "Add light %1").arg(m_light.name));
}

void AddLightCommand::redo()
{
    DocumentState& state = m_document->mutableState();
    state.lights.push_back(m_light);
    state.nextId = m_nextIdBefore + 1;
    m_document->notify({ ChangeEvent::Kind::Lights, int(state.lights.size()) - 1 });
}

void AddLightCommand::undo()
{
    DocumentState& state = m_document->mutableState();
    const int index = m_document->lightIndex(m_light.id);
    if (index >= 0)
        state.lights.erase(state.lights.begin() + index);
    state.nextId = m_nextIdBefore;
    m_document->notify({ ChangeEvent::Kind::Lights, index });
}

} // namespace vct::doc
