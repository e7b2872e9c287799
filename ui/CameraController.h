#pragma once

#include "scene/Aabb.h"
#include "scene/Camera.h"

namespace vct::ui {

/** Orbit, pan, zoom and fly navigation over a render::Camera (look-at point = orbit centre). */
class CameraController {
public:
    /** Rotates the camera around its look-at point; angles in degrees. */
    static render::Camera orbit(const render::Camera& camera, float yawDeg, float pitchDeg);
    /** Moves camera and look-at point in the view plane by a fraction of the visible height. */
    static render::Camera pan(const render::Camera& camera, float rightFraction, float upFraction);
    /** Moves towards the look-at point; steps > 0 zooms in (each step 15% of the distance). */
    static render::Camera zoom(const render::Camera& camera, float steps);
    /** Moves camera and look-at point together along the view axes, metres. */
    static render::Camera fly(const render::Camera& camera, float forward, float right, float up);
    /** Looks at the box from the current direction, fitting it in the vertical field of view. */
    static render::Camera frame(const render::Camera& camera, const render::Aabb& box);
};

} // namespace vct::ui
