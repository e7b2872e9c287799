#include "ToneMapper.h"

#include <algorithm>
#include <cmath>

// The GLSL file is the single definition of the display curve (the viewport's present/Present.frag too).
#include "common/ToneCurve.glsl"

namespace vct::io {

// Why Narkowicz's ACES fit rather than Hable (Uncharted 2): it is one rational function with no
// white-point parameter to tune, it reaches exactly 1 at a finite input (x ~ 7.24), so the
// ceiling light (radiance 17, 12, 4) clips to near-white as in common viewers, and it keeps
// more contrast in the mid-tones, where Hable's curve looks washed out without extra grading. It is
// applied per channel in linear sRGB primaries (no ACES colour-space transform), so very bright
// saturated colours shift towards white; for comparing renders the metrics work on linear data anyway.
float ToneMapper::filmic(float x)
{
    if (!(x > 0.0f))
        return 0.0f; // also NaN
    if (std::isinf(x))
        return 1.0f;
    return std::clamp(TONE_FILMIC(x), 0.0f, 1.0f);
}

float ToneMapper::exposureFromEv(float ev)
{
    return std::exp2(ev);
}

float ToneMapper::srgbOetf(float linear)
{
    if (!(linear > 0.0f))
        return 0.0f;
    if (linear >= 1.0f)
        return 1.0f;
    if (linear <= TONE_SRGB_THRESHOLD)
        return TONE_SRGB_LINEAR(linear);
    return TONE_SRGB_POWER_SCALE * std::pow(linear, TONE_SRGB_EXPONENT) - TONE_SRGB_POWER_OFFSET;
}

std::uint8_t ToneMapper::toByte(float encoded)
{
    if (!(encoded > 0.0f))
        return 0;
    return std::uint8_t(std::lround(std::min(encoded, 1.0f) * 255.0f));
}

glm::vec3 ToneMapper::toDisplay(const glm::vec3& radiance) const
{
    glm::vec3 out;
    for (int c = 0; c < 3; ++c) {
        const float exposed = radiance[c] * m_exposure;
        const float mapped = m_curve == Curve::Filmic ? filmic(exposed) : std::clamp(exposed, 0.0f, 1.0f);
        out[c] = srgbOetf(mapped);
    }
    return out;
}

glm::u8vec3 ToneMapper::toRgb8(const glm::vec3& radiance) const
{
    const glm::vec3 display = toDisplay(radiance);
    return glm::u8vec3(toByte(display.r), toByte(display.g), toByte(display.b));
}

std::vector<std::uint8_t> ToneMapper::toRgb8(const render::RadianceImage& image) const
{
    std::vector<std::uint8_t> bytes(image.pixels.size() * 3);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        const glm::u8vec3 rgb = toRgb8(image.pixels[i]);
        bytes[i * 3 + 0] = rgb.r;
        bytes[i * 3 + 1] = rgb.g;
        bytes[i * 3 + 2] = rgb.b;
    }
    return bytes;
}

} // namespace vct::io
