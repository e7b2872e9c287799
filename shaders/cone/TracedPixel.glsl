// The full-resolution pixel a traced (low-resolution) pixel stands for: the centre of the uDivisor x uDivisor
// block it covers. The composite upsamples from these.
uniform int uDivisor;    // one traced pixel stands for uDivisor x uDivisor screen pixels
uniform ivec3 uFullSize; // full-resolution width, height

ivec2 tracedPixel()
{
    return min(ivec2(gl_FragCoord.xy) * uDivisor + uDivisor / 2, uFullSize.xy - 1);
}
