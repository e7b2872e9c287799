#pragma once

#include "image/RadianceImage.h"

#include <glm/ext/vector_uint3_sized.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace vct::io {

/**
 * Turns linear HDR radiance into 8-bit sRGB for display and PNG: multiply by the exposure, apply the
 * curve per channel, then the sRGB OETF. This is the only place tone mapping happens; everything
 * upstream (renderer, PFM, EXR, metrics) stays in linear radiance.
 */
class ToneMapper {
public:
    enum class Curve {
        /** Narkowicz's fit of the ACES filmic curve: highlights roll off smoothly to white. */
        Filmic,
        /** Plain clamp to [0, 1]: for images already in display range (error heatmaps, albedo). */
        Clamp,
    };

    ToneMapper() = default;
    /** @p exposure is a linear multiplier on radiance (1 = unchanged; see exposureFromEv). */
    explicit ToneMapper(float exposure, Curve curve = Curve::Filmic)
        : m_exposure(exposure)
        , m_curve(curve)
    {
    }

    /** The multiplier for an exposure in stops: 2^ev (+1 EV doubles the radiance). */
    static float exposureFromEv(float ev);

    float exposure() const { return m_exposure; }
    void setExposure(float multiplier) { m_exposure = multiplier; }
    /** Sets the exposure in stops; exposure() then returns 2^ev. */
    void setExposureEv(float ev) { m_exposure = exposureFromEv(ev); }
    Curve curve() const { return m_curve; }
    void setCurve(Curve curve) { m_curve = curve; }

    /**
     * Narkowicz 2015 ACES fit, x(2.51x + 0.03) / (x(2.43x + 0.59) + 0.14), clamped to [0, 1]:
     * 0 -> 0, monotonic, reaches 1 at x ~ 7.24. Negative and NaN input give 0, +inf gives 1.
     */
    static float filmic(float x);
    /** sRGB OETF (IEC 61966-2-1 piecewise curve), linear [0, 1] -> encoded [0, 1]; input is clamped. */
    static float srgbOetf(float linear);
    /** An encoded [0, 1] value to a byte, rounding to nearest; NaN gives 0. */
    static std::uint8_t toByte(float encoded);

    /** Exposure, curve and OETF: linear radiance -> encoded sRGB in [0, 1]. */
    glm::vec3 toDisplay(const glm::vec3& radiance) const;
    /** One pixel to 8-bit sRGB. */
    glm::u8vec3 toRgb8(const glm::vec3& radiance) const;
    /**
     * The whole image as tightly packed 8-bit RGB, top row first, width * height * 3 bytes
     * (wrap with QImage(data, w, h, 3 * w, QImage::Format_RGB888)).
     */
    std::vector<std::uint8_t> toRgb8(const render::RadianceImage& image) const;

private:
    float m_exposure = 1.0f;
    Curve m_curve = Curve::Filmic;
};

} // namespace vct::io
