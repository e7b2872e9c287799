#include "scene/CameraBasis.h"

#include <glm/ext/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace vct::render {

CameraBasis CameraBasis::of(const Camera& camera)
{
    // The rows of the view's rotation, exactly as the rasterised views get it.
    const glm::mat4 view = glm::lookAt(glm::vec3(0.0f), camera.lookAt - camera.position, camera.up);
    CameraBasis basis;
    basis.right = glm::vec3(view[0][0], view[1][0], view[2][0]);
    basis.up = glm::vec3(view[0][1], view[1][1], view[2][1]);
    basis.forward = -glm::vec3(view[0][2], view[1][2], view[2][2]);
    basis.tanHalfFovY = std::tan(glm::radians(camera.fovYDeg) * 0.5f);
    return basis;
}

} // namespace vct::render
