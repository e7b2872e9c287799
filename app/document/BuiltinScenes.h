#pragma once

#include "scene/Scene.h"

#include <QString>
#include <QStringList>

namespace vct::doc {

/**
 * Scenes compiled into the binary (Qt resources under :/scenes):
 * - `cornell`: the reference Cornell box lit by its emitters (Ke), with the reference camera.
 * - `cornell_point`: the same box without emitters, lit by the reference point light, same camera.
 * - `atrium` (alias `default`): AtriumGenerator's courtyard, one warm point light with shadows at mid-height,
 * and the Stanford bunny (dynamic, 1.2 m tall) standing on the floor.
 * - `bunny`: the bunny on a 6 m floor square with one point light.
 */
class BuiltinScenes {
public:
    static constexpr float kBunnyHeight = 1.2f; ///< Metres.

    /** The names load() accepts, sorted; "default" is listed last. */
    static QStringList names();
    /**
     * Replaces `scene` with the named scene (geometry, materials, lights, camera). On failure returns false,
     * leaves `scene` unchanged and explains in `error` (an unknown name lists the known ones).
     */
    static bool load(const QString& name, render::Scene& scene, QString* error);
};

} // namespace vct::doc
