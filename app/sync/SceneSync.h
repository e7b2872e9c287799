#pragma once

#include "document/ChangeEvent.h"

#include <QObject>

#include <vector>

namespace vct::doc {
class Document;
}
namespace vct::render {
class Renderer;
}

namespace vct::sync {

/**
 * Turns Document change events into Renderer calls. Events are queued as they arrive (any time) and applied
 * by apply(), which the viewport calls with its GL context current, right before rendering a frame.
 */
class SceneSync : public QObject {
    Q_OBJECT

public:
    SceneSync(doc::Document* document, QObject* parent = nullptr);

    /** Brings the renderer up to date; with a new renderer (context recreated) pass fullRebuild. */
    void apply(render::Renderer& renderer, bool fullRebuild = false);
    bool hasPendingChanges() const { return !m_pending.empty() || m_needsReset || m_structureChanged; }
    /** The node each of the renderer's meshes came from (for picking and transform updates). */
    const std::vector<int>& meshToNode() const { return m_meshToNode; }

private:
    void onChanged(const doc::ChangeEvent& event);
    void rebuildScene(render::Renderer& renderer);
    doc::Document* m_document;
    std::vector<doc::ChangeEvent> m_pending;
    bool m_needsReset = true;
    std::vector<int> m_meshToNode;
    std::vector<bool> m_nodeDynamic; ///< each node's dynamic flag as the renderer's scene has it
    std::vector<quint64> m_nodeIds; ///< the nodes the renderer's scene was built from, in order
    /// The node list changed (Kind::Structure): a new scene, unless only visibility changed.
    bool m_structureChanged = false;
    /** Shows and hides the renderer's meshes as the nodes now are; false when the nodes themselves changed.
     */
    bool applyVisibility(render::Renderer& renderer);
};

} // namespace vct::sync
