#pragma once

#include "scene/Camera.h"

#include <QString>

namespace vct::doc {

/** A named view the user keeps in the project, to come back to (View > Bookmarks). */
struct CameraBookmark {
    QString name;
    render::Camera camera;
};

} // namespace vct::doc
