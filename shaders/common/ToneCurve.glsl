// The display curve, in one place for GLSL (present/Present.frag, the viewport) and C++ (app/imageio/ToneMapper,
// PNG files), so an exported PNG shows what the viewport showed. Expressions only, valid in both languages:
// the caller clamps and guards against NaN in its own language.
// Narkowicz's fit of the ACES filmic curve (why this one: app/imageio/ToneMapper.cpp), then clamp to [0, 1].
#define TONE_FILMIC(x) (((x) * (2.51f * (x) + 0.03f)) / ((x) * (2.43f * (x) + 0.59f) + 0.14f))
// The sRGB transfer function: linear up to the threshold, a 1/2.4 power above.
#define TONE_SRGB_THRESHOLD 0.0031308f
#define TONE_SRGB_LINEAR(x) (12.92f * (x))
#define TONE_SRGB_POWER_SCALE 1.055f
#define TONE_SRGB_POWER_OFFSET 0.055f
#define TONE_SRGB_EXPONENT (1.0f / 2.4f)
