#pragma once

#include "scene/Scene.h"

#include <glm/vec3.hpp>

namespace vct::doc {

/**
 * Whether a point is inside a room of the scene, by rays from it in evenly spread directions (a Fibonacci
 * sphere). A model of an interior (a hall, a courtyard within its arcades) framed from outside shows its
 * outer wall; SceneLoader frames it from inside instead, and a model without lights gets a sun only where the
 * sky is open.
 */
class Enclosure {
public:
    /** The share of the rays from `point` with a y component in [minY, maxY] that meet a triangle of `scene`.
     */
    static float hitShare(const render::Scene& scene, const glm::vec3& point, float minY, float maxY);
    /** Walls all round: 95% of the rays within 30 degrees of level meet geometry (a courtyard counts). */
    static bool encloses(const render::Scene& scene, const glm::vec3& point);
    /** A roof: 95% of the rays more than 30 degrees above level meet geometry. */
    static bool roofed(const render::Scene& scene, const glm::vec3& point);
    /** encloses() and roofed() together, in one pass over the scene's triangles. */
    static bool insideRoom(const render::Scene& scene, const glm::vec3& point);
};

} // namespace vct::doc
