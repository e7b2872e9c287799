#pragma once

#include "gl/Program.h"

namespace vct::render {

struct FrameContext;

/**
 * Sets what common/ConeTracing.glsl reads (grid placement, step and distance limits, the diffuse cone set)
 * and binds the volume the cones trace through, so the per-pixel cone pass and the per-voxel bounce gather
 * trace with the same parameters. @p useBounced chooses the second-bounce volume when there is one.
 */
class ConeTracingSetup {
public:
    static void apply(gl::Program& program, const FrameContext& frame, bool anisotropic, bool useBounced);
};

} // namespace vct::render
