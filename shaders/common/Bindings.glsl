// Texture units shared by several passes' shaders, and the light limits, defined once for GLSL and C++
// (core/GpuScene.h, core/LightUniforms.h and passes/ include this file), so a unit cannot drift between the
// shader that samples it and the code that binds it.
#ifndef BINDINGS_GLSL
#define BINDINGS_GLSL

#define MATERIAL_TABLE_UNIT 3 // the material table of the passes that read the g-buffer
#define POINT_SHADOW_UNIT 8 // shadow maps with depth comparison (common/Lights.glsl)
#define DIRECTIONAL_SHADOW_UNIT 9
#define AREA_LIGHT_UNIT 11 // the area-light table (common/AreaLights.glsl)
#define IRRADIANCE_UNIT 12 // irradiance cells (common/IrradianceLookup.glsl): front,
#define CELL_NORMAL_UNIT 13 // their normals and sides,
#define IRRADIANCE_BACK_UNIT 14 // and back faces
#define OPACITY_UNIT 15 // the opacity volume the area lights' shadow cones trace
#define POINT_DEPTH_UNIT 16 // the same shadow maps as raw depth (soft shadows' blocker search)
#define DIRECTIONAL_DEPTH_UNIT 17
#define PHONG_LTC_UNIT 18 // the glossy lobe's fits for area lights (common/AreaLights.glsl)
#define PHONG_LTC_ALBEDO_UNIT 19
#define CLIP_RADIANCE_UNIT 20 // a clipmap's coarser levels (common/ConeTracing.glsl), up to MAX_CLIP_LEVELS - 1 each
#define CLIP_TOWARDS_UNIT 26
#define MAX_CLIP_LEVELS 6
#define BRICK_TABLE_UNIT 31 // a sparse grid's brick table (common/VoxelBricks.glsl), bound once a frame
#define ENCLOSURE_UNIT 32 // where the grid around the scene is closed in (common/ConeTracing.glsl)
#define CLIP_BAND_VOXELS 4 // a cone starting this near a clip level's moving faces blends with the next level's

#define MAX_POINT_LIGHTS 8 // lights beyond these are ignored, and reported by the renderer
#define MAX_DIRECTIONAL_LIGHTS 4

#endif
