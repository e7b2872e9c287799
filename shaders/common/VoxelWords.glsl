// The voxelizer averages each voxel's material in place, in the 32-bit words the rest of the renderer samples
// (Crassin & Green, "Octree-Based Sparse Voxelization", OpenGL Insights ch. 22): a compare-and-swap loop
// replaces the running mean by mean + (value - mean) / (n + 1). No float-sum atlas is needed, so voxel memory
// holds only what cones and lighting read (docs/DESIGN.md, "Lean voxels").
//   albedo   rgba8:        rgb = mean albedo; a = fragments so far (1..254) while voxelizing, 255 once resolved
//                          (opacity 1 to every sampler).
//   normal   rgba8 snorm:  xyz = mean unit normal (shorter where faces cancel); w = fragments so far while
//                          voxelizing, 0 once resolved.
//   emission r11f_g11f_b10f: mean emitted radiance, the count taken from the albedo word.
// Counts stop at 254: past that, a new fragment still moves the mean by 1/255 of its difference.

// The voxelizer starts from cleared words (passes/VoxelizePass), so a count of 0 means an empty voxel.
const uint kMaxCount = 254u;

uint packAlbedoWord(vec3 albedo, uint count)
{
    return (packUnorm4x8(vec4(albedo, 0.0)) & 0x00FFFFFFu) | (count << 24);
}

uint packNormalWord(vec3 normal, uint count)
{
    return (packSnorm4x8(vec4(normal, 0.0)) & 0x00FFFFFFu) | (count << 24);
}

vec3 unpackNormalWord(uint word)
{
    return unpackSnorm4x8(word).xyz;
}

// GL's R11F_G11F_B10F: unsigned floats with half's five exponent bits and 6 (red, green) or 5 (blue) mantissa
// bits, red in the lowest bits. Built from half floats: the same exponent bias, the mantissa rounded.
uint packR11G11B10F(vec3 v)
{
    v = clamp(v, vec3(0.0), vec3(65000.0)); // rounding up from half's largest value would give infinity
    uint r = packHalf2x16(vec2(v.r, 0.0)) & 0x7FFFu;
    uint g = packHalf2x16(vec2(v.g, 0.0)) & 0x7FFFu;
    uint b = packHalf2x16(vec2(v.b, 0.0)) & 0x7FFFu;
    return ((r + 8u) >> 4) | (((g + 8u) >> 4) << 11) | (((b + 16u) >> 5) << 22);
}

vec3 unpackR11G11B10F(uint word)
{
    return vec3(unpackHalf2x16((word & 0x7FFu) << 4).x, unpackHalf2x16(((word >> 11) & 0x7FFu) << 4).x,
        unpackHalf2x16(((word >> 22) & 0x3FFu) << 5).x);
}
