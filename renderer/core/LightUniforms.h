#pragma once

#include "core/FrameResources.h"
#include "gl/Program.h"
#include "scene/Scene.h"

// The GLSL file is the single definition of the shared texture units and light limits.
#include "common/Bindings.glsl"

namespace vct::render {

/** Lights beyond these counts are ignored (and reported by the renderer). */
constexpr int kMaxPointLights = MAX_POINT_LIGHTS;
constexpr int kMaxDirectionalLights = MAX_DIRECTIONAL_LIGHTS;
/// Where shaders/common/Lights.glsl reads the shadow maps with depth comparison, and as raw depth.
constexpr GLuint kPointShadowUnit = POINT_SHADOW_UNIT;
constexpr GLuint kDirectionalShadowUnit = DIRECTIONAL_SHADOW_UNIT;
constexpr GLuint kPointDepthUnit = POINT_DEPTH_UNIT;
constexpr GLuint kDirectionalDepthUnit = DIRECTIONAL_DEPTH_UNIT;
/// The irradiance cells common/IrradianceLookup.glsl reads (the cache's, or the bounce iteration's).
constexpr GLuint kIrradianceUnit = IRRADIANCE_UNIT;
constexpr GLuint kCellNormalUnit = CELL_NORMAL_UNIT;
constexpr GLuint kIrradianceBackUnit = IRRADIANCE_BACK_UNIT;

/**
 * Whether a shadow-casting light within the limits has a size (a point light's radius, a directional light's
 * angular diameter): the shaders that include common/Lights.glsl then need the SOFT_SHADOWS variant.
 */
bool softShadowsUsed(const Scene& scene);
/** Sets the uniforms and binds the shadow maps that shaders/common/Lights.glsl reads. */
void applyLightUniforms(const gl::Program& program, const Scene& scene, const ShadowMaps& shadows);

struct FrameContext;
/**
 * Sets the uniforms and binds the table and the opacity volume that shaders/common/AreaLights.glsl reads
 * (the opacity volume must have been built this frame: InjectLightPass), and in a clipmap the coarser
 * levels' opacity, which shadow cones go on into.
 */
void applyAreaLightUniforms(const gl::Program& program, const FrameContext& frame);
/** The defines of a shader that traces area-light shadow cones (SHADOW_CLIP_LEVELS in a clipmap). */
void addAreaShadowDefines(std::vector<std::string>& defines, const FrameContext& frame);

} // namespace vct::render
