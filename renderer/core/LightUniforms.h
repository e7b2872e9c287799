#pragma once

#include "core/FrameResources.h"
#include "gl/Program.h"
#include "scene/Scene.h"

namespace vct::render {

/** Lights beyond these counts are ignored (and reported by the renderer); shaders/common/Lights.glsl agrees.
 */
constexpr int kMaxPointLights = 8;
constexpr int kMaxDirectionalLights = 4;
/// Where shaders/common/Lights.glsl reads the shadow maps as raw depth (POINT_DEPTH_UNIT,
/// DIRECTIONAL_DEPTH_UNIT).
constexpr GLuint kPointDepthUnit = 16;
constexpr GLuint kDirectionalDepthUnit = 17;

/** Sets the uniforms and binds the shadow maps that shaders/common/Lights.glsl reads. */
void applyLightUniforms(const gl::Program& program, const Scene& scene, const ShadowMaps& shadows);

struct FrameContext;
/**
 * Sets the uniforms and binds the table and the opacity volume that shaders/common/AreaLights.glsl reads
 * (the opacity volume must have been built this frame: InjectLightPass).
 */
void applyAreaLightUniforms(const gl::Program& program, const FrameContext& frame);

} // namespace vct::render
