#include "DuplicateNodeCommand.h"

#include "Document.h"

#include <QCoreApplication>

namespace vct::doc {

DuplicateNodeCommand::DuplicateNodeCommand(Document* document, int node)
    : m_document(document)
    , m_index(node + 1)
    , m_copy(document->state().nodes.at(std::size_t(node)))
    , m_nextIdBefore(document->state().nextId)
{
    m_copy.id = m_nextIdBefore;
    m_copy.name = QCoreApplication::translate("DuplicateNodeCommand", "%1 copy").arg(m_copy.name);
    setText(QCoreApplication::translate("DuplicateNodeCommand", "Duplicate %1")
                .arg(document->state().nodes.at(std::size_t(node)).name));
}

void DuplicateNodeCommand::redo()
{
    m_selectedBefore = m_document->selectedNodeId();
    DocumentState& state = m_document->mutableState();
    state.nodes.insert(state.nodes.begin() + m_index, m_copy);
    state.nextId = m_nextIdBefore + 1;
    m_document->notify({ ChangeEvent::Kind::Structure, m_index });
    m_document->setSelectedNode(m_index);
}

void DuplicateNodeCommand::undo()
{
    DocumentState& state = m_document->mutableState();
    state.nodes.erase(state.nodes.begin() + m_index);
    state.nextId = m_nextIdBefore;
    m_document->notify({ ChangeEvent::Kind::Structure, m_index });
    m_document->selectNodeById(m_selectedBefore);
}

} // namespace vct::doc
