#pragma once

#include <glm/vec3.hpp>

#include <vector>

namespace vct::render {

/**
 * A rectangle or disk that emits from its front face: an area light without a body. Both renderers light with
 * it as they light with emissive triangles (exact Lambertian irradiance, soft shadows, every bounce), but it
 * is no geometry: the camera does not see it, it casts no shadow and it is not voxelized, as area lights in
 * Blender, Unreal or Unity. A disk is the regular polygon of kDiskSides sides with the disk's area, in both
 * renderers, so they light with the same shape.
 */
struct SurfaceLight {
    enum class Shape { Rectangle, Disk };
    static constexpr int kDiskSides = 12;

    Shape shape = Shape::Rectangle;
    glm::vec3 centre { 0.0f }; ///< World space, metres.
    glm::vec3 direction { 0.0f, -1.0f, 0.0f }; ///< The way the front face looks (need not be normalised).
    float width = 1.0f; ///< Rectangles: metres along the width axis; disks: the diameter.
    float height = 1.0f; ///< Rectangles: metres along the height axis; unused by disks.
    /// Turns the rectangle about its direction, degrees. At 0 its width runs along the horizontal axis
    /// perpendicular to the direction (world x for a light facing straight up or down).
    float rotationDeg = 0.0f;
    glm::vec3 radiance { 1.0f }; ///< Emitted radiance, W/(m^2 sr), per channel, front face only.
    bool castsShadows = true;

    bool operator==(const SurfaceLight& other) const = default;
    /**
     * World-space corners, three per triangle, counter-clockwise seen from the front. Empty when the light
     * cannot emit: a zero or non-finite direction, size or centre.
     */
    std::vector<glm::vec3> triangles() const;
    /** Unit width and height axes (front = cross(width, height)); false when the direction is unusable. */
    bool axes(glm::vec3& widthAxis, glm::vec3& heightAxis, glm::vec3& front) const;
    /** m^2 of the emitting shape as both renderers use it (the disk's polygon has the disk's area). */
    float area() const;
};

} // namespace vct::render
