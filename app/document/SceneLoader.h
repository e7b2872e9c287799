#pragma once

#include "SceneLoadInfo.h"
#include "scene/Aabb.h"
#include "scene/Camera.h"
#include "scene/Scene.h"

#include <QString>

namespace vct::doc {

/**
 * Turns a scene spec into a scene: `builtin:NAME` (see BuiltinScenes) or the path of a model file.
 *
 * Next to a model file `DIR/STEM.EXT`, the optional siblings `DIR/STEM.lights.json` (LightsFile) and
 * `DIR/STEM.camera.json` (CameraFile) are loaded too, as tests/data/reference lays its scenes out. Without a
 * camera file the camera frames the bounds (frameBounds()).
 */
class SceneLoader {
public:
    static constexpr float kFramingFovYDeg = 40.0f;

    /**
     * Replaces `scene` with the scene `spec` names. On failure returns false, leaves `scene` unchanged and
     * names the file and the problem in `error`. `info`, if given, receives the import report and the camera
     * file's image size.
     */
    static bool load(
        const QString& spec, render::Scene& scene, QString* error, SceneLoadInfo* info = nullptr);

    /**
     * A camera on the +z side of `bounds` looking at its centre (-z), far enough that the bounding sphere
     * fits a vertical field of view of `fovYDeg` degrees (and the horizontal one for aspect ratios >= 1).
     */
    static render::Camera frameBounds(const render::Aabb& bounds, float fovYDeg = kFramingFovYDeg);
    /**
     * The near plane for a camera that came without one (camera files have none): a thousandth of the
     * scene's diagonal, so that a scene in any unit stays beyond it. The default of 0.01 m swallowed a
     * scene scaled to a fraction of a millimetre whole: both renderers drew black.
     */
    static float nearPlaneFor(const render::Aabb& bounds);
};

} // namespace vct::doc
