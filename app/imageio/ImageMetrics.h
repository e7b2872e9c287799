#pragma once

#include "image/RadianceImage.h"

#include <glm/vec3.hpp>

#include <cstddef>

namespace vct::io {

/**
 * Error and summary statistics on linear radiance images. Comparisons take the image under test
 * first and the reference second, and throw std::invalid_argument when the sizes differ or an image
 * is empty or inconsistent (pixels.size() != width * height). Sums are accumulated in double.
 * Non-finite values propagate into the results (NaN in, NaN out): check nonFiniteCount() first.
 */
class ImageMetrics {
public:
    /**
     * Default epsilon of relativeMse, in squared radiance units. Dark reference pixels (the black
     * background, shadowed corners at ~0.02) would otherwise dominate the mean through their tiny
     * denominators; 1e-2 means a pixel below radiance ~0.1 is judged on absolute error while brighter
     * ones are judged relatively. It is the value common in the denoising literature (Rousselle et al.).
     */
    static constexpr double kRelativeMseEpsilon = 1e-2;

    /** Mean over pixels and channels of (a - ref)^2 / (ref^2 + epsilon). */
    static double relativeMse(const render::RadianceImage& image, const render::RadianceImage& reference,
        double epsilon = kRelativeMseEpsilon);
    /** Mean over pixels and channels of (a - ref)^2, in squared radiance. */
    static double mse(const render::RadianceImage& image, const render::RadianceImage& reference);
    /** sqrt(mse), in radiance units. */
    static double rmse(const render::RadianceImage& image, const render::RadianceImage& reference);
    /**
     * 10 log10(peak^2 / mse) in dB on linear radiance; +infinity for identical images. @p peak is the
     * radiance treated as full scale (must be > 0): pick it per scene, e.g. 1 for the lit walls.
     */
    static double psnr(
        const render::RadianceImage& image, const render::RadianceImage& reference, double peak);

    /** Mean radiance per channel. Throws on an empty image. */
    static glm::vec3 meanRadiance(const render::RadianceImage& image);
    /** Mean Rec. 709 luminance, 0.2126 R + 0.7152 G + 0.0722 B. Throws on an empty image. */
    static double meanLuminance(const render::RadianceImage& image);
    /** Number of channel values (not pixels) that are NaN or infinite. */
    static std::size_t nonFiniteCount(const render::RadianceImage& image);

    /**
     * Averages each @p factor x @p factor block into one pixel (box filter), e.g. to compare a 4x
     * supersampled render with a reference. Width and height must be multiples of @p factor (>= 1).
     */
    static render::RadianceImage downsampleBox(const render::RadianceImage& image, int factor);

    /** Side of the SSIM window at full size (Wang et al. 2004). */
    static constexpr int kSsimWindow = 11;
    /** Standard deviation of the SSIM window's Gaussian weights, in pixels. */
    static constexpr double kSsimSigma = 1.5;

    /**
     * Mean structural similarity (Wang, Bovik, Sheikh, Simoncelli 2004) of the tone-mapped images, in
     * [-1, 1], 1 only for identical displays. Both images go through ToneMapper(@p exposure, Filmic) as
     * for PNG output, to sRGB-encoded display values in [0, 1]; SSIM is computed on their Rec. 709 luma
     * Y' = 0.2126 R' + 0.7152 G' + 0.0722 B' (weights applied after the transfer function, unrounded).
     * Window: Gaussian, sigma = kSsimSigma, side ssimWindowSize(); K1 = 0.01, K2 = 0.03, L = 1; the
     * result is the mean of the SSIM map over the window positions that lie wholly inside the image
     * (no padding). Symmetric in its arguments. @p exposure is a linear multiplier (> 0, finite).
     * The tone mapper sends NaN and -inf to black and +inf to white, so the result is always finite:
     * check nonFiniteCount() first. Costs O(width * height * window).
     */
    static double ssim(
        const render::RadianceImage& image, const render::RadianceImage& reference, float exposure = 1.0f);
    /**
     * The SSIM map whose mean ssim() returns, one value per valid window position, written to all three
     * channels. It is smaller than the input by w - 1 in each direction (w = ssimWindowSize()): map
     * pixel (x, y) belongs to the window centred on input pixel (x + (w - 1) / 2, y + (w - 1) / 2).
     * Values may be negative: write it with ToneMapper::Curve::Clamp.
     */
    static render::RadianceImage ssimMap(
        const render::RadianceImage& image, const render::RadianceImage& reference, float exposure = 1.0f);
    /**
     * The SSIM window side for an image of this size: kSsimWindow, or for images narrower or shorter
     * than that the largest odd side that fits (the Gaussian keeps sigma = kSsimSigma, truncated to the
     * smaller window and renormalised). Throws std::invalid_argument unless both sizes are >= 1.
     */
    static int ssimWindowSize(int width, int height);

    /**
     * A picture of where the images differ: each pixel's relative error
     * e = sqrt(mean over channels of (a - ref)^2 / (ref^2 + epsilon)) mapped with t = e / fullScale
     * onto a ramp black (0) -> blue (0.25) -> green (0.5) -> yellow (0.75) -> red (>= 1). Non-finite
     * errors are magenta. Values are in [0, 1]: write it with ToneMapper::Curve::Clamp, not the filmic curve.
     */
    static render::RadianceImage errorHeatmap(const render::RadianceImage& image,
        const render::RadianceImage& reference, double fullScale = 1.0, double epsilon = kRelativeMseEpsilon);
};

} // namespace vct::io
