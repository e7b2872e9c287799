#include "ExrFile.h"

#include "ImageLimits.h"
#include "files/AtomicFile.h"

#include <ImathBox.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>

#include <algorithm>
#include <cstring>
#include <exception>
#include <utility>

namespace vct::io {

namespace {

static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "RadianceImage pixels must be packed floats");

/** Collects an EXR file in memory so AtomicFile can write it in one go. */
class MemoryOStream final : public Imf::OStream {
public:
    explicit MemoryOStream(const std::string& fileName)
        : Imf::OStream(fileName.c_str())
    {
    }

    void write(const char c[], int n) override
    {
        const std::size_t end = m_pos + std::size_t(n);
        if (end > m_bytes.size())
            m_bytes.resize(end);
        std::memcpy(m_bytes.data() + m_pos, c, std::size_t(n));
        m_pos = end;
    }
    uint64_t tellp() override { return m_pos; }
    // OpenEXR seeks back to patch the line offset table after writing the pixels.
    void seekp(uint64_t pos) override { m_pos = std::size_t(pos); }

    std::string takeBytes() { return std::move(m_bytes); }

private:
    std::string m_bytes;
    std::size_t m_pos = 0;
};

} // namespace

std::optional<render::RadianceImage> ExrFile::read(const std::filesystem::path& path, std::string* error)
{
    auto fail = [&](const std::string& why) -> std::optional<render::RadianceImage> {
        if (error)
            *error = path.string() + ": " + why;
        return std::nullopt;
    };
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        return fail("cannot open for reading (no such file)");
    try {
        Imf::InputFile file(path.c_str());
        const Imf::Header& header = file.header();
        for (const char* name : { "R", "G", "B" }) {
            if (!header.channels().findChannel(name))
                return fail(std::string("EXR has no \"") + name + "\" channel (an RGB image is required)");
        }
        const Imath::Box2i window = header.dataWindow();
        const long long width = (long long)window.max.x - window.min.x + 1;
        const long long height = (long long)window.max.y - window.min.y + 1;
        std::string reason;
        if (!ImageLimits::checkSize(width, height, &reason))
            return fail("bad EXR data window: " + reason);

        render::RadianceImage image(static_cast<int>(width), static_cast<int>(height));
        char* base = reinterpret_cast<char*>(image.pixels.data());
        const std::size_t xStride = sizeof(glm::vec3);
        const std::size_t yStride = xStride * std::size_t(width);
        Imf::FrameBuffer frameBuffer;
        // Slice::Make accounts for a data window that does not start at (0, 0).
        frameBuffer.insert("R", Imf::Slice::Make(Imf::FLOAT, base, window, xStride, yStride));
        frameBuffer.insert("G", Imf::Slice::Make(Imf::FLOAT, base + sizeof(float), window, xStride, yStride));
        frameBuffer.insert(
            "B", Imf::Slice::Make(Imf::FLOAT, base + 2 * sizeof(float), window, xStride, yStride));
        file.setFrameBuffer(frameBuffer);
        file.readPixels(window.min.y, window.max.y);
        return image;
    } catch (const std::exception& e) {
        return fail(std::string("cannot read EXR: ") + e.what());
    }
}

bool ExrFile::write(const std::filesystem::path& path, const render::RadianceImage& image, std::string* error)
{
    if (!ImageLimits::checkWritable(image, path, error))
        return false;
    std::string bytes;
    try {
        Imf::Header header(image.width, image.height);
        header.compression() = Imf::ZIP_COMPRESSION;
        header.channels().insert("R", Imf::Channel(Imf::FLOAT));
        header.channels().insert("G", Imf::Channel(Imf::FLOAT));
        header.channels().insert("B", Imf::Channel(Imf::FLOAT));

        // OpenEXR only reads through the slices, but its API takes a non-const pointer.
        char* base = const_cast<char*>(reinterpret_cast<const char*>(image.pixels.data()));
        const std::size_t xStride = sizeof(glm::vec3);
        const std::size_t yStride = xStride * std::size_t(image.width);
        Imf::FrameBuffer frameBuffer;
        frameBuffer.insert("R", Imf::Slice(Imf::FLOAT, base, xStride, yStride));
        frameBuffer.insert("G", Imf::Slice(Imf::FLOAT, base + sizeof(float), xStride, yStride));
        frameBuffer.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), xStride, yStride));

        MemoryOStream stream(path.string());
        {
            // The file's destructor flushes the line offset table, so it must end before taking the bytes.
            Imf::OutputFile file(stream, header);
            file.setFrameBuffer(frameBuffer);
            file.writePixels(image.height);
        }
        bytes = stream.takeBytes();
    } catch (const std::exception& e) {
        if (error)
            *error = path.string() + ": cannot encode EXR: " + e.what();
        return false;
    }
    return files::AtomicFile::write(path, bytes, error);
}

} // namespace vct::io
