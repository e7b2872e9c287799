// Stencil bits that sort pixels into the shader variants that shade them (passes/GBufferPass, CompositePass,
// ConeTracePass). llvmpipe runs every instruction of a fragment shader for every pixel, whatever its branches
// say, and even a loop runs its first iteration for all of them; an early stencil test is what skips a 4x4
// block of pixels before its shader starts. Shared with C++ (core/PixelClass.h).
#define PIXEL_GEOMETRY 1u    // a surface was drawn here (0: nothing, the sky)
#define PIXEL_GLOSSY 2u      // its material has a specular lobe
#define PIXEL_EMISSIVE 4u    // its material emits
#define PIXEL_NEEDS_CONES 8u // traced pixels only: no irradiance-cache cell serves it, or there is no cache
