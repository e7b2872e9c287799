#pragma once

#include "CameraSetup.h"

#include <glm/ext/vector_double3.hpp>

#include <QString>

namespace vct::doc {

/**
 * The pinhole camera file of the reference scenes (tests/data/reference) (*.camera.json):
 * `{"position": [x,y,z], "look_at": [x,y,z], "up": [x,y,z], "fov_y_deg": 40, "width": 256, "height": 256}`.
 * Positions in metres, field of view vertical in degrees, size in pixels. `up` is optional (default +Y).
 */
class CameraFile {
public:
    /**
     * Reads `path` into `setup`; on failure returns false, leaves `setup` alone and names file and field in
     * `error`. Position and look-at are read less `origin`, in double precision (SceneRebase).
     */
    static bool read(
        const QString& path, CameraSetup& setup, QString* error, const glm::dvec3& origin = glm::dvec3(0.0));
    /** Writes `setup` as indented JSON; false with a message on I/O failure. */
    static bool write(const QString& path, const CameraSetup& setup, QString* error);
};

} // namespace vct::doc
