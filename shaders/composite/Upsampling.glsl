// Joint bilateral upsampling from a grid of traced pixels (one per divisor x divisor block of the screen): the
// four nearest traced pixels, weighted bilinearly and by how well their surface (the tangent plane of the
// full-resolution pixel each was traced from, kept in the grid's guide) matches this pixel's normal and
// passes through this pixel, so light does not bleed across depth or orientation edges.
// Needs uVoxelSize (metres). fromCamera is this pixel's surface point relative to the camera.

struct UpsamplingTaps {
    ivec2 texel[4];
    float weight[4]; // summing to one
};

UpsamplingTaps upsamplingTaps(sampler2D guide, int divisor, ivec2 pixel, vec3 fromCamera, vec3 n)
{
    UpsamplingTaps taps;
    ivec2 gridSize = textureSize(guide, 0);
    vec2 traced = (vec2(pixel) + 0.5) / float(divisor) - 0.5;
    ivec2 base = ivec2(floor(traced));
    vec2 f = traced - vec2(base);
    float weightSum = 0.0;
    float bestSimilarity = -1.0;
    int best = 0;
    float planeScale = 1.0 / max(uVoxelSize, 1e-6); // metres to voxels
    for (int i = 0; i < 4; ++i) {
        ivec2 offset = ivec2(i & 1, i >> 1);
        ivec2 q = clamp(base + offset, ivec2(0), gridSize - 1);
        vec4 plane = texelFetch(guide, q, 0); // a zero normal where no surface was traced
        float bilinear = (offset.x == 1 ? f.x : 1.0 - f.x) * (offset.y == 1 ? f.y : 1.0 - f.y);
        float c = max(dot(plane.xyz, n), 0.0);
        c *= c;
        c *= c; // cos^8 without pow: llvmpipe expands pow to exp2(log2) per lane
        float similarity = c * c * exp(-abs(dot(fromCamera, plane.xyz) - plane.w) * planeScale);
        taps.texel[i] = q;
        taps.weight[i] = (bilinear + 1e-3) * similarity;
        weightSum += taps.weight[i];
        if (similarity > bestSimilarity) {
            bestSimilarity = similarity;
            best = i;
        }
    }
    // No neighbour lies on this surface: take the closest match rather than nothing.
    bool none = !(weightSum > 1e-4);
    for (int i = 0; i < 4; ++i)
        taps.weight[i] = none ? (i == best ? 1.0 : 0.0) : taps.weight[i] / weightSum;
    return taps;
}

vec4 upsampled(sampler2D values, UpsamplingTaps taps)
{
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 4; ++i)
        sum += taps.weight[i] * texelFetch(values, taps.texel[i], 0);
    return sum;
}
