#pragma once

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace vct::render {

/** Linear RGB radiance, W/(m^2 sr), rows top to bottom. */
struct RadianceImage {
    int width = 0;
    int height = 0;
    std::vector<glm::vec3> pixels; ///< width * height, row-major, top row first.

    RadianceImage() = default;
    RadianceImage(int w, int h)
        : width(w)
        , height(h)
        , pixels(std::size_t(w) * std::size_t(h), glm::vec3(0.0f))
    {
    }

    glm::vec3& at(int x, int y) { return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
    const glm::vec3& at(int x, int y) const
    {
        return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }
    bool isEmpty() const { return pixels.empty(); }
};

} // namespace vct::render
