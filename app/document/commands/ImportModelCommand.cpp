#include "ImportModelCommand.h"

#include "Document.h"

#include <QCoreApplication>
#include <QFileInfo>

#include <utility>

namespace vct::doc {

ImportModelCommand::ImportModelCommand(Document* document, const SceneSource& source,
    std::vector<render::Material> materials, std::vector<SceneNode> nodes, std::vector<LightNode> lights,
    quint64 nextIdAfter)
    : m_document(document)
    , m_source(source)
    , m_materials(std::move(materials))
    , m_nodes(std::move(nodes))
    , m_lights(std::move(lights))
    , m_nextIdBefore(document->state().nextId)
    , m_nextIdAfter(nextIdAfter)
{
    setText(QCoreApplication::translate("ImportModelCommand", "Import %1")
                .arg(QFileInfo(source.spec).fileName()));
}

void ImportModelCommand::redo()
{
    m_selectedBefore = m_document->selectedNodeId();
    DocumentState& state = m_document->mutableState();
    state.sources.push_back(m_source);
    state.materials.insert(state.materials.end(), m_materials.begin(), m_materials.end());
    state.nodes.insert(state.nodes.end(), m_nodes.begin(), m_nodes.end());
    state.lights.insert(state.lights.end(), m_lights.begin(), m_lights.end());
    state.nextId = m_nextIdAfter;
    m_document->notify({ ChangeEvent::Kind::Reset, -1 });
}

void ImportModelCommand::undo()
{
    // Redo appended at the ends and later commands were undone first, so the additions are the tails.
    DocumentState& state = m_document->mutableState();
    state.sources.pop_back();
    state.materials.resize(state.materials.size() - m_materials.size());
    state.nodes.resize(state.nodes.size() - m_nodes.size());
    state.lights.resize(state.lights.size() - m_lights.size());
    state.nextId = m_nextIdBefore;
    m_document->notify({ ChangeEvent::Kind::Reset, -1 });
    m_document->selectNodeById(m_selectedBefore);
}

} // namespace vct::doc
