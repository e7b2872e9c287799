#pragma once

#include "scene/Scene.h"

namespace vct::doc {

/**
 * A procedural, Sponza-like courtyard in metres, Y up, centred on the origin with the floor's top at y = 0.
 *
 * Outer walls enclose 30 m (x) by 14 m (z), 13 m high, open to the sky. Along both long sides run two storeys
 * of arcades on the lines z = +-4: columns carrying semicircular arches, a gallery floor slab between the
 * storeys, a parapet on the upper storey and a covered gallery 2.7 m deep behind each arcade (the outer wall
 * is its back wall, with a ceiling over each storey). Coloured cloths hang from the upper parapets into the
 * courtyard. About 57 000 triangles; the same every time. Front faces are counter-clockwise and face the
 * visible side.
 */
class AtriumGenerator {
public:
    static constexpr float kLength = 30.0f; ///< Metres along x between the inner faces of the end walls.
    static constexpr float kWidth = 14.0f; ///< Metres along z between the inner faces of the long walls.
    static constexpr float kHeight = 13.0f; ///< Metres, top of the walls.
    static constexpr float kFloorY = 0.0f; ///< Height of the floor's top surface.
    static constexpr float kArcadeZ = 4.0f; ///< The arcades' centre lines are z = +-kArcadeZ.

    /** Appends the courtyard's meshes and their materials (stone, floor, column stone, cloths) to `scene`. */
    static void generate(render::Scene& scene);
};

} // namespace vct::doc
