#pragma once

#include "scene/Aabb.h"
#include "scene/Camera.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace vct::render {

/**
 * Primary rays framed exactly as the GL renderer frames its image: glm::lookAt and glm::perspective with
 * aspect = width / height and a vertical field of view, pixel rows top to bottom as in readFrame(), and
 * surfaces nearer than the GL near plane clipped away.
 */
class CameraRays {
public:
    /** A ray that starts on the near plane. */
    struct Ray {
        glm::vec3 origin { 0.0f };
        glm::vec3 direction { 0.0f, 0.0f, -1.0f }; ///< Unit length.
    };

    /** @p sceneBounds sets the near plane as the GL renderer derives it. */
    CameraRays(const Camera& camera, int width, int height, const Aabb& sceneBounds);

    /**
     * The ray through image point (x + offset.x, y + offset.y), x to the right and y down from the top-left
     * corner, in pixels; an offset uniform in [0,1)^2 gives the pixel's box filter.
     */
    Ray ray(int x, int y, const glm::vec2& offset) const;

private:
    glm::vec3 m_position;
    glm::vec3 m_forward;
    glm::vec3 m_right; ///< Scaled to the half-width of the image at unit distance.
    glm::vec3 m_up; ///< Scaled to the half-height of the image at unit distance.
    float m_nearPlane;
    float m_width;
    float m_height;
};

} // namespace vct::render
