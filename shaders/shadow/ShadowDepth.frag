// Depth only. Point and directional maps both keep the rasterised depth: writing gl_FragDepth would switch
// off llvmpipe's early depth test and shade every hidden fragment (ShadowMaps, common/Lights.glsl).
void main()
{
}
