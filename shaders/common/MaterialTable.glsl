// What the g-buffer does not store per pixel: the material's specular lobe and emission, looked up through
// the material index the g-buffer keeps (common/GBufferSurface.glsl: index + 1; 0 = no geometry): two fewer
// render targets, and each costs llvmpipe a fixed share of the g-buffer pass. Filled by core/GpuScene.
// A buffer texture rather than a shader storage buffer: with the storage buffer the composite was slower and
// gave most of the gain back (docs/DESIGN.md, "Measured choices").
#include "common/Bindings.glsl"

struct MaterialEntry {
    vec4 specularShininess; // specular reflectance rgb, Phong exponent (0 = not glossy)
    vec4 emission;          // emitted radiance rgb, W/(m^2 sr), front faces only
};
layout(binding = MATERIAL_TABLE_UNIT) uniform samplerBuffer uMaterialTable; // two rgba32f texels per material

// positionA is surfaceMaterial() at a pixel with geometry (> 0).
MaterialEntry materialAt(float positionA)
{
    int first = 2 * (int(positionA + 0.5) - 1);
    return MaterialEntry(texelFetch(uMaterialTable, first), texelFetch(uMaterialTable, first + 1));
}
