#pragma once

#include "scene/Camera.h"

namespace vct::doc {

/** A camera plus the image size it was framed for, as stored in a *.camera.json file. */
struct CameraSetup {
    render::Camera camera;
    int width = 256; ///< Pixels.
    int height = 256; ///< Pixels.
};

} // namespace vct::doc
