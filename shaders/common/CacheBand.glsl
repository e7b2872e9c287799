// In a clipmap the irradiance cache's cells are the finest level's (passes/VoxelIrradiancePass). A surface
// within the cones' blend band of that level's moving faces (common/ConeTracing.glsl, startLevelOf) takes a
// blend of gathers started in two levels, which cells there do not hold (looked up, they read 10-15% darker
// than the pixels' own cones): such a pixel traces its own cones and requests no cell.
#include "common/Bindings.glsl"
#include "common/ClipFaces.glsl"

uniform vec4 uCacheGrid;  // the finest level: corner xyz, side w (metres)
uniform vec4 uCacheScene; // the coarsest level, the grid around the scene
uniform float uCacheBand; // metres; 0 for a dense grid

bool inCacheBand(vec3 p)
{
    return uCacheBand > 0.0 && insideMovingFaces(p, uCacheGrid.xyz, uCacheGrid.w, uCacheScene) < uCacheBand;
}
