#pragma once

#include "scene/Scene.h"

#include <glm/ext/vector_double3.hpp>

namespace vct::doc {

/**
 * Moves a scene that lies far from the world's origin (a building in a geo-referenced city model, a terrain
 * tile) to a local origin, in double precision, before its coordinates are used as floats. At 1e5 m a float
 * resolves 8 mm; a camera or light read there moves by that much, and the renderers' positions lose the
 * same again when a model matrix adds the offset. Rebased, the scene's floats resolve its own size.
 *
 * Model files reach us as floats (Assimp's ai_real is float in Debian's build), so their vertices keep the
 * quantisation they were read with; the camera and lights files, read as doubles, do not
 * (CameraFile::read, LightsFile::read with the origin).
 */
class SceneRebase {
public:
    /**
     * The local origin for `scene`: the centre of its world bounds, computed in double precision, when that
     * centre is further from the world's origin than the scene is across; else zero (a scene around the
     * origin is left exactly as it is).
     */
    static glm::dvec3 originFor(const render::Scene& scene);

    /**
     * Moves `scene` by -`origin` and adds `origin` to scene.origin. Static meshes get their transform baked
     * into their vertices in double precision (so a model matrix holding a large offset loses nothing);
     * dynamic meshes keep their transform, its translation moved. Lights and camera are moved as floats:
     * read files with the origin instead where they are still doubles.
     */
    static void rebase(render::Scene& scene, const glm::dvec3& origin);
};

} // namespace vct::doc
