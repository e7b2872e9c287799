#include "reference/RayOffset.h"

#include <bit>
#include <cmath>
#include <cstdint>

namespace vct::render {

glm::vec3 offsetRayOrigin(const glm::vec3& point, const glm::vec3& normal)
{
    // Constants from the paper: near the origin ULPs are tiny, so a fixed step takes over.
    constexpr float kOrigin = 1.0f / 32.0f;
    constexpr float kFloatScale = 1.0f / 65536.0f;
    constexpr float kIntScale = 256.0f;
    glm::vec3 result;
    for (int i = 0; i < 3; ++i) {
        const auto ulps = std::int32_t(kIntScale * normal[i]);
        const auto bits = std::bit_cast<std::int32_t>(point[i]);
        const float stepped = std::bit_cast<float>(bits + (point[i] < 0.0f ? -ulps : ulps));
        result[i] = std::abs(point[i]) < kOrigin ? point[i] + kFloatScale * normal[i] : stepped;
    }
    return result;
}

} // namespace vct::render
