#pragma once

/**
 * The names of the frame's textures in the resource table (core/ResourceTable): what passes declare they read
 * and write, what the memory tables, the NaN check and the inspector show and look up. One spelling each.
 */
namespace vct::render::resource {

// The voxel grid (VoxelVolume).
inline constexpr const char* kAlbedo = "albedo";
inline constexpr const char* kNormal = "normal";
inline constexpr const char* kEmission = "emission";
inline constexpr const char* kRadiance = "radiance";
inline constexpr const char* kOpacity = "opacity";
inline constexpr const char* kRadianceDirectional = "radiance, directional (+x -x +y -y +z -z)";
inline constexpr const char* kBounced = "bounced";
inline constexpr const char* kBouncedDirectional = "bounced, directional (+x -x +y -y +z -z)";
inline constexpr const char* kBounceCells = "bounce cells";
inline constexpr const char* kBounceCellsBack = "bounce cells, back faces";
inline constexpr const char* kBounceCellNormals = "bounce cell normals";
inline constexpr const char* kHigherBounceCells = "higher-bounce cells";
inline constexpr const char* kHigherBounceCellsBack = "higher-bounce cells, back faces";
inline constexpr const char* kHigherBounceCellNormals = "higher-bounce cell normals";
inline constexpr const char* kHigherBounceBase = "higher-bounce cells, first-bounce light";
inline constexpr const char* kHigherBounceBaseBack = "higher-bounce cells, first-bounce light, back faces";
inline constexpr const char* kHigherBounceChange = "higher-bounce cells, last change";
inline constexpr const char* kHigherBounceChangeBack = "higher-bounce cells, last change, back faces";
// Each higher-bounce cell's sums of its surface voxels, added up by the bounce cells' first gather.
inline constexpr const char* kHigherBounceCellSums = "higher-bounce cells, surface sums";
inline constexpr const char* kBrickTable = "brick table"; // a sparse grid's (common/VoxelBricks.glsl)
inline constexpr const char* kEnclosure = "enclosed space"; // around the scene (core/EnclosedSpace)
inline constexpr const char* kIrradiance = "irradiance cache";
inline constexpr const char* kIrradianceBack = "irradiance cache, back faces";
inline constexpr const char* kIrradianceNormals = "irradiance cell normals";
inline constexpr const char* kIrradianceRequested = "irradiance cells gathered";
inline constexpr const char* kInspectionMips = "box levels for inspection";
// The cells above the occupied voxels each mip builder lists (VoxelMipBuilder), one bit per level.
inline constexpr const char* kMipCellMarks = "cell marks, first-bounce levels";
inline constexpr const char* kBounceCellMarks = "cell marks, bounced levels";
inline constexpr const char* kInspectionCellMarks = "cell marks, inspection levels";

// Shadow maps (ShadowMaps, and the shadow pass's copies of the static casters).
inline constexpr const char* kPointShadows = "point shadow maps";
inline constexpr const char* kDirectionalShadows = "directional shadow maps";
inline constexpr const char* kStaticPointShadows = "point shadow maps, static casters";
inline constexpr const char* kStaticDirectionalShadows = "directional shadow maps, static casters";

// Per pixel (ScreenTargets).
inline constexpr const char* kSurface = "surface";
inline constexpr const char* kDepth = "depth and pixel classes";
inline constexpr const char* kIndirectDiffuse = "indirect diffuse";
inline constexpr const char* kIndirectGuide = "indirect upsampling guide";
inline constexpr const char* kIndirectStencil = "indirect pixel classes";
inline constexpr const char* kSpecular = "specular";
inline constexpr const char* kSpecularGuide = "specular upsampling guide";
inline constexpr const char* kSpecularStencil = "specular pixel classes";
inline constexpr const char* kAreaShadow = "area-light shadows";
inline constexpr const char* kAreaShadowGuide = "area-light shadow guide";
inline constexpr const char* kAreaShadowStencil = "area-light pixel classes";
inline constexpr const char* kFinal = "final";

// Constant tables a pass uploads once.
inline constexpr const char* kPhongLtc = "glossy lobe fits (area lights)";
inline constexpr const char* kPhongLtcAlbedo = "glossy lobe albedo (area lights)";

// A pass's own working state.
inline constexpr const char* kBounceSums = "bounce change sums";

} // namespace vct::render::resource
