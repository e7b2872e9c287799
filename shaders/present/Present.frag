// Shows the linear frame on screen: exposure, the Narkowicz ACES fit and the sRGB curve, from the one
// definition the PNG writer uses too (common/ToneCurve.glsl), so the viewport and an exported PNG agree.
#include "common/ToneCurve.glsl"

layout(binding = 0) uniform sampler2D uRadiance;
uniform float uExposure;
uniform vec4 uTarget; // x, y, width, height of the target rectangle in window pixels

layout(location = 0) out vec4 oColor;

vec3 filmic(vec3 x)
{
    return clamp(TONE_FILMIC(x), 0.0, 1.0);
}

vec3 srgbOetf(vec3 c)
{
    return mix(TONE_SRGB_LINEAR(c), TONE_SRGB_POWER_SCALE * pow(c, vec3(TONE_SRGB_EXPONENT)) - TONE_SRGB_POWER_OFFSET,
        step(vec3(TONE_SRGB_THRESHOLD), c));
}

void main()
{
    vec2 uv = (gl_FragCoord.xy - uTarget.xy) / uTarget.zw;
    vec3 radiance = texture(uRadiance, uv).rgb;
    // Non-finite values show as magenta instead of poisoning the filter.
    if (any(isnan(radiance)) || any(isinf(radiance)))
        radiance = vec3(1.0, 0.0, 1.0);
    oColor = vec4(srgbOetf(filmic(max(radiance, 0.0) * uExposure)), 1.0);
}
