#include "FileSizeLimit.h"
#include "TestSupport.h"

#include "imageio/ExrFile.h"
#include "imageio/ImageFile.h"
#include "imageio/PfmFile.h"
#include "imageio/ToneMapper.h"

#include "image/RadianceImage.h"

#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include <QDir>
#include <QFile>
// Tests get Qt Core and Test include paths only; Qt Gui is linked through vct_imageio (its PNG writer).
#include <QtGui/QImage>
#include <QtTest>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>

#include <csignal>
#include <sys/resource.h>

using vct::render::RadianceImage;
using namespace vct::io;

namespace {

std::filesystem::path outPath(const QString& name)
{
    const QString dir = vct::test::outputDir() + QStringLiteral("/imageio");
    QDir().mkpath(dir);
    return std::filesystem::path((dir + QLatin1Char('/') + name).toStdString());
}

std::filesystem::path referencePath(const char* name)
{
    return std::filesystem::path(
        (vct::test::referenceDir() + QLatin1Char('/') + QLatin1String(name)).toStdString());
}

QByteArray fileBytes(const std::filesystem::path& path)
{
    QFile file(QString::fromStdString(path.string()));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return file.readAll();
}

bool writeBytes(const std::filesystem::path& path, const QByteArray& bytes)
{
    QFile file(QString::fromStdString(path.string()));
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}

/** A non-square image whose every channel value is distinct and not exactly representable in half. */
RadianceImage makeTestImage(int width, int height)
{
    RadianceImage image(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x)
            image.at(x, y) = glm::vec3(float(x) + 0.001f * float(y), -0.5f * float(y) + 1e-7f * float(x),
                std::ldexp(1.2345678f, x - y));
    }
    return image;
}

bool bitwiseEqual(const RadianceImage& a, const RadianceImage& b)
{
    return a.width == b.width && a.height == b.height && a.pixels.size() == b.pixels.size()
        && std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(glm::vec3)) == 0;
}

float luminance(const glm::vec3& c)
{
    return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
}

float meanLuminance(const RadianceImage& image, int x0, int y0, int size)
{
    double sum = 0.0;
    for (int y = y0; y < y0 + size; ++y) {
        for (int x = x0; x < x0 + size; ++x)
            sum += luminance(image.at(x, y));
    }
    return float(sum / (size * size));
}

QByteArray bigEndianFloat(float value)
{
    const auto bits = std::bit_cast<std::uint32_t>(value);
    QByteArray bytes(4, '\0');
    for (int i = 0; i < 4; ++i)
        bytes[i] = char((bits >> (24 - 8 * i)) & 0xffu);
    return bytes;
}

float littleEndianFloatAt(const QByteArray& bytes, qsizetype offset)
{
    std::uint32_t bits = 0;
    for (int i = 0; i < 4; ++i)
        bits |= std::uint32_t(std::uint8_t(bytes[offset + i])) << (8 * i);
    return std::bit_cast<float>(bits);
}

QStringList directoryEntries(const std::filesystem::path& file)
{
    return QDir(QString::fromStdString(file.parent_path().string())).entryList(QDir::Files | QDir::Hidden);
}

} // namespace

class tst_ImageIo : public QObject {
    Q_OBJECT

private slots:
    void pfmRoundTripIsExact();
    void pfmStoresTopRowLast();
    void pfmReadsBigEndianAndGrey();
    void pfmRejectsBadFiles_data();
    void pfmRejectsBadFiles();
    void readsReferencePfm();
    void exrRoundTripIsExact();
    void exrReferenceMatchesPfm();
    void exrMissingChannelIsAnError();
    void exrGarbageIsAnError();
    void writeToMissingDirectoryFails_data();
    void writeToMissingDirectoryFails();
    void failedWriteKeepsExistingFile_data();
    void failedWriteKeepsExistingFile();
    void ioFailureKeepsExistingFile_data();
    void ioFailureKeepsExistingFile();
    void imageFileDispatchesByExtension();
    void toneMapperCurve();
    void toneMapperExposure();
    void pngIsToneMappedSrgb();
};

void tst_ImageIo::pfmRoundTripIsExact()
{
    const RadianceImage image = makeTestImage(7, 3);
    const auto path = outPath(QStringLiteral("roundtrip.pfm"));
    std::string error;
    QVERIFY2(PfmFile::write(path, image, &error), error.c_str());
    const auto back = PfmFile::read(path, &error);
    QVERIFY2(back, error.c_str());
    QCOMPARE(back->width, 7);
    QCOMPARE(back->height, 3);
    QVERIFY(bitwiseEqual(*back, image));

    // Non-finite values are radiance bugs worth keeping visible, so they survive too.
    RadianceImage special(1, 2);
    special.at(0, 0)
        = glm::vec3(std::numeric_limits<float>::infinity(), -0.0f, std::numeric_limits<float>::denorm_min());
    special.at(0, 1) = glm::vec3(std::numeric_limits<float>::quiet_NaN(), 0.0f, 3.0e38f);
    QVERIFY2(PfmFile::write(path, special, &error), error.c_str());
    const auto specialBack = PfmFile::read(path, &error);
    QVERIFY2(specialBack, error.c_str());
    QVERIFY(bitwiseEqual(*specialBack, special));
}

void tst_ImageIo::pfmStoresTopRowLast()
{
    RadianceImage image(2, 3);
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 2; ++x)
            image.at(x, y) = glm::vec3(float(10 * y + x), float(100 + 10 * y + x), float(200 + 10 * y + x));
    }
    const auto path = outPath(QStringLiteral("flip.pfm"));
    std::string error;
    QVERIFY2(PfmFile::write(path, image, &error), error.c_str());

    const QByteArray bytes = fileBytes(path);
    const QByteArray header("PF\n2 3\n-1.0\n");
    QVERIFY(bytes.startsWith(header));
    const qsizetype rowBytes = 2 * 3 * 4;
    QCOMPARE(bytes.size(), header.size() + 3 * rowBytes);
    for (int fileRow = 0; fileRow < 3; ++fileRow) {
        const int y = 2 - fileRow; // the file's first row is the image's bottom row
        for (int x = 0; x < 2; ++x) {
            for (int c = 0; c < 3; ++c) {
                const qsizetype offset = header.size() + fileRow * rowBytes + (x * 3 + c) * 4;
                QCOMPARE(littleEndianFloatAt(bytes, offset), image.at(x, y)[c]);
            }
        }
    }
    // The top-left pixel (0, 0, 0 + 100, 200) starts the last row.
    QCOMPARE(littleEndianFloatAt(bytes, header.size() + 2 * rowBytes + 4), 100.0f);
}

void tst_ImageIo::pfmReadsBigEndianAndGrey()
{
    // Positive scale: big-endian. Rows bottom to top: the second row in the file is the top row.
    QByteArray colour("PF\n1 2\n1.0\n");
    for (float v : { 1.0f, 2.0f, 3.0f, 4.0f, 5.5f, -6.0f })
        colour += bigEndianFloat(v);
    std::string error;
    const auto image
        = PfmFile::decode(std::string_view(colour.constData(), std::size_t(colour.size())), "mem", &error);
    QVERIFY2(image, error.c_str());
    QCOMPARE(image->at(0, 0), glm::vec3(4.0f, 5.5f, -6.0f));
    QCOMPARE(image->at(0, 1), glm::vec3(1.0f, 2.0f, 3.0f));

    QByteArray grey("Pf\n3 1\n1.0\n");
    for (float v : { 0.25f, 8.0f, 1e-3f })
        grey += bigEndianFloat(v);
    const auto path = outPath(QStringLiteral("grey.pfm"));
    QVERIFY(writeBytes(path, grey));
    const auto greyImage = PfmFile::read(path, &error);
    QVERIFY2(greyImage, error.c_str());
    QCOMPARE(greyImage->width, 3);
    QCOMPARE(greyImage->height, 1);
    QCOMPARE(greyImage->at(0, 0), glm::vec3(0.25f));
    QCOMPARE(greyImage->at(1, 0), glm::vec3(8.0f));
    QCOMPARE(greyImage->at(2, 0), glm::vec3(1e-3f));
}

void tst_ImageIo::pfmRejectsBadFiles_data()
{
    QTest::addColumn<QByteArray>("bytes");
    QTest::addColumn<QString>("problem");

    QByteArray valid("PF\n2 2\n-1.0\n");
    valid += QByteArray(2 * 2 * 3 * 4, '\0');
    QTest::newRow("truncated") << valid.left(valid.size() - 5) << "truncated";
    QTest::newRow("header only") << QByteArray("PF\n2 2\n-1.0\n") << "truncated";
    QTest::newRow("header cut") << QByteArray("PF\n2 2\n-1.0") << "header";
    QTest::newRow("empty") << QByteArray() << "empty";
    QTest::newRow("garbage") << QByteArray("\x89PNG\r\n\x1a\n garbage bytes") << "header";
    QTest::newRow("text size") << QByteArray("PF\nwide 2\n-1.0\n") << "header";
    QTest::newRow("zero width") << QByteArray("PF\n0 2\n-1.0\n") << "non-positive";
    QTest::newRow("negative height") << QByteArray("PF\n2 -3\n-1.0\n") << "non-positive";
    QTest::newRow("too large") << QByteArray("PF\n40000 2\n-1.0\n") << "exceeds 32768x32768";
    QTest::newRow("zero scale") << QByteArray("PF\n2 2\n0\n") << "scale";
}

void tst_ImageIo::pfmRejectsBadFiles()
{
    QFETCH(QByteArray, bytes);
    QFETCH(QString, problem);
    const auto path = outPath(
        QStringLiteral("bad_%1.pfm").arg(QString::fromLatin1(QTest::currentDataTag()).replace(' ', '_')));
    QVERIFY(writeBytes(path, bytes));
    std::string error;
    QVERIFY(!PfmFile::read(path, &error));
    QVERIFY2(error.find(path.string()) != std::string::npos, error.c_str());
    QVERIFY2(QString::fromStdString(error).contains(problem, Qt::CaseInsensitive), error.c_str());
    // The same through the dispatcher.
    std::string dispatched;
    QVERIFY(!ImageFile::read(path, &dispatched));
    QCOMPARE(dispatched, error);
}

void tst_ImageIo::readsReferencePfm()
{
    const auto path = referencePath("cornell_1024spp.pfm");
    std::string error;
    const auto image = PfmFile::read(path, &error);
    QVERIFY2(image, error.c_str());
    QCOMPARE(image->width, 256);
    QCOMPARE(image->height, 256);

    // The top-left corner is in shadow (about 0.04 luminance) while the centre sees the light (about 0.18).
    const float corner = meanLuminance(*image, 0, 0, 32);
    const float centre = meanLuminance(*image, 112, 112, 32);
    QVERIFY2(
        corner < 0.5f * centre, qPrintable(QStringLiteral("corner %1, centre %2").arg(corner).arg(centre)));

    // The ceiling light covers rows 30..40, columns 104..151 (top-down); pixels wholly on it read Ke.
    const glm::vec3 light = image->at(128, 35);
    QVERIFY2(glm::all(glm::lessThan(glm::abs(light - glm::vec3(17.0f, 12.0f, 4.0f)), glm::vec3(1e-3f))),
        qPrintable(QStringLiteral("(%1, %2, %3)").arg(light.r).arg(light.g).arg(light.b)));
    // Its mirror image across the horizontal centre line is the floor, so a flipped read fails here.
    QVERIFY(luminance(image->at(128, 255 - 35)) < 2.0f);
    int lightPixels = 0;
    for (int y = 0; y < image->height; ++y) {
        for (int x = 0; x < image->width; ++x) {
            if (glm::all(glm::lessThan(
                    glm::abs(image->at(x, y) - glm::vec3(17.0f, 12.0f, 4.0f)), glm::vec3(1e-3f)))) {
                ++lightPixels;
                QVERIFY2(y < 64, qPrintable(QStringLiteral("light pixel at (%1, %2)").arg(x).arg(y)));
            }
        }
    }
    QVERIFY2(lightPixels > 300, qPrintable(QString::number(lightPixels)));
}

void tst_ImageIo::exrRoundTripIsExact()
{
    const RadianceImage image = makeTestImage(5, 9);
    const auto path = outPath(QStringLiteral("roundtrip.exr"));
    std::string error;
    QVERIFY2(ExrFile::write(path, image, &error), error.c_str());
    const auto back = ExrFile::read(path, &error);
    QVERIFY2(back, error.c_str());
    QCOMPARE(back->width, 5);
    QCOMPARE(back->height, 9);
    QVERIFY(bitwiseEqual(*back, image));
}

void tst_ImageIo::exrReferenceMatchesPfm()
{
    std::string error;
    const auto exr = ExrFile::read(referencePath("cornell_1024spp.exr"), &error);
    QVERIFY2(exr, error.c_str());
    const auto pfm = PfmFile::read(referencePath("cornell_1024spp.pfm"), &error);
    QVERIFY2(pfm, error.c_str());
    QCOMPARE(exr->width, pfm->width);
    QCOMPARE(exr->height, pfm->height);
    float worst = 0.0f;
    for (std::size_t i = 0; i < pfm->pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const float a = exr->pixels[i][c];
            const float b = pfm->pixels[i][c];
            // Relative, with an absolute floor for the black background.
            worst = std::max(worst, std::abs(a - b) / std::max(std::abs(b), 1e-3f));
        }
    }
    QVERIFY2(worst <= 1e-3f, qPrintable(QStringLiteral("worst relative difference %1").arg(worst)));
}

void tst_ImageIo::exrMissingChannelIsAnError()
{
    const auto path = outPath(QStringLiteral("no_blue.exr"));
    std::string error;
    QVERIFY2(ExrFile::write(path, makeTestImage(4, 4), &error), error.c_str());
    // Rename channel "B" to "A" in the header (still sorted: A, G, R); pixel data does not name channels.
    QByteArray bytes = fileBytes(path);
    const QByteArray attribute("channels\0chlist\0", 16);
    const qsizetype at = bytes.indexOf(attribute);
    QVERIFY(at > 0);
    const qsizetype firstName = at + attribute.size() + 4; // skip the attribute's size
    QCOMPARE(bytes[firstName], 'B');
    bytes[firstName] = 'A';
    QVERIFY(writeBytes(path, bytes));

    QVERIFY(!ExrFile::read(path, &error));
    QVERIFY2(error.find(path.string()) != std::string::npos, error.c_str());
    QVERIFY2(error.find("\"B\"") != std::string::npos, error.c_str());
}

void tst_ImageIo::exrGarbageIsAnError()
{
    const auto path = outPath(QStringLiteral("garbage.exr"));
    QVERIFY(writeBytes(path, QByteArray("this is not an OpenEXR file at all")));
    std::string error;
    QVERIFY(!ExrFile::read(path, &error));
    QVERIFY2(error.find(path.string()) != std::string::npos, error.c_str());

    const auto missing = outPath(QStringLiteral("does_not_exist.exr"));
    QVERIFY(!ExrFile::read(missing, &error));
    QVERIFY2(error.find(missing.string()) != std::string::npos, error.c_str());
}

void tst_ImageIo::writeToMissingDirectoryFails_data()
{
    QTest::addColumn<QString>("name");
    QTest::newRow("png") << "image.png";
    QTest::newRow("pfm") << "image.pfm";
    QTest::newRow("exr") << "image.exr";
}

void tst_ImageIo::writeToMissingDirectoryFails()
{
    QFETCH(QString, name);
    const auto path = outPath(QStringLiteral("no_such_directory/") + name);
    std::filesystem::remove_all(path.parent_path());
    std::string error;
    QVERIFY(!ImageFile::write(path, makeTestImage(3, 2), 1.0f, &error));
    QVERIFY2(error.find(path.string()) != std::string::npos, error.c_str());
    QVERIFY(!std::filesystem::exists(path.parent_path()));
}

void tst_ImageIo::failedWriteKeepsExistingFile_data()
{
    QTest::addColumn<QString>("name");
    QTest::newRow("png") << "keep.png";
    QTest::newRow("pfm") << "keep.pfm";
    QTest::newRow("exr") << "keep.exr";
}

void tst_ImageIo::failedWriteKeepsExistingFile()
{
    QFETCH(QString, name);
    const auto path = outPath(name);
    std::string error;
    QVERIFY2(ImageFile::write(path, makeTestImage(4, 3), 1.0f, &error), error.c_str());
    const QByteArray before = fileBytes(path);
    QVERIFY(!before.isEmpty());

    QVERIFY(!ImageFile::write(path, RadianceImage(), 1.0f, &error));
    QVERIFY2(error.find(path.string()) != std::string::npos, error.c_str());

    RadianceImage inconsistent(4, 3);
    inconsistent.pixels.pop_back();
    QVERIFY(!ImageFile::write(path, inconsistent, 1.0f, &error));
    QVERIFY2(error.find(path.string()) != std::string::npos, error.c_str());

    QCOMPARE(fileBytes(path), before);
}

void tst_ImageIo::ioFailureKeepsExistingFile_data()
{
    failedWriteKeepsExistingFile_data();
}

void tst_ImageIo::ioFailureKeepsExistingFile()
{
    QFETCH(QString, name);
    const auto path = outPath(QStringLiteral("io_") + name);
    std::string error;
    QVERIFY2(ImageFile::write(path, makeTestImage(4, 3), 1.0f, &error), error.c_str());
    const QByteArray before = fileBytes(path);
    const QStringList entriesBefore = directoryEntries(path);

    // Noise, so even PNG cannot compress it under the size limit: the temporary file's writes fail (EFBIG).
    RadianceImage big(256, 256);
    std::uint32_t state = 12345u;
    auto next = [&state] {
        state = state * 1664525u + 1013904223u;
        return float(state >> 8) / float(1u << 24);
    };
    for (glm::vec3& p : big.pixels)
        p = glm::vec3(next(), next(), next());
    bool written = true;
    {
        vct::test::FileSizeLimit limit(4096);
        QVERIFY(limit.isActive());
        written = ImageFile::write(path, big, 1.0f, &error);
    }
    QVERIFY(!written);
    QVERIFY2(error.find(path.string()) != std::string::npos, error.c_str());
    QCOMPARE(fileBytes(path), before);
    QCOMPARE(directoryEntries(path), entriesBefore); // no temporary file left behind
}

void tst_ImageIo::imageFileDispatchesByExtension()
{
    QCOMPARE(ImageFile::formatFor("a/b.PNG"), ImageFile::Format::Png);
    QCOMPARE(ImageFile::formatFor("b.pfm"), ImageFile::Format::Pfm);
    QCOMPARE(ImageFile::formatFor("b.Exr"), ImageFile::Format::Exr);
    QCOMPARE(ImageFile::formatFor("b.jpg"), ImageFile::Format::Unknown);
    QCOMPARE(ImageFile::formatFor("exr"), ImageFile::Format::Unknown);

    const RadianceImage image = makeTestImage(3, 5);
    std::string error;
    for (const char* name : { "dispatch.PFM", "dispatch.exr" }) {
        const auto path = outPath(QString::fromLatin1(name));
        // Exposure must not touch linear files.
        QVERIFY2(ImageFile::write(path, image, 4.0f, &error), error.c_str());
        const auto back = ImageFile::read(path, &error);
        QVERIFY2(back, error.c_str());
        QVERIFY(bitwiseEqual(*back, image));
    }
    const auto pfmBytes = fileBytes(outPath(QStringLiteral("dispatch.PFM")));
    QVERIFY(pfmBytes.startsWith("PF\n"));
    QVERIFY(fileBytes(outPath(QStringLiteral("dispatch.exr"))).startsWith("\x76\x2f\x31\x01"));

    const auto unknown = outPath(QStringLiteral("dispatch.tiff"));
    QVERIFY(!ImageFile::write(unknown, image, 1.0f, &error));
    QVERIFY2(error.find(unknown.string()) != std::string::npos, error.c_str());
    QVERIFY(!std::filesystem::exists(unknown));

    const auto png = outPath(QStringLiteral("dispatch.png"));
    QVERIFY2(ImageFile::write(png, image, 1.0f, &error), error.c_str());
    QVERIFY(!ImageFile::read(png, &error));
    QVERIFY2(error.find(png.string()) != std::string::npos, error.c_str());
}

void tst_ImageIo::toneMapperCurve()
{
    QCOMPARE(ToneMapper::filmic(0.0f), 0.0f);
    QCOMPARE(ToneMapper::filmic(-1.0f), 0.0f);
    QCOMPARE(ToneMapper::filmic(std::numeric_limits<float>::quiet_NaN()), 0.0f);
    QCOMPARE(ToneMapper::filmic(std::numeric_limits<float>::infinity()), 1.0f);
    QCOMPARE(ToneMapper::filmic(1000.0f), 1.0f);
    QCOMPARE(ToneMapper::srgbOetf(0.0f), 0.0f);
    QCOMPARE(ToneMapper::srgbOetf(1.0f), 1.0f);
    QVERIFY(std::abs(ToneMapper::srgbOetf(0.001f) - 0.01292f) < 1e-6f); // linear toe
    QVERIFY(std::abs(ToneMapper::srgbOetf(0.5f) - 0.735357f) < 1e-5f);

    float previous = -1.0f;
    int previousByte = -1;
    const ToneMapper mapper;
    for (int i = 0; i <= 4000; ++i) {
        const float x = float(i) * 0.005f; // 0 .. 20
        const float y = ToneMapper::filmic(x);
        QVERIFY2(y >= previous, qPrintable(QStringLiteral("not monotonic at %1").arg(x)));
        previous = y;
        const int byte = mapper.toRgb8(glm::vec3(x)).g;
        QVERIFY(byte >= previousByte);
        previousByte = byte;
    }
    QCOMPARE(int(mapper.toRgb8(glm::vec3(0.0f)).r), 0);
    QCOMPARE(mapper.toRgb8(glm::vec3(100.0f)), glm::u8vec3(255));
    QCOMPARE(mapper.toRgb8(glm::vec3(std::numeric_limits<float>::quiet_NaN())), glm::u8vec3(0));

    // Mid grey: ACES(0.18) = 0.2669, sRGB-encoded 0.5534, byte 141 -- a visibly mid-range value.
    const float aces = 0.18f * (2.51f * 0.18f + 0.03f) / (0.18f * (2.43f * 0.18f + 0.59f) + 0.14f);
    QVERIFY(std::abs(ToneMapper::filmic(0.18f) - aces) < 1e-6f);
    const int grey = mapper.toRgb8(glm::vec3(0.18f)).r;
    QVERIFY2(grey >= 140 && grey <= 142, qPrintable(QString::number(grey)));

    // Clamp leaves display-range values alone apart from the OETF.
    const ToneMapper clamp(1.0f, ToneMapper::Curve::Clamp);
    QCOMPARE(clamp.toRgb8(glm::vec3(1.0f, 0.5f, 0.0f)), glm::u8vec3(255, 188, 0));
    QCOMPARE(clamp.toRgb8(glm::vec3(7.0f, -1.0f, 0.0f)), glm::u8vec3(255, 0, 0));
}

void tst_ImageIo::toneMapperExposure()
{
    QCOMPARE(ToneMapper::exposureFromEv(0.0f), 1.0f);
    QCOMPARE(ToneMapper::exposureFromEv(1.0f), 2.0f);
    QCOMPARE(ToneMapper::exposureFromEv(-2.0f), 0.25f);
    ToneMapper mapper;
    mapper.setExposureEv(3.0f);
    QCOMPARE(mapper.exposure(), 8.0f);
    // One stop up on 0.09 equals 0.18 at exposure 1.
    QCOMPARE(ToneMapper(2.0f).toRgb8(glm::vec3(0.09f)), ToneMapper().toRgb8(glm::vec3(0.18f)));
}

void tst_ImageIo::pngIsToneMappedSrgb()
{
    // Non-square and padded (width 5: 15 bytes a row) to catch stride and orientation mistakes.
    RadianceImage image(5, 2);
    image.at(0, 0) = glm::vec3(100.0f, 0.0f, 0.18f); // top-left
    image.at(4, 1) = glm::vec3(0.0f, 0.5f, 0.0f); // bottom-right
    const auto path = outPath(QStringLiteral("tonemapped.png"));
    std::string error;
    QVERIFY2(ImageFile::write(path, image, 1.0f, &error), error.c_str());

    const QImage png(QString::fromStdString(path.string()));
    QVERIFY(!png.isNull());
    QCOMPARE(png.width(), 5);
    QCOMPARE(png.height(), 2);
    const ToneMapper mapper;
    for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 5; ++x) {
            const glm::u8vec3 expected = mapper.toRgb8(image.at(x, y));
            const QRgb actual = png.pixel(x, y);
            QCOMPARE(qRed(actual), int(expected.r));
            QCOMPARE(qGreen(actual), int(expected.g));
            QCOMPARE(qBlue(actual), int(expected.b));
        }
    }
    QCOMPARE(qRed(png.pixel(0, 0)), 255);
    QCOMPARE(qRgb(0, 0, 0), png.pixel(1, 0) | 0xff000000u);

    // Exposure applies to PNG: a quarter of the radiance at exposure 4 gives the same bytes.
    RadianceImage dim = image;
    for (glm::vec3& p : dim.pixels)
        p *= 0.25f;
    const auto dimPath = outPath(QStringLiteral("tonemapped_dim.png"));
    QVERIFY2(ImageFile::write(dimPath, dim, 4.0f, &error), error.c_str());
    QCOMPARE(QImage(QString::fromStdString(dimPath.string())).convertToFormat(QImage::Format_RGB32),
        png.convertToFormat(QImage::Format_RGB32));
}

QTEST_GUILESS_MAIN(tst_ImageIo)
#include "tst_ImageIo.moc"
