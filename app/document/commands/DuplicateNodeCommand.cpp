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
    // Beside the original, a tenth of its width apart, rather than inside it where it cannot be seen or
    // picked: its own width along x, or its largest extent when it is flat across x.
    if (const render::Aabb bounds = document->nodeWorldBounds(node); !bounds.isEmpty()) {
        const glm::vec3 size = bounds.size();
        const float width = size.x > 0.0f ? size.x : std::max({ size.x, size.y, size.z });
        m_copy.transform.translation.x += 1.1f * width;
    }
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
