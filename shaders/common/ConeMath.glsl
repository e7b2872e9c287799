// Cone-tracing arithmetic shared by GLSL and C++ (renderer/core/ConeMath.h includes this file), so the unit
// tests check the very code the shaders run. Keep to the subset both languages accept.

// Cone footprint at distance t along the axis: d = 2 t tan(theta/2).
float coneDiameter(float t, float tanHalfAperture)
{
    return 2.0f * t * tanHalfAperture;
}

// The mip level whose voxels match the footprint; a footprint below one voxel samples level 0.
float coneMipLevel(float diameter, float voxelSize, float maxLevel)
{
    return clamp(log2(max(diameter, voxelSize) / voxelSize), 0.0f, maxLevel);
}

// Step length d * beta, never below beta voxels so a thin cone still advances.
float coneStepLength(float diameter, float voxelSize, float stepFactor)
{
    return max(diameter, voxelSize) * stepFactor;
}

// Opacity of a sample stored for a voxel of side `sampleSize` when the step covers `stepLength` of it:
// 1 - (1 - a)^(step / size), so halving the step does not double the occlusion.
float correctOpacity(float alpha, float stepLength, float sampleSize)
{
    return 1.0f - pow(clamp(1.0f - alpha, 0.0f, 1.0f), stepLength / sampleSize);
}

// The axis (0 = x, 1 = y, 2 = z) along which a triangle with normal n has the largest projected area.
int dominantAxis(vec3 n)
{
    vec3 a = abs(n);
    if (a.x >= a.y && a.x >= a.z)
        return 0;
    if (a.y >= a.z)
        return 1;
    return 2;
}
