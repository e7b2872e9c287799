#pragma once

#include "scene/Scene.h"

#include <QString>

namespace vct::doc {

/**
 * The analytic lights file of the reference scenes (tests/data/reference) (*.lights.json):
 * `{"lights": [{"type": "point", "position": [x,y,z], "intensity": [r,g,b]},
 *              {"type": "directional", "direction": [dx,dy,dz], "irradiance": [r,g,b]}], "shadows": true}`.
 * Point intensity is radiant intensity in W/sr, directional irradiance W/m^2 on a surface facing the light,
 * `direction` the way the light travels. The optional top-level `"shadows"` (default true) sets whether the
 * file's lights cast shadows; a light may override it with its own `"shadows"`.
 */
class LightsFile {
public:
    /**
     * Appends the file's lights to `scene`. On failure returns false, appends nothing and names the file and
     * the field (e.g. "lights[1].type") in `error`.
     */
    static bool read(const QString& path, render::Scene& scene, QString* error);
};

} // namespace vct::doc
