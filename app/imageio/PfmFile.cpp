#include "PfmFile.h"

#include "ImageLimits.h"
#include "files/AtomicFile.h"

#include <bit>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>

namespace vct::io {

namespace {

static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "RadianceImage pixels must be packed floats");

bool isSpace(char c)
{
    return std::isspace(static_cast<unsigned char>(c)) != 0;
}

/** Walks the text header: whitespace-separated tokens, then exactly one whitespace byte before the data. */
class HeaderReader {
public:
    explicit HeaderReader(std::string_view bytes)
        : m_bytes(bytes)
    {
    }

    std::string_view nextToken()
    {
        while (m_pos < m_bytes.size() && isSpace(m_bytes[m_pos]))
            ++m_pos;
        const std::size_t start = m_pos;
        while (m_pos < m_bytes.size() && !isSpace(m_bytes[m_pos]))
            ++m_pos;
        return m_bytes.substr(start, m_pos - start);
    }

    /** Consumes the single whitespace byte that ends the header; data may legally start with 0x20 etc. */
    bool endHeader()
    {
        if (m_pos >= m_bytes.size() || !isSpace(m_bytes[m_pos]))
            return false;
        ++m_pos;
        return true;
    }

    std::size_t position() const { return m_pos; }

private:
    std::string_view m_bytes;
    std::size_t m_pos = 0;
};

std::optional<long long> parseInt(std::string_view token)
{
    long long value = 0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc() || end != token.data() + token.size())
        return std::nullopt;
    return value;
}

std::optional<double> parseDouble(std::string_view token)
{
    double value = 0.0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc() || end != token.data() + token.size())
        return std::nullopt;
    return value;
}

float loadFloat(const char* bytes, bool littleEndian)
{
    std::uint32_t bits = 0;
    std::memcpy(&bits, bytes, sizeof bits);
    if (littleEndian != (std::endian::native == std::endian::little))
        bits = __builtin_bswap32(bits);
    return std::bit_cast<float>(bits);
}

void storeFloatLittleEndian(char* bytes, float value)
{
    auto bits = std::bit_cast<std::uint32_t>(value);
    if constexpr (std::endian::native == std::endian::big)
        bits = __builtin_bswap32(bits);
    std::memcpy(bytes, &bits, sizeof bits);
}

} // namespace

std::optional<render::RadianceImage> PfmFile::read(const std::filesystem::path& path, std::string* error)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        if (error)
            *error = path.string() + ": cannot open for reading (" + std::strerror(errno) + ")";
        return std::nullopt;
    }
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) {
        if (error)
            *error = path.string() + ": read error";
        return std::nullopt;
    }
    return decode(bytes, path.string(), error);
}

std::optional<render::RadianceImage> PfmFile::decode(
    std::string_view bytes, const std::string& sourceName, std::string* error)
{
    auto fail = [&](const std::string& why) -> std::optional<render::RadianceImage> {
        if (error)
            *error = sourceName + ": " + why;
        return std::nullopt;
    };
    if (bytes.empty())
        return fail("empty file, not a PFM image");

    HeaderReader header(bytes);
    const std::string_view magic = header.nextToken();
    int channels = 0;
    if (magic == "PF")
        channels = 3;
    else if (magic == "Pf")
        channels = 1;
    else
        return fail("bad PFM header: expected \"PF\" or \"Pf\" magic");

    const std::optional<long long> width = parseInt(header.nextToken());
    const std::optional<long long> height = parseInt(header.nextToken());
    if (!width || !height)
        return fail("bad PFM header: width and height must be integers");
    std::string reason;
    if (!ImageLimits::checkSize(*width, *height, &reason))
        return fail("bad PFM header: " + reason);

    const std::optional<double> scale = parseDouble(header.nextToken());
    if (!scale || *scale == 0.0 || !std::isfinite(*scale))
        return fail("bad PFM header: scale must be a non-zero finite number");
    if (!header.endHeader())
        return fail("bad PFM header: no whitespace after the scale (truncated?)");

    const std::size_t w = std::size_t(*width);
    const std::size_t h = std::size_t(*height);
    const std::size_t rowBytes = w * std::size_t(channels) * sizeof(float);
    const std::size_t expected = rowBytes * h;
    const std::size_t available = bytes.size() - header.position();
    if (available < expected)
        return fail("truncated PFM data: expected " + std::to_string(expected) + " bytes of pixels for "
            + std::to_string(w) + "x" + std::to_string(h) + ", found " + std::to_string(available));

    const bool littleEndian = *scale < 0.0;
    render::RadianceImage image(static_cast<int>(w), static_cast<int>(h));
    const char* data = bytes.data() + header.position();
    for (std::size_t fileRow = 0; fileRow < h; ++fileRow) {
        const char* row = data + fileRow * rowBytes;
        const int y = int(h - 1 - fileRow);
        for (std::size_t x = 0; x < w; ++x) {
            glm::vec3& pixel = image.at(int(x), y);
            if (channels == 3) {
                for (int c = 0; c < 3; ++c)
                    pixel[c] = loadFloat(row + (x * 3 + std::size_t(c)) * sizeof(float), littleEndian);
            } else {
                pixel = glm::vec3(loadFloat(row + x * sizeof(float), littleEndian));
            }
        }
    }
    return image;
}

std::string PfmFile::encode(const render::RadianceImage& image)
{
    const std::string header
        = "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
    const std::size_t w = std::size_t(image.width);
    const std::size_t h = std::size_t(image.height);
    const std::size_t rowBytes = w * 3 * sizeof(float);
    std::string bytes(header.size() + rowBytes * h, '\0');
    std::memcpy(bytes.data(), header.data(), header.size());
    char* data = bytes.data() + header.size();
    for (std::size_t fileRow = 0; fileRow < h; ++fileRow) {
        const int y = int(h - 1 - fileRow);
        char* row = data + fileRow * rowBytes;
        for (std::size_t x = 0; x < w; ++x) {
            const glm::vec3& pixel = image.at(int(x), y);
            for (int c = 0; c < 3; ++c)
                storeFloatLittleEndian(row + (x * 3 + std::size_t(c)) * sizeof(float), pixel[c]);
        }
    }
    return bytes;
}

bool PfmFile::write(const std::filesystem::path& path, const render::RadianceImage& image, std::string* error)
{
    if (!ImageLimits::checkWritable(image, path, error))
        return false;
    return files::AtomicFile::write(path, encode(image), error);
}

} // namespace vct::io
