#pragma once

#include "scene/Scene.h"

#include <glm/ext/vector_double3.hpp>

#include <QString>

namespace vct::doc {

/**
 * The analytic lights file of the reference scenes (tests/data/reference) (*.lights.json):
 * `{"lights": [{"type": "point", "position": [x,y,z], "intensity": [r,g,b], "radius": 0.05},
 *              {"type": "spot", "position": [x,y,z], "direction": [dx,dy,dz], "intensity": [r,g,b],
 *               "inner_deg": 20, "outer_deg": 35},
 *              {"type": "directional", "direction": [dx,dy,dz], "irradiance": [r,g,b],
 *               "angular_diameter_deg": 0.53},
 *              {"type": "rect", "position": [x,y,z], "direction": [dx,dy,dz], "size": [w,h],
 *               "rotation_deg": 0, "radiance": [r,g,b]},
 *              {"type": "disk", "position": [x,y,z], "direction": [dx,dy,dz], "diameter": d,
 *               "radiance": [r,g,b]}], "shadows": true}`.
 * Point intensity is radiant intensity in W/sr (a spot's on its axis, full within `inner_deg` of it and none
 * beyond `outer_deg`), directional irradiance W/m^2 on a surface facing the light, `direction` the way the
 * light travels. The optional `radius` of a point or spot light (metres, default 0: a point) makes it a
 * sphere of the same intensity, and the optional `angular_diameter_deg` of a directional light (default 0;
 * the sun's is about 0.53, less than 90) the disk it comes from: both soften shadows only. Rect and
 * disk lights (render::SurfaceLight) emit `radiance` in W/(m^2 sr) from their front face only; `position` is
 * their centre, `direction` the way the front face looks, `size` width and height in metres (a disk:
 * `diameter`), and the optional `rotation_deg` (default 0) turns a rect about its direction. The optional
 * top-level `"shadows"` (default true) sets whether the file's lights cast shadows; a light may override it
 * with its own `"shadows"`.
 */
class LightsFile {
public:
    /**
     * Appends the file's lights to `scene`. On failure returns false, appends nothing and names the file and
     * the field (e.g. "lights[1].type") in `error`. Positions are read less `origin`, in double precision,
     * for a scene rebased to a local origin (SceneRebase).
     */
    static bool read(const QString& path, render::Scene& scene, QString* error,
        const glm::dvec3& origin = glm::dvec3(0.0));
};

} // namespace vct::doc
