#pragma once

namespace vct::doc {

/**
 * The part of a material an edit changes. Consecutive edits of the same field of one material within one
 * gesture merge into one undo step (a spin box's steps, a colour dialog's live preview); an edit of another
 * field starts a new step, so changing the albedo and then the strength can be undone one at a time.
 */
enum class MaterialField {
    Whole, ///< Any part at once, as a script or a test replaces a material: consecutive ones merge.
    Albedo,
    Emissive, ///< The switch: turns emission on (colour times strength) or off (zero).
    EmissionColor,
    EmissionStrength,
    Specular,
    Shininess,
    DoubleSided,
};

} // namespace vct::doc
