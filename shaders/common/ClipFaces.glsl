// Where a point is in a clipmap's level (core/ClipmapLayout), shared by the cones (common/ConeTracing.glsl) and
// the irradiance cache's band (common/CacheBand.glsl) so both draw the same line.
#ifndef CLIP_FACES_GLSL
#define CLIP_FACES_GLSL

// How far p is inside a grid (corner, side) from the faces it can move past: a face on the face of `scene`,
// the coarsest level, the grid around the scene (xyz corner, w side), never moves (the levels stay inside it)
// and has no level beyond it to blend with, so it is as far as can be. Negative outside a face that moves.
float insideMovingFaces(vec3 p, vec3 corner, float side, vec4 scene)
{
    float eps = 1e-4 * scene.w;
    vec3 lo = p - corner, hi = corner + vec3(side) - p;
    lo = mix(lo, vec3(1e30), lessThanEqual(corner, scene.xyz + eps));
    hi = mix(hi, vec3(1e30), greaterThanEqual(corner + vec3(side), scene.xyz + vec3(scene.w) - eps));
    return min(min(min(lo.x, lo.y), lo.z), min(min(hi.x, hi.y), hi.z));
}

#endif
