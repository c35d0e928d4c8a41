//VTK::System::Dec
// vtkFXToonEdgeMaskFS: which pixels the edges pass (vtkFXToonEdgesFS) can
// mark, as a depth image: 0 where the pixel, its right neighbour or the
// one above holds a surface (linear depth above 0), 1 elsewhere. Two
// background pixels are never separated, so a pixel whose three are all
// background has no mark. The edges pass draws at the far plane with the
// depth test GL_GREATER against this image, which rejects those pixels
// before its fragment shader runs: a software rasteriser (llvmpipe)
// skips whole 4x4 blocks that fail, where a branch inside the shader
// saves nothing.

in vec2 texCoord;

uniform sampler2D fxLinearDepth;
uniform ivec2 fxGBufferSize;

void main()
{
  if (texCoord.x < -1.0)
  {
    discard; // never: texCoord is read so that the quad's attribute stays bound
  }
  ivec2 texel = ivec2(gl_FragCoord.xy);
#if FX_GATHER
  // (the edges pass's 2x2 block: here (w), right (z), above (x))
  vec4 depths = textureGather(fxLinearDepth, vec2(texel + 1) / vec2(fxGBufferSize), 0);
#else
  ivec2 last = fxGBufferSize - 1;
  vec4 depths = vec4(texelFetch(fxLinearDepth, min(texel + ivec2(0, 1), last), 0).r, 0.0,
    texelFetch(fxLinearDepth, min(texel + ivec2(1, 0), last), 0).r,
    texelFetch(fxLinearDepth, texel, 0).r);
#endif
  // (NaN depth is background, as in the edges pass)
  bool surface = depths.w > 0.0 || depths.z > 0.0 || depths.x > 0.0;
  gl_FragDepth = surface ? 0.0 : 1.0;
}
