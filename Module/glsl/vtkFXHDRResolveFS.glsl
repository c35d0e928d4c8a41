//VTK::System::Dec
// vtkFXHDRResolveFS: writes vtkFXHDRTargetPass's float target back into the
// framebuffer it was copied from. NaN becomes 0 and colours are clamped to
// [0, 65504] (alpha to [0, 1]: an effect may mark pixels with larger
// values during the frame, vtkFXBloomPass), so no effect's non-finite
// value reaches the screen; an 8-bit
// framebuffer clamps to [0, 1] itself, and a float one (vtkToneMappingPass
// or a float vtkFramebufferPass around the pipeline) keeps the HDR values
// its tone mapping reads (a clamp to 1 flattened every highlight there).
// FX_WRITE_DEPTH: the depth too (else vtkFXHDRTargetPass blitted it).

in vec2 texCoord;
uniform sampler2D fxColor;
uniform sampler2D fxDepth;

//VTK::Output::Dec

void main()
{
  vec4 c = texture(fxColor, texCoord);
  c = mix(c, vec4(0.0), bvec4(isnan(c.r), isnan(c.g), isnan(c.b), isnan(c.a)));
  gl_FragData[0] = clamp(c, vec4(0.0), vec4(65504.0, 65504.0, 65504.0, 1.0));
#if FX_WRITE_DEPTH
  gl_FragDepth = texture(fxDepth, texCoord).r;
#endif
}
