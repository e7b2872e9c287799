#pragma once

#include "ImportReport.h"

#include <QStringList>

namespace vct::doc {

/** What SceneLoader found besides the scene itself. */
struct SceneLoadInfo {
    ImportReport report; ///< From the model import (empty for built-in scenes).
    bool hasCameraFile
        = false; ///< A *.camera.json set the camera; otherwise it frames the bounds or is built in.
    int width = 0; ///< Image size from the camera file, pixels; 0 when there was none.
    int height = 0;
    QStringList files; ///< Files read, model first (for messages and logs).
};

} // namespace vct::doc
