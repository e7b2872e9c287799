#pragma once

#include "image/RadianceImage.h"

#include <filesystem>
#include <optional>
#include <string>

namespace vct::io {

/**
 * OpenEXR scanline or tiled images holding linear RGB radiance. Reads R, G and B channels of any
 * pixel type (half, float or uint, converted to float); other channels (A, depth...) are ignored.
 * Writes 32-bit float R, G, B with ZIP compression, so a round trip is exact.
 */
class ExrFile {
public:
    /**
     * Reads the data window of @p path into an image, top row first. Fails, with an error naming
     * the file, when it cannot be opened or parsed, lacks an R, G or B channel, or is over
     * ImageLimits::kMaxDimension on a side.
     */
    static std::optional<render::RadianceImage> read(
        const std::filesystem::path& path, std::string* error = nullptr);

    /**
     * Writes @p image, replacing @p path atomically (encoded in memory, then written through a
     * temporary file and renamed). On failure returns false with an error naming the file, and an
     * existing file is left whole.
     */
    static bool write(
        const std::filesystem::path& path, const render::RadianceImage& image, std::string* error = nullptr);
};

} // namespace vct::io
