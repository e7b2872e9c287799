#pragma once

namespace vct::doc {

/**
 * The part of a NodeTransform an edit changes. Consecutive edits of the same field of one node within one
 * gesture (Document::endEditGesture) merge into one undo step (a spin box's steps, typing a number digit by
 * digit); an edit of another field starts a new step, so moving along X and then rotating can be undone one
 * at a time.
 */
enum class NodeTransformField {
    Whole, ///< Any part at once, as a viewport drag moves a node: consecutive moves of one node merge.
    TranslationX,
    TranslationY,
    TranslationZ,
    RotationX,
    RotationY,
    RotationZ,
    ScaleX,
    ScaleY,
    ScaleZ,
    UniformScale, ///< All three scale factors set to one value.
};

} // namespace vct::doc
