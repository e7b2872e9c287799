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
 * camera file the camera frames the scene (frameScene()).
 *
 * A model file may be in any unit: `unitScale` is metres per model unit (0.01 for centimetres). The siblings
 * are in the model's units too, so the whole loaded scene is scaled (scaledScene()). Built-in scenes are in
 * metres and accept no other scale.
 */
class SceneLoader {
public:
    static constexpr float kFramingFovYDeg = 40.0f;

    /** Which axis of a model file points up. We are Y-up; CAD tools, 3ds Max and many exports are Z-up. */
    enum class UpAxis { Y, Z };

    /** Whether a model far from the world's origin is moved to a local one (SceneRebase). */
    enum class Origin {
        Keep, ///< Coordinates as the files give them: a document whose sources must share one frame.
        RebaseFar, ///< Rebased when far off, scene.origin saying where: a scene rendered on its own.
    };

    /**
     * Replaces `scene` with the scene `spec` names. On failure returns false, leaves `scene` unchanged and
     * names the file and the problem in `error`. `info`, if given, receives the import report and the camera
     * file's image size. `unitScale` is metres per unit of a model file; a built-in scene takes only 1.
     * With Origin::RebaseFar a model file far from the origin is rebased before its camera and lights files
     * are read, and they are read less the origin in double precision.
     */
    static bool load(const QString& spec, render::Scene& scene, QString* error, SceneLoadInfo* info = nullptr,
        float unitScale = 1.0f, Origin origin = Origin::Keep);

    /**
     * `scene`, in units of `unitScale` metres, in metres: mesh transforms, light positions, light sizes and
     * the camera (its near plane too) and scene.origin scaled about the origin. Directions, angles,
     * intensities and radiances are physical quantities that do not depend on the unit, so they stay.
     */
    static render::Scene scaledScene(render::Scene scene, float unitScale);
    /**
     * `scene`, whose up axis is `up`, turned Y-up: a rotation of -90 degrees about x for Z-up, applied to
     * mesh transforms, light positions and directions and the camera. Nothing changes for Y-up.
     */
    static render::Scene uprightScene(render::Scene scene, UpAxis up);
    /** The rotation uprightScene() applies. */
    static glm::mat4 uprightRotation(UpAxis up);
    /** An up axis as a command line or dialog gives it ("y", "z"): empty on success, else the problem. */
    static QString parseUpAxis(const QString& text, UpAxis* up);
    /** Empty when `unitScale` can scale a model (finite and positive), else the problem. */
    static QString unitScaleProblem(float unitScale);
    /** A unit scale as a command line gives it ("0.01"): empty on success, else the problem. */
    static QString parseUnitScale(const QString& text, float* unitScale);

    /**
     * A camera on the +z side of `bounds` looking at its centre (-z), far enough that the bounding sphere
     * fits a vertical field of view of `fovYDeg` degrees (and the horizontal one for aspect ratios >= 1).
     */
    static render::Camera frameBounds(const render::Aabb& bounds, float fovYDeg = kFramingFovYDeg);
    /**
     * The camera for a model that came without one: frameBounds() of its bounds, unless their centre is
     * inside a closed room (Enclosure), which from outside would show only its outer wall: then at that
     * centre, looking along the longer horizontal side.
     */
    static render::Camera frameScene(const render::Scene& scene);
    /**
     * The near plane for a camera that came without one (camera files have none): a thousandth of the
     * scene's diagonal, so that a scene in any unit stays beyond it. The default of 0.01 m swallowed a
     * scene scaled to a fraction of a millimetre whole: both renderers drew black.
     */
    static float nearPlaneFor(const render::Aabb& bounds);
};

} // namespace vct::doc
