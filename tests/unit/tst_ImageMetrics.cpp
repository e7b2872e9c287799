#include "imageio/ImageMetrics.h"

#include "image/RadianceImage.h"

#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include <QtTest>

#include <cmath>
#include <limits>
#include <stdexcept>

using vct::io::ImageMetrics;
using vct::render::RadianceImage;

namespace {

RadianceImage constant(int width, int height, const glm::vec3& value)
{
    RadianceImage image(width, height);
    for (glm::vec3& p : image.pixels)
        p = value;
    return image;
}

RadianceImage ramp(int width, int height)
{
    RadianceImage image(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x)
            image.at(x, y) = glm::vec3(float(x), float(y), float(x * y) + 0.5f);
    }
    return image;
}

bool near(double a, double b, double tolerance = 1e-12)
{
    return std::abs(a - b) <= tolerance * std::max(1.0, std::abs(b));
}

} // namespace

class tst_ImageMetrics : public QObject {
    Q_OBJECT

private slots:
    void identicalImages();
    void constantOffset();
    void epsilonGuardsDarkPixels();
    void psnrKnownValue();
    void meanRadianceAndLuminance();
    void nonFiniteCount();
    void downsampleBoxAverages();
    void downsampleBoxRejectsBadFactors();
    void errorHeatmapColours();
    void mismatchThrows();
};

void tst_ImageMetrics::identicalImages()
{
    const RadianceImage a = ramp(5, 3);
    QCOMPARE(ImageMetrics::relativeMse(a, a), 0.0);
    QCOMPARE(ImageMetrics::mse(a, a), 0.0);
    QCOMPARE(ImageMetrics::rmse(a, a), 0.0);
    QVERIFY(std::isinf(ImageMetrics::psnr(a, a, 1.0)));
    QVERIFY(ImageMetrics::psnr(a, a, 1.0) > 0.0);
}

void tst_ImageMetrics::constantOffset()
{
    const RadianceImage reference = constant(4, 3, glm::vec3(1.0f));
    const RadianceImage image = constant(4, 3, glm::vec3(1.5f));
    // Every channel: 0.5^2 / (1^2 + 0.01).
    QVERIFY(near(ImageMetrics::relativeMse(image, reference), 0.25 / 1.01));
    QVERIFY(near(ImageMetrics::relativeMse(image, reference, 0.0), 0.25));
    QVERIFY(near(ImageMetrics::mse(image, reference), 0.25));
    QVERIFY(near(ImageMetrics::rmse(image, reference), 0.5));
    // The reference is the second argument: swapping changes the denominator.
    QVERIFY(near(ImageMetrics::relativeMse(reference, image, 0.0), 0.25 / 2.25));
}

void tst_ImageMetrics::epsilonGuardsDarkPixels()
{
    // One channel off by 0.1 on a black reference, the others exact: (0.01 / 0.01 + 0 + 0) / 3.
    RadianceImage reference(1, 1);
    reference.at(0, 0) = glm::vec3(0.0f, 1.0f, 2.0f);
    RadianceImage image = reference;
    image.at(0, 0).r = 0.1f;
    QVERIFY(near(ImageMetrics::relativeMse(image, reference), double(0.1f) * double(0.1f) / 0.01 / 3.0));
    QCOMPARE(ImageMetrics::kRelativeMseEpsilon, 1e-2);
}

void tst_ImageMetrics::psnrKnownValue()
{
    const RadianceImage reference = constant(3, 2, glm::vec3(0.0f));
    const RadianceImage image = constant(3, 2, glm::vec3(0.1f));
    // mse = 0.01 (in float precision): peak 1 gives 20 dB, peak 10 gives 40 dB.
    const double mse = double(0.1f) * double(0.1f);
    QVERIFY(near(ImageMetrics::mse(image, reference), mse));
    QVERIFY(near(ImageMetrics::psnr(image, reference, 1.0), 10.0 * std::log10(1.0 / mse)));
    QVERIFY(std::abs(ImageMetrics::psnr(image, reference, 1.0) - 20.0) < 1e-5);
    QVERIFY(std::abs(ImageMetrics::psnr(image, reference, 10.0) - 40.0) < 1e-5);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, ImageMetrics::psnr(image, reference, 0.0));
}

void tst_ImageMetrics::meanRadianceAndLuminance()
{
    RadianceImage image(2, 1);
    image.at(0, 0) = glm::vec3(1.0f, 2.0f, 3.0f);
    image.at(1, 0) = glm::vec3(3.0f, 4.0f, 5.0f);
    QCOMPARE(ImageMetrics::meanRadiance(image), glm::vec3(2.0f, 3.0f, 4.0f));
    QVERIFY(near(ImageMetrics::meanLuminance(image), 0.2126 * 2.0 + 0.7152 * 3.0 + 0.0722 * 4.0));
    QVERIFY(near(ImageMetrics::meanLuminance(constant(3, 3, glm::vec3(1.0f))), 1.0));
    QVERIFY(near(ImageMetrics::meanLuminance(constant(1, 2, glm::vec3(1.0f, 0.0f, 0.0f))), 0.2126));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, ImageMetrics::meanRadiance(RadianceImage()));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, ImageMetrics::meanLuminance(RadianceImage()));
}

void tst_ImageMetrics::nonFiniteCount()
{
    RadianceImage image = ramp(3, 3);
    QCOMPARE(ImageMetrics::nonFiniteCount(image), std::size_t(0));
    image.at(0, 0) = glm::vec3(std::numeric_limits<float>::quiet_NaN(),
        std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity());
    image.at(2, 1).g = std::numeric_limits<float>::quiet_NaN();
    image.at(1, 2).b = std::numeric_limits<float>::max(); // huge but finite
    QCOMPARE(ImageMetrics::nonFiniteCount(image), std::size_t(4));
    QCOMPARE(ImageMetrics::nonFiniteCount(RadianceImage()), std::size_t(0));
}

void tst_ImageMetrics::downsampleBoxAverages()
{
    // 4x2 -> 2x1: each output pixel averages a 2x2 block.
    RadianceImage image(4, 2);
    image.at(0, 0) = glm::vec3(1, 0, 4);
    image.at(1, 0) = glm::vec3(2, 0, 4);
    image.at(0, 1) = glm::vec3(3, 0, 4);
    image.at(1, 1) = glm::vec3(6, 8, 4);
    image.at(2, 0) = glm::vec3(10, 1, 0);
    image.at(3, 0) = glm::vec3(20, 1, 0);
    image.at(2, 1) = glm::vec3(30, 1, 0);
    image.at(3, 1) = glm::vec3(40, 1, 2);
    const RadianceImage half = ImageMetrics::downsampleBox(image, 2);
    QCOMPARE(half.width, 2);
    QCOMPARE(half.height, 1);
    QCOMPARE(half.at(0, 0), glm::vec3(3.0f, 2.0f, 4.0f));
    QCOMPARE(half.at(1, 0), glm::vec3(25.0f, 1.0f, 0.5f));

    // Non-square with factor 3: averages of the ramp are the block centres.
    const RadianceImage big = ramp(6, 9);
    const RadianceImage third = ImageMetrics::downsampleBox(big, 3);
    QCOMPARE(third.width, 2);
    QCOMPARE(third.height, 3);
    QCOMPARE(third.at(1, 2).r, 4.0f);
    QCOMPARE(third.at(1, 2).g, 7.0f);
    QCOMPARE(third.at(1, 2).b, 28.5f); // mean of x*y over x in 3..5, y in 6..8 is 4 * 7, plus 0.5

    const RadianceImage same = ImageMetrics::downsampleBox(big, 1);
    QCOMPARE(same.width, big.width);
    QVERIFY(same.pixels == big.pixels);
    // The mean is preserved by box filtering.
    QVERIFY(glm::all(glm::lessThan(
        glm::abs(ImageMetrics::meanRadiance(third) - ImageMetrics::meanRadiance(big)), glm::vec3(1e-5f))));
}

void tst_ImageMetrics::downsampleBoxRejectsBadFactors()
{
    const RadianceImage image = ramp(6, 4);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, ImageMetrics::downsampleBox(image, 0));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, ImageMetrics::downsampleBox(image, -2));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, ImageMetrics::downsampleBox(image, 4));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, ImageMetrics::downsampleBox(RadianceImage(), 2));
}

void tst_ImageMetrics::errorHeatmapColours()
{
    const RadianceImage reference = constant(3, 2, glm::vec3(1.0f));
    RadianceImage image = reference;
    image.at(1, 0) = glm::vec3(1.5f); // relative error 0.5: half-way, green
    image.at(2, 0) = glm::vec3(3.0f); // relative error 2: past full scale, red
    image.at(0, 1).r = std::numeric_limits<float>::quiet_NaN();
    image.at(1, 1) = glm::vec3(1.25f); // 0.25: blue

    const RadianceImage heat = ImageMetrics::errorHeatmap(image, reference, 1.0, 0.0);
    QCOMPARE(heat.width, 3);
    QCOMPARE(heat.height, 2);
    QCOMPARE(heat.pixels.size(), std::size_t(6));
    QCOMPARE(heat.at(0, 0), glm::vec3(0.0f));
    QCOMPARE(heat.at(1, 0), glm::vec3(0.0f, 1.0f, 0.0f));
    QCOMPARE(heat.at(2, 0), glm::vec3(1.0f, 0.0f, 0.0f));
    QCOMPARE(heat.at(0, 1), glm::vec3(1.0f, 0.0f, 1.0f));
    QCOMPARE(heat.at(1, 1), glm::vec3(0.0f, 0.0f, 1.0f));
    QCOMPARE(heat.at(2, 1), glm::vec3(0.0f));

    // Full scale stretches the ramp: error 0.5 of full scale 2 is a quarter, blue.
    QCOMPARE(ImageMetrics::errorHeatmap(image, reference, 2.0, 0.0).at(1, 0), glm::vec3(0.0f, 0.0f, 1.0f));
    // Identical images are black everywhere.
    for (const glm::vec3& p : ImageMetrics::errorHeatmap(reference, reference).pixels)
        QCOMPARE(p, glm::vec3(0.0f));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, ImageMetrics::errorHeatmap(image, reference, 0.0));
}

void tst_ImageMetrics::mismatchThrows()
{
    const RadianceImage a = ramp(4, 3);
    const RadianceImage transposed = ramp(3, 4); // same pixel count, different shape
    const RadianceImage empty;
    for (const RadianceImage* b : { &transposed, &empty }) {
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, ImageMetrics::relativeMse(a, *b));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, ImageMetrics::mse(a, *b));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, ImageMetrics::rmse(*b, a));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, ImageMetrics::psnr(a, *b, 1.0));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, ImageMetrics::errorHeatmap(*b, a));
    }
    RadianceImage inconsistent(4, 3);
    inconsistent.pixels.resize(5);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, ImageMetrics::mse(a, inconsistent));

    try {
        ImageMetrics::relativeMse(a, transposed);
        QFAIL("no exception");
    } catch (const std::invalid_argument& e) {
        const QString message = QString::fromUtf8(e.what());
        QVERIFY2(
            message.contains(QStringLiteral("4x3")) && message.contains(QStringLiteral("3x4")), e.what());
    }
}

QTEST_GUILESS_MAIN(tst_ImageMetrics)
#include "tst_ImageMetrics.moc"
