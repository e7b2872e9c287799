#pragma once

#include "DocumentState.h"

#include <QUndoCommand>

#include <vector>

namespace vct::doc {

class Document;

/**
 * Adds an imported model: one source, its materials (appended), one node per mesh and its lights, all as
 * one step; announces Reset because materials, textures, meshes and lights all change together. The
 * model's geometry must already be in the document's cache (Document::importModel does that). Undo removes
 * exactly what redo added and restores the next id; the cached geometry stays.
 */
class ImportModelCommand : public QUndoCommand {
public:
    /** `nodes` and `lights` carry their final ids and indices (source, material) for after the append. */
    ImportModelCommand(Document* document, const SceneSource& source, std::vector<render::Material> materials,
        std::vector<SceneNode> nodes, std::vector<LightNode> lights, quint64 nextIdAfter);

    void redo() override;
    void undo() override;

private:
    Document* m_document;
    SceneSource m_source;
    std::vector<render::Material> m_materials;
    std::vector<SceneNode> m_nodes;
    std::vector<LightNode> m_lights;
    quint64 m_nextIdBefore;
    quint64 m_nextIdAfter;
    quint64 m_selectedBefore = 0;
};

} // namespace vct::doc
