#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace vct::render {

/** An 8-bit sRGB RGBA image, rows top to bottom, as decoded from a model's texture file. */
struct TextureImage {
    std::string name;
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
};

} // namespace vct::render
