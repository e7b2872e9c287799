#pragma once

#include "image/RadianceImage.h"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace vct::io {

/**
 * Portable float map: "PF" (RGB) or "Pf" (grey) header, width and height, a scale whose sign gives the
 * byte order (negative = little-endian), then 32-bit floats with rows running bottom to top. Images
 * in memory run top to bottom, so rows are flipped on the way in and out. The scale's magnitude is
 * ignored on read and written as 1: values are stored as absolute radiance.
 */
class PfmFile {
public:
    /**
     * Reads a PFM file; a "Pf" grey file becomes RGB with equal channels. Returns nothing on failure
     * and, if @p error is set, a message naming the file and the problem.
     */
    static std::optional<render::RadianceImage> read(
        const std::filesystem::path& path, std::string* error = nullptr);

    /**
     * Writes @p image as little-endian "PF", replacing @p path atomically. Returns false (and an error
     * naming the file) for an invalid image or an I/O failure; an existing file is then left whole.
     */
    static bool write(
        const std::filesystem::path& path, const render::RadianceImage& image, std::string* error = nullptr);

    /**
     * Decodes PFM bytes already in memory. @p sourceName only labels error messages (a file name,
     * or something like "<memory>").
     */
    static std::optional<render::RadianceImage> decode(
        std::string_view bytes, const std::string& sourceName, std::string* error = nullptr);

    /** Encodes @p image as little-endian "PF" bytes. The image must be valid (see ImageLimits). */
    static std::string encode(const render::RadianceImage& image);
};

} // namespace vct::io
