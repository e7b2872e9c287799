// The layout of the six direction-dependent mip chains, which share one 3D texture as tiles stacked along z
// (+x, -x, +y, -y, +z, -z; gl::Texture::create3DStack, VoxelVolume::directional), laid out by
// scene/DirectionalStackLayout.h. Between two tiles lies an empty gap, never written: a trilinear lookup up to
// one texel past a tile's end reads zeros, as the border of a texture of its own would give. The levels halve
// tiles and gaps alike, so the chains stop where the gap is one texel (a cone wanting a coarser level reads
// that one: the lookup's level is clamped). The gap is half a tile, a quarter where the stack would be deeper
// than GL allows (512^3); the shaders get the strides as uniforms.
#ifndef DIRECTIONAL_STACK_GLSL
#define DIRECTIONAL_STACK_GLSL

#define STACK_TILES 6

#endif
