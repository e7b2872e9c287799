#include "SetNodeTransformCommand.h"

#include "CommandIds.h"
#include "Document.h"

#include <QCoreApplication>

namespace vct::doc {

SetNodeTransformCommand::SetNodeTransformCommand(Document* document, int node, const NodeTransform& transform)
    : m_document(document)
    , m_nodeId(document->state().nodes.at(node).id)
    , m_before(document->state().nodes.at(node).transform)
    , m_after(transform)
{
    setText(QCoreApplication::translate("SetNodeTransformCommand", "Move %1")
                .arg(document->state().nodes.at(node).name));
}

void SetNodeTransformCommand::redo()
{
    apply(m_after);
}

void SetNodeTransformCommand::undo()
{
    apply(m_before);
}

int SetNodeTransformCommand::id() const
{
    return int(CommandId::SetNodeTransform);
}

bool SetNodeTransformCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = static_cast<const SetNodeTransformCommand*>(other);
    if (next->m_nodeId != m_nodeId)
        return false;
    m_after = next->m_after;
    // A drag that ends where it started is no edit: the stack drops the command.
    setObsolete(m_after == m_before);
    return true;
}

void SetNodeTransformCommand::apply(const NodeTransform& transform)
{
    const int index = m_document->nodeIndex(m_nodeId);
    if (index < 0)
        return;
    m_document->mutableState().nodes[std::size_t(index)].transform = transform;
    m_document->notify({ ChangeEvent::Kind::NodeTransform, index });
}

} // namespace vct::doc
