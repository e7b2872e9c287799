#pragma once

#include "scene/TextureImage.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace vct::render {

/**
 * An sRGB albedo texture decoded once to linear RGB, looked up as the GL renderer's sampler does: bilinear
 * with repeat, decoding before filtering (as GL does for sRGB textures), row 0 at t = 0 (the importer flips
 * V). An empty or malformed image reads as white, which leaves the albedo it multiplies unchanged.
 */
class LinearTexture {
public:
    explicit LinearTexture(const TextureImage& image);

    glm::vec3 sample(const glm::vec2& uv) const;

private:
    const glm::vec3& texel(int x, int y) const;

    int m_width = 0;
    int m_height = 0;
    std::vector<glm::vec3> m_texels;
};

} // namespace vct::render
