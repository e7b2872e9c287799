#include "ImageMetrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

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
