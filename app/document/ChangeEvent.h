#pragma once

namespace vct::doc {

/** What changed in a Document, so views and the renderer update only that. */
struct ChangeEvent {
    enum class Kind {
        Reset, ///< Everything (new scene, project opened): rebuild all.
        Structure, ///< Nodes added, removed, shown or hidden: the renderer's mesh list changes.
        NodeTransform, ///< index = node
        NodeProperty, ///< index = node: name or dynamic flag
        Material, ///< index = material
        Lights, ///< any light added, removed or edited
        Camera,
        Bookmarks, ///< the camera bookmarks (DocumentState::bookmarks)
        Settings,
    };
    Kind kind = Kind::Reset;
    int index = -1;
};

} // namespace vct::doc
