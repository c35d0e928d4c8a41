//VTK::System::Dec
// vtkFXSurfaceMaskFS: a depth image of the texels, fxStep G-buffer pixels
// apart, that hold a surface: 0 where the G-buffer's linear depth at
// texel x fxStep is above 0 (or NaN: a shader that reads it must still run
// there to write what it writes for it), 1 elsewhere. A pass drawn at the
// far plane with the depth test GL_GREATER against it then leaves the
// other texels out before its fragment shader runs (a software rasteriser
// skips their 4x4 blocks). vtkFXSSAOPass makes it at half resolution,
// where the G-buffer's own depth does not fit.

in vec2 texCoord;

uniform sampler2D fxLinearDepth;
uniform ivec2 fxGBufferSize;
uniform int fxStep;

void main()
{
  if (texCoord.x < -1.0)
  {
    discard; // never: texCoord is read so that the quad's attribute stays bound
  }
  ivec2 texel = min(ivec2(gl_FragCoord.xy) * fxStep, fxGBufferSize - 1);
  float depth = texelFetch(fxLinearDepth, texel, 0).r;
  gl_FragDepth = (depth <= 0.0) ? 1.0 : 0.0;
}
