#include "reference/LinearTexture.h"

#include <array>
#include <cmath>

namespace vct::render {

namespace {

float srgbToLinear(float c)
{
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

const std::array<float, 256>& srgbTable()
{
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t {};
        for (int i = 0; i < 256; ++i)
            t[std::size_t(i)] = srgbToLinear(float(i) / 255.0f);
        return t;
    }();
    return table;
}

int wrap(int i, int size)
{
    const int r = i % size;
    return r < 0 ? r + size : r;
}

} // namespace

LinearTexture::LinearTexture(const TextureImage& image)
{
    const std::size_t count
        = std::size_t(image.width > 0 ? image.width : 0) * std::size_t(image.height > 0 ? image.height : 0);
    if (count == 0 || image.rgba.size() < count * 4) {
        m_width = m_height = 1;
        m_texels.assign(1, glm::vec3(1.0f));
        return;
    }
    m_width = image.width;
    m_height = image.height;
    m_texels.resize(count);
    const std::array<float, 256>& table = srgbTable();
    for (std::size_t i = 0; i < count; ++i)
        m_texels[i]
            = { table[image.rgba[4 * i]], table[image.rgba[4 * i + 1]], table[image.rgba[4 * i + 2]] };
}

const glm::vec3& LinearTexture::texel(int x, int y) const
{
    return m_texels[std::size_t(wrap(y, m_height)) * std::size_t(m_width) + std::size_t(wrap(x, m_width))];
}

glm::vec3 LinearTexture::sample(const glm::vec2& uv) const
{
    // Texel centres sit at half-integer coordinates.
    const float x = uv.x * float(m_width) - 0.5f, y = uv.y * float(m_height) - 0.5f;
    if (!std::isfinite(x) || !std::isfinite(y))
        return texel(0, 0);
    const float fx = std::floor(x), fy = std::floor(y);
    const float tx = x - fx, ty = y - fy;
    // Wrap in double first: a huge uv must not overflow the int conversion.
    const int x0 = int(std::fmod(double(fx), double(m_width))),
              y0 = int(std::fmod(double(fy), double(m_height)));
    return (1.0f - ty) * ((1.0f - tx) * texel(x0, y0) + tx * texel(x0 + 1, y0))
        + ty * ((1.0f - tx) * texel(x0, y0 + 1) + tx * texel(x0 + 1, y0 + 1));
}

} // namespace vct::render
