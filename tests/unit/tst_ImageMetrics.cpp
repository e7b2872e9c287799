#include "imageio/ImageMetrics.h"

#include "image/RadianceImage.h"
#include "imageio/ToneMapper.h"

#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include <QtTest>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

using vct::io::ImageMetrics;
using vct::io::ToneMapper;
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

/** A repeatable value in [0, 1) per (x, y, seed), so the tests do not depend on a library's RNG. */
double hashUnit(int x, int y, int seed)
{
    std::uint32_t h
        = std::uint32_t(x) * 0x8da6b343u ^ std::uint32_t(y) * 0xd8163841u ^ std::uint32_t(seed) * 0xcb1ab31fu;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return double(h) / 4294967296.0;
}

/** A textured image with radiance from ~0.05 to ~3: dark, mid-tone and filmic-shoulder values. */
RadianceImage textured(int width, int height, int seed)
{
    RadianceImage image(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const double base = 0.05 + 1.5 * double(x + y) / double(width + height);
            image.at(x, y) = glm::vec3(float(base + 1.5 * hashUnit(x, y, seed)),
                float(base + 0.5 * hashUnit(x, y, seed + 1)), float(base * hashUnit(x, y, seed + 2)));
        }
    }
    return image;
}

double displayLuma(const glm::vec3& radiance, float exposure)
{
    const glm::vec3 d = ToneMapper(exposure, ToneMapper::Curve::Filmic).toDisplay(radiance);
    return 0.2126 * double(d.r) + 0.7152 * double(d.g) + 0.0722 * double(d.b);
}

/**
 * Wang et al.'s SSIM written out literally, to check the separable implementation: a 2D Gaussian
 * window evaluated directly, the weighted means, variances Σw(x - μ)^2 and covariance, and
 * ((2 μx μy + C1)(2 σxy + C2)) / ((μx² + μy² + C1)(σx² + σy² + C2)) per window position.
 */
std::vector<double> directSsimMap(const RadianceImage& a, const RadianceImage& b, float exposure, int window)
{
    const double sigma = 1.5, c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
    const int r = (window - 1) / 2;
    std::vector<double> weights(std::size_t(window * window));
    double total = 0.0;
    for (int j = 0; j < window; ++j) {
        for (int i = 0; i < window; ++i) {
            const double d2 = double((i - r) * (i - r) + (j - r) * (j - r));
            total += weights[std::size_t(j * window + i)] = std::exp(-d2 / (2.0 * sigma * sigma));
        }
    }
    std::vector<double> map;
    for (int oy = 0; oy + window <= a.height; ++oy) {
        for (int ox = 0; ox + window <= a.width; ++ox) {
            double mx = 0.0, my = 0.0;
            for (int j = 0; j < window; ++j) {
                for (int i = 0; i < window; ++i) {
                    const double w = weights[std::size_t(j * window + i)] / total;
                    mx += w * displayLuma(a.at(ox + i, oy + j), exposure);
                    my += w * displayLuma(b.at(ox + i, oy + j), exposure);
                }
            }
            double vx = 0.0, vy = 0.0, cxy = 0.0;
            for (int j = 0; j < window; ++j) {
                for (int i = 0; i < window; ++i) {
                    const double w = weights[std::size_t(j * window + i)] / total;
                    const double dx = displayLuma(a.at(ox + i, oy + j), exposure) - mx;
                    const double dy = displayLuma(b.at(ox + i, oy + j), exposure) - my;
                    vx += w * dx * dx;
                    vy += w * dy * dy;
                    cxy += w * dx * dy;
                }
            }
            map.push_back(
                ((2.0 * mx * my + c1) * (2.0 * cxy + c2)) / ((mx * mx + my * my + c1) * (vx + vy + c2)));
        }
    }
    return map;
}

double mean(const std::vector<double>& values)
{
    double sum = 0.0;
    for (double v : values)
        sum += v;
    return sum / double(values.size());
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
    void ssimWindowSize();
    void ssimOfIdenticalImagesIsOne();
    void ssimIsSymmetric();
    void ssimOfConstantImagesIsLuminanceTerm();
    void ssimFallsWithNoise();
    void ssimMatchesDirectImplementation();
    void ssimMapSizeAndMean();
    void ssimRejectsBadInput();
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

void tst_ImageMetrics::ssimWindowSize()
{
    QCOMPARE(ImageMetrics::ssimWindowSize(11, 11), 11);
    QCOMPARE(ImageMetrics::ssimWindowSize(640, 360), 11);
    QCOMPARE(ImageMetrics::ssimWindowSize(10, 50), 9); // largest odd side that fits
    QCOMPARE(ImageMetrics::ssimWindowSize(50, 8), 7);
    QCOMPARE(ImageMetrics::ssimWindowSize(3, 3), 3);
    QCOMPARE(ImageMetrics::ssimWindowSize(2, 5), 1);
    QCOMPARE(ImageMetrics::ssimWindowSize(1, 1), 1);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, ImageMetrics::ssimWindowSize(0, 4));
}

void tst_ImageMetrics::ssimOfIdenticalImagesIsOne()
{
    for (const RadianceImage& image : { textured(32, 24, 1), textured(7, 9, 2), textured(2, 2, 3),
             constant(12, 12, glm::vec3(0.3f, 0.0f, 5.0f)), constant(1, 1, glm::vec3(0.0f)) }) {
        QCOMPARE(ImageMetrics::ssim(image, image), 1.0);
        QCOMPARE(ImageMetrics::ssim(image, image, 0.25f), 1.0);
        for (const glm::vec3& p : ImageMetrics::ssimMap(image, image).pixels)
            QCOMPARE(p, glm::vec3(1.0f));
    }
    // A copy, not the same object: equality is of values.
    const RadianceImage a = textured(20, 15, 4);
    const RadianceImage copy = a;
    QCOMPARE(ImageMetrics::ssim(a, copy), 1.0);
}

void tst_ImageMetrics::ssimIsSymmetric()
{
    const RadianceImage a = textured(30, 17, 5);
    const RadianceImage b = textured(30, 17, 9);
    const double ab = ImageMetrics::ssim(a, b);
    QVERIFY(ab < 0.9);
    QCOMPARE(ImageMetrics::ssim(b, a), ab); // exactly, not just nearly
    QCOMPARE(ImageMetrics::ssim(b, a, 3.0f), ImageMetrics::ssim(a, b, 3.0f));
    const RadianceImage flat = constant(8, 5, glm::vec3(0.2f));
    const RadianceImage busy = textured(8, 5, 1);
    QCOMPARE(ImageMetrics::ssim(flat, busy), ImageMetrics::ssim(busy, flat));
}

void tst_ImageMetrics::ssimOfConstantImagesIsLuminanceTerm()
{
    // Both variances and the covariance are 0, so the contrast-structure term is C2 / C2 = 1 and SSIM is
    // the luminance term of the two display lumas, the same at every window position.
    const double c1 = 0.01 * 0.01;
    struct Case {
        glm::vec3 a, b;
        float exposure;
    };
    for (const Case& c : { Case { glm::vec3(0.3f), glm::vec3(0.6f), 1.0f },
             Case { glm::vec3(0.2f, 0.5f, 1.0f), glm::vec3(2.0f, 0.1f, 0.05f), 1.0f },
             Case { glm::vec3(0.01f), glm::vec3(0.0f), 1.0f },
             Case { glm::vec3(0.3f), glm::vec3(0.6f), 4.0f } }) {
        const double mu1 = displayLuma(c.a, c.exposure);
        const double mu2 = displayLuma(c.b, c.exposure);
        const double expected = (2.0 * mu1 * mu2 + c1) / (mu1 * mu1 + mu2 * mu2 + c1);
        for (const auto& [w, h] : { std::pair(16, 12), std::pair(5, 5), std::pair(1, 3) }) {
            const double got = ImageMetrics::ssim(constant(w, h, c.a), constant(w, h, c.b), c.exposure);
            QVERIFY2(near(got, expected),
                qPrintable(QStringLiteral("%1x%2: %3 vs %4")
                               .arg(w)
                               .arg(h)
                               .arg(got, 0, 'g', 17)
                               .arg(expected, 0, 'g', 17)));
        }
    }
    // Hand-worked value for grey 0.3 vs 0.6 at exposure 1: filmic then sRGB, grey so luma = the channel.
    const double g1 = ToneMapper::srgbOetf(ToneMapper::filmic(0.3f));
    const double g2 = ToneMapper::srgbOetf(ToneMapper::filmic(0.6f));
    QVERIFY(near(ImageMetrics::ssim(constant(11, 11, glm::vec3(0.3f)), constant(11, 11, glm::vec3(0.6f))),
        (2.0 * g1 * g2 + c1) / (g1 * g1 + g2 * g2 + c1)));
}

void tst_ImageMetrics::ssimFallsWithNoise()
{
    const RadianceImage reference = textured(48, 40, 11);
    double previous = 1.0;
    for (float amplitude : { 0.002f, 0.01f, 0.03f, 0.1f, 0.3f, 1.0f }) {
        RadianceImage noisy = reference;
        for (int y = 0; y < noisy.height; ++y) {
            for (int x = 0; x < noisy.width; ++x) {
                // The same zero-mean pattern, scaled, so only the amplitude changes.
                const glm::vec3 n(
                    float(hashUnit(x, y, 100)), float(hashUnit(x, y, 101)), float(hashUnit(x, y, 102)));
                noisy.at(x, y) += amplitude * (2.0f * n - 1.0f);
            }
        }
        const double value = ImageMetrics::ssim(noisy, reference);
        QVERIFY2(value < previous,
            qPrintable(
                QStringLiteral("amplitude %1: %2 not below %3").arg(amplitude).arg(value).arg(previous)));
        QVERIFY(value > -1.0);
        previous = value;
    }
    QVERIFY(previous < 0.5);
}

void tst_ImageMetrics::ssimMatchesDirectImplementation()
{
    struct Case {
        int width, height, window;
        float exposure;
    };
    for (const Case& c : { Case { 16, 13, 11, 1.0f }, Case { 14, 11, 11, 0.5f }, Case { 7, 9, 7, 1.0f },
             Case { 10, 10, 9, 2.0f }, Case { 4, 6, 3, 1.0f }, Case { 2, 3, 1, 1.0f } }) {
        QCOMPARE(ImageMetrics::ssimWindowSize(c.width, c.height), c.window);
        const RadianceImage a = textured(c.width, c.height, 21);
        const RadianceImage b = textured(c.width, c.height, 22);
        const std::vector<double> direct = directSsimMap(a, b, c.exposure, c.window);
        const double got = ImageMetrics::ssim(a, b, c.exposure);
        QVERIFY2(std::abs(got - mean(direct)) < 1e-9,
            qPrintable(QStringLiteral("%1x%2: %3 vs %4")
                           .arg(c.width)
                           .arg(c.height)
                           .arg(got, 0, 'g', 17)
                           .arg(mean(direct), 0, 'g', 17)));

        const RadianceImage map = ImageMetrics::ssimMap(a, b, c.exposure);
        QCOMPARE(map.pixels.size(), direct.size());
        for (std::size_t i = 0; i < direct.size(); ++i)
            QVERIFY(std::abs(double(map.pixels[i].g) - direct[i]) < 1e-6);
    }
}

void tst_ImageMetrics::ssimMapSizeAndMean()
{
    const RadianceImage a = textured(40, 25, 31);
    const RadianceImage b = textured(40, 25, 32);
    const RadianceImage map = ImageMetrics::ssimMap(a, b);
    QCOMPARE(map.width, 40 - 10);
    QCOMPARE(map.height, 25 - 10);
    double sum = 0.0;
    for (const glm::vec3& p : map.pixels) {
        QCOMPARE(p.r, p.g);
        QCOMPARE(p.g, p.b);
        QVERIFY(p.r >= -1.0f && p.r <= 1.0f);
        sum += double(p.r);
    }
    QVERIFY(std::abs(sum / double(map.pixels.size()) - ImageMetrics::ssim(a, b)) < 1e-6);

    // A change confined to one corner shows up only in the windows that cover it.
    RadianceImage changed = a;
    changed.at(0, 0) = glm::vec3(10.0f);
    const RadianceImage local = ImageMetrics::ssimMap(changed, a);
    QVERIFY(local.at(0, 0).r < 1.0f);
    QCOMPARE(local.at(1, 0).r, 1.0f);
    QCOMPARE(local.at(map.width - 1, map.height - 1).r, 1.0f);

    QCOMPARE(ImageMetrics::ssimMap(a, b, 1.0f).pixels.size(), std::size_t(30 * 15));
    const RadianceImage tiny = ImageMetrics::ssimMap(textured(2, 4, 1), textured(2, 4, 2));
    QCOMPARE(tiny.width, 2); // window 1: one position per pixel
    QCOMPARE(tiny.height, 4);
}

void tst_ImageMetrics::ssimRejectsBadInput()
{
    const RadianceImage a = ramp(12, 12);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, ImageMetrics::ssim(a, ramp(12, 11)));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, ImageMetrics::ssim(RadianceImage(), RadianceImage()));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, ImageMetrics::ssimMap(a, ramp(11, 12)));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, ImageMetrics::ssim(a, a, 0.0f));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, ImageMetrics::ssim(a, a, -1.0f));
    QVERIFY_THROWS_EXCEPTION(
        std::invalid_argument, ImageMetrics::ssim(a, a, std::numeric_limits<float>::quiet_NaN()));
    QVERIFY_THROWS_EXCEPTION(
        std::invalid_argument, ImageMetrics::ssim(a, a, std::numeric_limits<float>::infinity()));
    // The tone mapper sends NaN to black, so a broken pixel lowers SSIM instead of poisoning it.
    RadianceImage broken = a;
    broken.at(5, 5) = glm::vec3(std::numeric_limits<float>::quiet_NaN());
    const double value = ImageMetrics::ssim(broken, a);
    QVERIFY(std::isfinite(value));
    QVERIFY(value < 1.0);
}

QTEST_GUILESS_MAIN(tst_ImageMetrics)
#include "tst_ImageMetrics.moc"
