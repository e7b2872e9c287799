#pragma once

#include "ToneMapper.h"

#include "image/RadianceImage.h"

#include <filesystem>
#include <optional>
#include <string>

namespace vct::io {

/**
 * Reads and writes images by file extension (case-insensitive): .png is display-referred 8-bit sRGB
 * through ToneMapper; .pfm and .exr store linear radiance unchanged. Every write replaces the target
 * atomically, so a failed write leaves an existing file whole. Errors name the file.
 */
class ImageFile {
public:
    enum class Format { Unknown, Png, Pfm, Exr };

    /** The format an extension selects, or Unknown. */
    static Format formatFor(const std::filesystem::path& path);

    /**
     * Writes @p image to @p path. @p exposure (a linear multiplier) only affects PNG, which is
     * tone-mapped with ToneMapper's filmic curve; PFM and EXR always store the radiance as it is, so
     * they stay comparable with references. Returns false with an error on failure.
     */
    static bool write(const std::filesystem::path& path, const render::RadianceImage& image,
        float exposure = 1.0f, std::string* error = nullptr);

    /** As above, with full control over PNG tone mapping (e.g. ToneMapper::Curve::Clamp for heatmaps). */
    static bool write(const std::filesystem::path& path, const render::RadianceImage& image,
        const ToneMapper& toneMapper, std::string* error = nullptr);

    /** Reads a .pfm or .exr file as linear radiance; PNG and others are refused (they are not radiance). */
    static std::optional<render::RadianceImage> read(
        const std::filesystem::path& path, std::string* error = nullptr);
};

} // namespace vct::io
