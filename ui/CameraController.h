#pragma once

#include "scene/Aabb.h"
#include "scene/Camera.h"

namespace vct::ui {

/**
 * Orbit, pan, zoom and fly navigation over a render::Camera. The look-at point is where zoom heads and what
 * pan keeps under the cursor; orbits turn about any pivot.
 */
class CameraController {
public:
    /** Rotates the camera around its look-at point; angles in degrees. */
    static render::Camera orbit(const render::Camera& camera, float yawDeg, float pitchDeg);
    /**
     * Turns the camera rigidly about @p pivot (yaw about the up axis, pitch about the view's right axis), so
     * the pivot stays where it is on screen; the view never tips over the poles.
     */
    static render::Camera orbitAbout(
        const render::Camera& camera, const glm::vec3& pivot, float yawDeg, float pitchDeg);
    /**
     * Moves the look-at point along the view axis to the depth of @p point: the picture stays, but zoom and
     * pan then work at the distance of what the user is looking at, not of a point metres behind it.
     */
    static render::Camera focusAtDepth(const render::Camera& camera, const glm::vec3& point);
    /** Moves camera and look-at point in the view plane by a fraction of the visible height. */
    static render::Camera pan(const render::Camera& camera, float rightFraction, float upFraction);
    /** Moves towards the look-at point; steps > 0 zooms in (each step 15% of the distance). */
    static render::Camera zoom(const render::Camera& camera, float steps);
    /** Moves camera and look-at point together along the view axes, metres. */
    static render::Camera fly(const render::Camera& camera, float forward, float right, float up);
    /** Looks at the box from the current direction, fitting it in the vertical field of view. */
    static render::Camera frame(const render::Camera& camera, const render::Aabb& box);
    /**
     * Frames the whole scene: as frame() from outside its bounds, but from inside them (a room, a building)
     * the camera stays where it is and turns to the bounds' centre, since backing out to fit the box would
     * leave the walls between the camera and everything it framed.
     */
    static render::Camera frameAll(const render::Camera& camera, const render::Aabb& sceneBounds);
};

} // namespace vct::ui
