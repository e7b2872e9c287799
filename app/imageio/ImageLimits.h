#pragma once

#include "image/RadianceImage.h"

#include <cstddef>
#include <filesystem>
#include <string>

namespace vct::io {

/** The image sizes every reader and writer accepts, checked in one place so the formats agree. */
struct ImageLimits {
    /** Largest width or height, in pixels, that any reader or writer accepts. */
    static constexpr int kMaxDimension = 32768;

    /** Whether a width and height are both in [1, kMaxDimension]; sets a reason (no file name) if not. */
    static bool checkSize(long long width, long long height, std::string* reason)
    {
        if (width <= 0 || height <= 0) {
            if (reason)
                *reason = "non-positive image size " + std::to_string(width) + "x" + std::to_string(height);
            return false;
        }
        if (width > kMaxDimension || height > kMaxDimension) {
            if (reason)
                *reason = "image size " + std::to_string(width) + "x" + std::to_string(height) + " exceeds "
                    + std::to_string(kMaxDimension) + "x" + std::to_string(kMaxDimension);
            return false;
        }
        return true;
    }

    /**
     * Whether @p image can be written: a valid size and exactly width * height pixels. Writers call this
     * before touching the disk, so an invalid image never replaces a good file.
     */
    static bool checkWritable(
        const render::RadianceImage& image, const std::filesystem::path& path, std::string* error)
    {
        std::string reason;
        if (!checkSize(image.width, image.height, &reason)) {
            if (error)
                *error = path.string() + ": cannot write: " + reason;
            return false;
        }
        if (image.pixels.size() != std::size_t(image.width) * std::size_t(image.height)) {
            if (error)
                *error = path.string() + ": cannot write: image holds " + std::to_string(image.pixels.size())
                    + " pixels, expected " + std::to_string(image.width) + "x" + std::to_string(image.height);
            return false;
        }
        return true;
    }
};

} // namespace vct::io
