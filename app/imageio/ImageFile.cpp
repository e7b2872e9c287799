#include "ImageFile.h"

#include "ExrFile.h"
#include "ImageLimits.h"
#include "PfmFile.h"
#include "files/AtomicFile.h"

#include <QBuffer>
#include <QByteArray>
#include <QColorSpace>
#include <QImage>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <string_view>

namespace vct::io {

namespace {

bool writePng(const std::filesystem::path& path, const render::RadianceImage& image,
    const ToneMapper& toneMapper, std::string* error)
{
    const std::vector<std::uint8_t> rgb = toneMapper.toRgb8(image);
    QImage qimage(image.width, image.height, QImage::Format_RGB888);
    if (qimage.isNull()) {
        if (error)
            *error = path.string() + ": cannot allocate a " + std::to_string(image.width) + "x"
                + std::to_string(image.height) + " PNG image";
        return false;
    }
    // QImage pads scanlines to 4 bytes, so copy row by row.
    const std::size_t rowBytes = std::size_t(image.width) * 3;
    for (int y = 0; y < image.height; ++y)
        std::memcpy(qimage.scanLine(y), rgb.data() + std::size_t(y) * rowBytes, rowBytes);
    qimage.setColorSpace(QColorSpace(QColorSpace::SRgb));

    QByteArray encoded;
    QBuffer buffer(&encoded);
    buffer.open(QIODevice::WriteOnly);
    if (!qimage.save(&buffer, "PNG")) {
        if (error)
            *error = path.string() + ": cannot encode PNG";
        return false;
    }
    return files::AtomicFile::write(
        path, std::string_view(encoded.constData(), std::size_t(encoded.size())), error);
}

} // namespace

ImageFile::Format ImageFile::formatFor(const std::filesystem::path& path)
{
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
        [](unsigned char c) { return char(std::tolower(c)); });
    if (extension == ".png")
        return Format::Png;
    if (extension == ".pfm")
        return Format::Pfm;
    if (extension == ".exr")
        return Format::Exr;
    return Format::Unknown;
}

bool ImageFile::write(
    const std::filesystem::path& path, const render::RadianceImage& image, float exposure, std::string* error)
{
    return write(path, image, ToneMapper(exposure), error);
}

bool ImageFile::write(const std::filesystem::path& path, const render::RadianceImage& image,
    const ToneMapper& toneMapper, std::string* error)
{
    const Format format = formatFor(path);
    if (format == Format::Unknown) {
        if (error)
            *error = path.string() + ": unsupported image format \"" + path.extension().string()
                + "\" (use .png, .pfm or .exr)";
        return false;
    }
    if (!ImageLimits::checkWritable(image, path, error))
        return false;
    switch (format) {
    case Format::Png:
        return writePng(path, image, toneMapper, error);
    case Format::Pfm:
        return PfmFile::write(path, image, error);
    case Format::Exr:
        return ExrFile::write(path, image, error);
    case Format::Unknown:
        break;
    }
    return false;
}

std::optional<render::RadianceImage> ImageFile::read(const std::filesystem::path& path, std::string* error)
{
    switch (formatFor(path)) {
    case Format::Pfm:
        return PfmFile::read(path, error);
    case Format::Exr:
        return ExrFile::read(path, error);
    case Format::Png:
    case Format::Unknown:
        break;
    }
    if (error)
        *error = path.string() + ": cannot read \"" + path.extension().string()
            + "\" as radiance (only .pfm and .exr hold linear radiance)";
    return std::nullopt;
}

} // namespace vct::io
