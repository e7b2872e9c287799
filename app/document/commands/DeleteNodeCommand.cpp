#include "DeleteNodeCommand.h"

#include "Document.h"

#include <QCoreApplication>

namespace vct::doc {

DeleteNodeCommand::DeleteNodeCommand(Document* document, int node)
    : m_document(document)
    , m_index(node)
    , m_node(document->state().nodes.at(std::size_t(node)))
{
    setText(QCoreApplication::translate("DeleteNodeCommand", "Delete %1").arg(m_node.name));
}

void DeleteNodeCommand::redo()
{
    m_selectedBefore = m_document->selectedNodeId();
    DocumentState& state = m_document->mutableState();
    state.nodes.erase(state.nodes.begin() + m_index);
    m_document->notify({ ChangeEvent::Kind::Structure, m_index });
    // selectNodeById gives -1 for the deleted node itself and the shifted index for any other.
    m_document->selectNodeById(m_selectedBefore);
}

void DeleteNodeCommand::undo()
{
    DocumentState& state = m_document->mutableState();
    state.nodes.insert(state.nodes.begin() + m_index, m_node);
    m_document->notify({ ChangeEvent::Kind::Structure, m_index });
    m_document->selectNodeById(m_selectedBefore);
}

} // namespace vct::doc
