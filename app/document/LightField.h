#pragma once

namespace vct::doc {

/**
 * The part of a LightNode an edit changes. Consecutive edits of the same field of one light within one
 * gesture merge into one undo step; an edit of another field starts a new step, so changing the intensity
 * and then moving the light along X can be undone one at a time.
 */
enum class LightField {
    Whole, ///< Any part at once: consecutive ones merge.
    Name,
    Type,
    PositionX,
    PositionY,
    PositionZ,
    DirectionX,
    DirectionY,
    DirectionZ,
    Color,
    Intensity,
    Shadows,
    SpotInner, ///< May carry the outer angle along: inner never exceeds outer.
    SpotOuter, ///< May carry the inner angle along.
    Radius,
    AngularDiameter,
    AreaWidth,
    AreaHeight,
    AreaRotation,
};

} // namespace vct::doc
