#include "SetNodeTransformCommand.h"

#include "CommandIds.h"
#include "Document.h"

#include <QCoreApplication>

namespace vct::doc {

namespace {

const char* verbFor(NodeTransformField field)
{
    switch (field) {
    case NodeTransformField::RotationX:
    case NodeTransformField::RotationY:
    case NodeTransformField::RotationZ:
        return QT_TRANSLATE_NOOP("SetNodeTransformCommand", "Rotate %1");
    case NodeTransformField::ScaleX:
    case NodeTransformField::ScaleY:
    case NodeTransformField::ScaleZ:
    case NodeTransformField::UniformScale:
        return QT_TRANSLATE_NOOP("SetNodeTransformCommand", "Scale %1");
    case NodeTransformField::Whole:
    case NodeTransformField::TranslationX:
    case NodeTransformField::TranslationY:
    case NodeTransformField::TranslationZ:
        break;
    }
    return QT_TRANSLATE_NOOP("SetNodeTransformCommand", "Move %1");
}

} // namespace

SetNodeTransformCommand::SetNodeTransformCommand(
    Document* document, int node, const NodeTransform& transform, NodeTransformField field)
    : m_document(document)
    , m_nodeId(document->state().nodes.at(node).id)
    , m_field(field)
    , m_gesture(document->editGesture())
    , m_before(document->state().nodes.at(node).transform)
    , m_after(transform)
{
    setText(QCoreApplication::translate("SetNodeTransformCommand", verbFor(field))
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
    if (next->m_nodeId != m_nodeId || next->m_field != m_field || next->m_gesture != m_gesture)
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
