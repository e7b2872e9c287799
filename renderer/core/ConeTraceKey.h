#pragma once

#include <cstdint>
#include <vector>

namespace vct::render {

struct FrameContext;

/**
 * Every setting ConeTracingSetup hands common/ConeTracing.glsl, so that a pass whose result comes from cones
 * (the irradiance cache, the bounce iteration) keys its reuse on exactly what it traces with.
 */
struct ConeTraceKey {
    bool anisotropic = false;
    int cones = 0;
    int resolution = 0;
    float apertureDeg = 0.0f;
    float step = 0.0f;
    bool dropBackFaces = false;
    float maxDistance = 0.0f;
    float coneOffset = 0.0f;
    std::uint64_t enclosure = 0; ///< the enclosed-space map's version, 0 when gathers do not use one
    /// A clipmap's coarser levels, which the cones go on into: their radiance and bounced versions, so that
    /// what a finer level gathered is redone when their light changes.
    std::vector<std::uint64_t> coarserLight;

    static ConeTraceKey of(const FrameContext& frame);
    bool operator==(const ConeTraceKey& other) const = default;
};

} // namespace vct::render
