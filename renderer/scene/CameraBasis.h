#pragma once

#include "scene/Camera.h"

#include <glm/vec3.hpp>

namespace vct::render {

/**
 * A camera's axes as glm::lookAt builds them (right-handed; the camera looks down its -z) and the tangent of
 * half its vertical field of view: the one place the renderer's pixel rays, the path tracer's camera rays
 * and the editor's picking and dragging get them from, so all three agree on where a pixel looks.
 */
struct CameraBasis {
    glm::vec3 right { 1.0f, 0.0f, 0.0f };
    glm::vec3 up { 0.0f, 1.0f, 0.0f };
    glm::vec3 forward { 0.0f, 0.0f, -1.0f };
    float tanHalfFovY = 1.0f;

    static CameraBasis of(const Camera& camera);
    /**
     * The direction through normalized device coordinates (ndcX, ndcY), each -1..1 with y up, of an image
     * `aspect` (width / height) wide: not normalised, its forward component is 1 (unit view depth).
     */
    glm::vec3 through(float ndcX, float ndcY, float aspect) const
    {
        return forward + right * (ndcX * tanHalfFovY * aspect) + up * (ndcY * tanHalfFovY);
    }
};

} // namespace vct::render
