#pragma once

#include "LightNode.h"

#include "scene/Aabb.h"

#include <glm/vec3.hpp>

#include <vector>

namespace vct::doc {

/**
 * A light as the Light panel adds it: placed where it lights something, and as strong as the scene's own
 * lights, so that adding one to a sunlit courtyard or to a dim room neither vanishes nor burns the image out.
 */
class NewLight {
public:
    /**
     * A new light of `type` for a scene with these bounds, lights and a camera looking at `lookAt`. Points
     * and spots stand at `lookAt`, a directional light slants down, rects and disks hang under the top of the
     * scene facing down. Its strength, to two significant digits, gives, a quarter of the scene's diagonal
     * away, the mean irradiance the existing lights give at `lookAt` (π W/m² without any, which a white wall
     * shows as radiance 1).
     */
    static LightNode make(LightType type, const render::Aabb& bounds, const glm::vec3& lookAt,
        const std::vector<LightNode>& existing);

    /** The irradiance, W/m², `light` gives a surface at `point` facing it, unshadowed (brightest channel). */
    static float irradianceAt(const LightNode& light, const glm::vec3& point);
};

} // namespace vct::doc
