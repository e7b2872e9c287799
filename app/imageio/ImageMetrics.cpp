#include "ImageMetrics.h"

#include "ToneMapper.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace vct::io {

namespace {

std::string sizeText(const render::RadianceImage& image)
{
    return std::to_string(image.width) + "x" + std::to_string(image.height);
}

void requireValid(const render::RadianceImage& image, const char* what)
{
    if (image.width <= 0 || image.height <= 0)
        throw std::invalid_argument(std::string(what) + " is empty (" + sizeText(image) + ")");
    if (image.pixels.size() != std::size_t(image.width) * std::size_t(image.height))
        throw std::invalid_argument(std::string(what) + " holds " + std::to_string(image.pixels.size())
            + " pixels, expected " + sizeText(image));
}

void requireComparable(const render::RadianceImage& image, const render::RadianceImage& reference)
{
    requireValid(image, "image");
    requireValid(reference, "reference");
    if (image.width != reference.width || image.height != reference.height)
        throw std::invalid_argument(
            "image size " + sizeText(image) + " differs from reference size " + sizeText(reference));
}

/** Mean over every pixel and channel of f(a, ref). */
template <typename F>
double meanOverChannels(const render::RadianceImage& image, const render::RadianceImage& reference, F f)
{
    requireComparable(image, reference);
    double sum = 0.0;
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c)
            sum += f(double(image.pixels[i][c]), double(reference.pixels[i][c]));
    }
    return sum / (3.0 * double(image.pixels.size()));
}

glm::vec3 ramp(double t)
{
    static constexpr std::array<glm::vec3, 5> kStops = { glm::vec3(0, 0, 0), glm::vec3(0, 0, 1),
        glm::vec3(0, 1, 0), glm::vec3(1, 1, 0), glm::vec3(1, 0, 0) };
    if (!std::isfinite(t))
        return glm::vec3(1, 0, 1);
    const double scaled = std::clamp(t, 0.0, 1.0) * double(kStops.size() - 1);
    const std::size_t lower = std::min(std::size_t(scaled), kStops.size() - 2);
    const float fraction = float(scaled - double(lower));
    return kStops[lower] + (kStops[lower + 1] - kStops[lower]) * fraction;
}

/** Per-position SSIM over the valid window positions, row-major. */
struct SsimField {
    int width = 0;
    int height = 0;
    std::vector<double> values;
};

/** Rec. 709 luma of the tone-mapped, sRGB-encoded display values, one double per pixel. */
std::vector<double> displayLuma(const render::RadianceImage& image, const ToneMapper& toneMapper)
{
    std::vector<double> luma(image.pixels.size());
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        const glm::vec3 d = toneMapper.toDisplay(image.pixels[i]);
        luma[i] = 0.2126 * double(d.r) + 0.7152 * double(d.g) + 0.0722 * double(d.b);
    }
    return luma;
}

std::vector<double> gaussianWeights(int size, double sigma)
{
    std::vector<double> weights(static_cast<std::size_t>(size));
    const double centre = double(size - 1) / 2.0;
    double sum = 0.0;
    for (int i = 0; i < size; ++i) {
        const double offset = double(i) - centre;
        weights[std::size_t(i)] = std::exp(-offset * offset / (2.0 * sigma * sigma));
        sum += weights[std::size_t(i)];
    }
    for (double& w : weights)
        w /= sum;
    return weights;
}

/**
 * Filters each plane with the separable window, keeping only positions where the window lies wholly
 * inside: rows first (width shrinks to outWidth), then columns.
 */
std::vector<std::vector<double>> filterValid(const std::vector<const std::vector<double>*>& planes, int width,
    int height, const std::vector<double>& weights)
{
    const int size = int(weights.size());
    const int outWidth = width - size + 1;
    const int outHeight = height - size + 1;
    std::vector<std::vector<double>> result;
    result.reserve(planes.size());
    std::vector<double> rows(std::size_t(height) * std::size_t(outWidth));
    for (const std::vector<double>* plane : planes) {
        for (int y = 0; y < height; ++y) {
            const double* in = plane->data() + std::size_t(y) * std::size_t(width);
            double* out = rows.data() + std::size_t(y) * std::size_t(outWidth);
            for (int x = 0; x < outWidth; ++x) {
                double sum = 0.0;
                for (int i = 0; i < size; ++i)
                    sum += weights[std::size_t(i)] * in[x + i];
                out[x] = sum;
            }
        }
        std::vector<double> filtered(std::size_t(outHeight) * std::size_t(outWidth), 0.0);
        for (int y = 0; y < outHeight; ++y) {
            double* out = filtered.data() + std::size_t(y) * std::size_t(outWidth);
            for (int j = 0; j < size; ++j) {
                const double* in = rows.data() + std::size_t(y + j) * std::size_t(outWidth);
                const double w = weights[std::size_t(j)];
                for (int x = 0; x < outWidth; ++x)
                    out[x] += w * in[x];
            }
        }
        result.push_back(std::move(filtered));
    }
    return result;
}

SsimField computeSsim(
    const render::RadianceImage& image, const render::RadianceImage& reference, float exposure)
{
    requireComparable(image, reference);
    if (!(exposure > 0.0f) || !std::isfinite(exposure))
        throw std::invalid_argument(
            "SSIM exposure must be positive and finite, got " + std::to_string(exposure));

    const ToneMapper toneMapper(exposure, ToneMapper::Curve::Filmic);
    const std::vector<double> x = displayLuma(image, toneMapper);
    const std::vector<double> y = displayLuma(reference, toneMapper);
    std::vector<double> xy(x.size());
    std::vector<double> diffSquared(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
        xy[i] = x[i] * y[i];
        diffSquared[i] = (x[i] - y[i]) * (x[i] - y[i]);
    }

    const int size = ImageMetrics::ssimWindowSize(image.width, image.height);
    const std::vector<std::vector<double>> filtered = filterValid({ &x, &y, &xy, &diffSquared }, image.width,
        image.height, gaussianWeights(size, ImageMetrics::kSsimSigma));
    const std::vector<double>& meanX = filtered[0];
    const std::vector<double>& meanY = filtered[1];
    const std::vector<double>& meanXy = filtered[2];
    const std::vector<double>& meanDiffSquared = filtered[3];

    constexpr double kC1 = (0.01 * 1.0) * (0.01 * 1.0); // (K1 L)^2 with L = 1: display values span [0, 1]
    constexpr double kC2 = (0.03 * 1.0) * (0.03 * 1.0); // (K2 L)^2
    SsimField field;
    field.width = image.width - size + 1;
    field.height = image.height - size + 1;
    field.values.resize(meanX.size());
    for (std::size_t i = 0; i < meanX.size(); ++i) {
        // The denominators use the identities mu_x^2 + mu_y^2 = (mu_x - mu_y)^2 + 2 mu_x mu_y and
        // var_x + var_y = var(x - y) + 2 cov(x, y) rather than Wang's literal terms. Mathematically the
        // same, but with identical inputs the difference terms are exactly 0, so each ratio is exactly
        // 1 and the result is exactly symmetric whether or not the compiler fuses multiply-adds; the
        // variance of the difference also avoids cancelling two large near-equal variances.
        const double muProduct2 = 2.0 * meanX[i] * meanY[i];
        const double muDiff = meanX[i] - meanY[i];
        const double covariance2 = 2.0 * (meanXy[i] - meanX[i] * meanY[i]);
        const double diffVariance = meanDiffSquared[i] - muDiff * muDiff;
        const double luminance = (muProduct2 + kC1) / (muDiff * muDiff + muProduct2 + kC1);
        const double contrastStructure = (covariance2 + kC2) / (diffVariance + covariance2 + kC2);
        field.values[i] = luminance * contrastStructure;
    }
    return field;
}

} // namespace

double ImageMetrics::relativeMse(
    const render::RadianceImage& image, const render::RadianceImage& reference, double epsilon)
{
    return meanOverChannels(image, reference, [epsilon](double a, double b) {
        const double d = a - b;
        return d * d / (b * b + epsilon);
    });
}

double ImageMetrics::mse(const render::RadianceImage& image, const render::RadianceImage& reference)
{
    return meanOverChannels(image, reference, [](double a, double b) { return (a - b) * (a - b); });
}

double ImageMetrics::rmse(const render::RadianceImage& image, const render::RadianceImage& reference)
{
    return std::sqrt(mse(image, reference));
}

double ImageMetrics::psnr(
    const render::RadianceImage& image, const render::RadianceImage& reference, double peak)
{
    if (!(peak > 0.0))
        throw std::invalid_argument("PSNR peak must be positive, got " + std::to_string(peak));
    const double error = mse(image, reference);
    if (error == 0.0)
        return std::numeric_limits<double>::infinity();
    return 10.0 * std::log10(peak * peak / error);
}

glm::vec3 ImageMetrics::meanRadiance(const render::RadianceImage& image)
{
    requireValid(image, "image");
    std::array<double, 3> sum {};
    for (const glm::vec3& pixel : image.pixels) {
        for (int c = 0; c < 3; ++c)
            sum[std::size_t(c)] += double(pixel[c]);
    }
    const double n = double(image.pixels.size());
    return glm::vec3(float(sum[0] / n), float(sum[1] / n), float(sum[2] / n));
}

double ImageMetrics::meanLuminance(const render::RadianceImage& image)
{
    requireValid(image, "image");
    double sum = 0.0;
    for (const glm::vec3& pixel : image.pixels)
        sum += 0.2126 * double(pixel.r) + 0.7152 * double(pixel.g) + 0.0722 * double(pixel.b);
    return sum / double(image.pixels.size());
}

std::size_t ImageMetrics::nonFiniteCount(const render::RadianceImage& image)
{
    std::size_t count = 0;
    for (const glm::vec3& pixel : image.pixels) {
        for (int c = 0; c < 3; ++c)
            count += std::isfinite(pixel[c]) ? 0 : 1;
    }
    return count;
}

render::RadianceImage ImageMetrics::downsampleBox(const render::RadianceImage& image, int factor)
{
    requireValid(image, "image");
    if (factor < 1)
        throw std::invalid_argument("downsample factor must be >= 1, got " + std::to_string(factor));
    if (image.width % factor != 0 || image.height % factor != 0)
        throw std::invalid_argument("image size " + sizeText(image)
            + " is not a multiple of the downsample factor " + std::to_string(factor));
    render::RadianceImage out(image.width / factor, image.height / factor);
    const double weight = 1.0 / (double(factor) * double(factor));
    for (int y = 0; y < out.height; ++y) {
        for (int x = 0; x < out.width; ++x) {
            std::array<double, 3> sum {};
            for (int sy = 0; sy < factor; ++sy) {
                for (int sx = 0; sx < factor; ++sx) {
                    const glm::vec3& p = image.at(x * factor + sx, y * factor + sy);
                    for (int c = 0; c < 3; ++c)
                        sum[std::size_t(c)] += double(p[c]);
                }
            }
            out.at(x, y) = glm::vec3(float(sum[0] * weight), float(sum[1] * weight), float(sum[2] * weight));
        }
    }
    return out;
}

int ImageMetrics::ssimWindowSize(int width, int height)
{
    if (width < 1 || height < 1)
        throw std::invalid_argument(
            "SSIM needs a non-empty image, got " + std::to_string(width) + "x" + std::to_string(height));
    // Odd so the window has a centre pixel, as in the reference implementation.
    const int fits = std::min({ kSsimWindow, width, height });
    return fits % 2 == 1 ? fits : fits - 1;
}

double ImageMetrics::ssim(
    const render::RadianceImage& image, const render::RadianceImage& reference, float exposure)
{
    const SsimField field = computeSsim(image, reference, exposure);
    double sum = 0.0;
    for (double value : field.values)
        sum += value;
    return sum / double(field.values.size());
}

render::RadianceImage ImageMetrics::ssimMap(
    const render::RadianceImage& image, const render::RadianceImage& reference, float exposure)
{
    const SsimField field = computeSsim(image, reference, exposure);
    render::RadianceImage out(field.width, field.height);
    for (std::size_t i = 0; i < field.values.size(); ++i)
        out.pixels[i] = glm::vec3(float(field.values[i]));
    return out;
}

render::RadianceImage ImageMetrics::errorHeatmap(const render::RadianceImage& image,
    const render::RadianceImage& reference, double fullScale, double epsilon)
{
    requireComparable(image, reference);
    if (!(fullScale > 0.0))
        throw std::invalid_argument("heatmap full scale must be positive, got " + std::to_string(fullScale));
    render::RadianceImage out(image.width, image.height);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        double sum = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double a = image.pixels[i][c];
            const double b = reference.pixels[i][c];
            sum += (a - b) * (a - b) / (b * b + epsilon);
        }
        out.pixels[i] = ramp(std::sqrt(sum / 3.0) / fullScale);
    }
    return out;
}

} // namespace vct::io
