#pragma once

#include "NodeTransform.h"

#include <QString>

namespace vct::doc {

/** One mesh instance in the document's scene graph. Geometry stays in the source it was imported from. */
struct SceneNode {
    quint64 id = 0; ///< Unique within a document; stable across undo/redo (selection, merging).
    QString name;
    int source = 0; ///< Index into DocumentState::sources.
    int mesh = 0; ///< Index of the mesh within that source's imported scene.
    int material = 0; ///< Index into DocumentState::materials.
    NodeTransform transform;
    bool dynamic = false; ///< Re-voxelized every frame it moves (the bunny).
    bool visible = true;

    bool operator==(const SceneNode& other) const = default;
};

} // namespace vct::doc
