// The layout of the six direction-dependent mip chains, which share one 3D texture as tiles stacked along z
// (+x, -x, +y, -y, +z, -z; gl::Texture::create3DStack, VoxelVolume::directional). Included by the shaders that
// write and read them and by C++, so both sides agree.
//
// Between two tiles lies an empty gap half a tile deep, never written: a trilinear lookup up to one texel past
// a tile's end reads zeros, as the border of a texture of its own would give. The levels halve tiles and gaps
// alike, so the chains stop at tiles two texels wide, where the gap is still one texel (a cone wanting a
// coarser level reads that one: the lookup's level is clamped). Half a tile rather than a whole one: the gaps
// cost 2.5 tiles of memory instead of 5 (docs/DESIGN.md, "Lean voxels").
#ifndef DIRECTIONAL_STACK_GLSL
#define DIRECTIONAL_STACK_GLSL

#define STACK_TILES 6
// Tile k starts at z = k * STACK_STRIDE_HALVES / 2 tiles: a tile and the gap after it.
#define STACK_STRIDE_HALVES 3
// The stack's depth in half tiles: six tiles and five gaps.
#define STACK_DEPTH_HALVES 17

#endif
