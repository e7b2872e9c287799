#pragma once

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <limits>

namespace vct::render {

/** Axis-aligned box; empty until a point is added. */
struct Aabb {
    glm::vec3 min { std::numeric_limits<float>::max() };
    glm::vec3 max { -std::numeric_limits<float>::max() };

    bool isEmpty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    void extend(const glm::vec3& p)
    {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void extend(const Aabb& other)
    {
        if (!other.isEmpty()) {
            extend(other.min);
            extend(other.max);
        }
    }
    glm::vec3 size() const { return isEmpty() ? glm::vec3(0.0f) : max - min; }
    glm::vec3 center() const { return (min + max) * 0.5f; }
    /** Whether @p p lies in the box, faces included. */
    bool contains(const glm::vec3& p) const
    {
        return p.x >= min.x && p.y >= min.y && p.z >= min.z && p.x <= max.x && p.y <= max.y && p.z <= max.z;
    }
    /** The same box moved by @p offset (empty stays empty). */
    Aabb translated(const glm::vec3& offset) const
    {
        return isEmpty() ? *this : Aabb { min + offset, max + offset };
    }
};

} // namespace vct::render
