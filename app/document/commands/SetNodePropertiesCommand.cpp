#include "SetNodePropertiesCommand.h"

#include "Document.h"

#include <QCoreApplication>

namespace vct::doc {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("SetNodePropertiesCommand", text);
}

} // namespace

SetNodePropertiesCommand::SetNodePropertiesCommand(Document* document, int node, const Properties& properties)
    : m_document(document)
    , m_nodeId(document->state().nodes.at(node).id)
    , m_before(propertiesOf(*document, node))
    , m_after(properties)
{
    const QString name = m_before.name;
    if (m_after.name != m_before.name)
        setText(tr("Rename %1 to %2").arg(name, m_after.name));
    else if (m_after.visible != m_before.visible)
        setText((m_after.visible ? tr("Show %1") : tr("Hide %1")).arg(name));
    else if (m_after.dynamic != m_before.dynamic)
        setText((m_after.dynamic ? tr("Make %1 dynamic") : tr("Make %1 static")).arg(name));
    else
        setText(tr("Edit %1").arg(name));
}

SetNodePropertiesCommand::Properties SetNodePropertiesCommand::propertiesOf(
    const Document& document, int node)
{
    const SceneNode& n = document.state().nodes.at(std::size_t(node));
    return { n.name, n.visible, n.dynamic };
}

void SetNodePropertiesCommand::redo()
{
    apply(m_after);
}

void SetNodePropertiesCommand::undo()
{
    apply(m_before);
}

void SetNodePropertiesCommand::apply(const Properties& properties)
{
    const int index = m_document->nodeIndex(m_nodeId);
    if (index < 0)
        return;
    SceneNode& node = m_document->mutableState().nodes[std::size_t(index)];
    const bool visibilityChanged = node.visible != properties.visible;
    const bool propertyChanged = node.name != properties.name || node.dynamic != properties.dynamic;
    node.name = properties.name;
    node.visible = properties.visible;
    node.dynamic = properties.dynamic;
    if (visibilityChanged)
        m_document->notify({ ChangeEvent::Kind::Structure, index });
    if (propertyChanged)
        m_document->notify({ ChangeEvent::Kind::NodeProperty, index });
}

} // namespace vct::doc
