//VTK::System::Dec
// vtkFXAVSMLookupFS: for every G-buffer pixel, each casting light's
// visibility through the translucent casters, from the receiver back to
// the light (vtkFXAVSMCurves.glsl), at the receiver's view-space position
// (linear depth and the frustum ray): channel k for the k-th casting light
// (the target may keep only the first). The background is unshadowed.

in vec2 texCoord;

uniform sampler2D fxLinearDepth;
//VTK::FXViewPosition::Dec
#if FX_EXACT
//VTK::FXAVSMLists::Dec
#endif

//VTK::Output::Dec

//VTK::FXAVSMCurves::Dec

void main()
{
  // Texels through gl_FragCoord; texCoord is read once only (the draw binds
  // it).
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  ivec2 size = textureSize(fxLinearDepth, 0);
  float linearDepth = texelFetch(fxLinearDepth, pixel, 0).r;
  if (texCoord.x < -1.0)
  {
    linearDepth = 0.0; // never
  }
  if (!(linearDepth > 0.0))
  {
    gl_FragData[0] = vec4(1.0);
    return;
  }
  vec2 ndc = 2.0 * (vec2(pixel) + 0.5) / vec2(size) - 1.0;
  vec3 position = fxViewPosition(ndc, linearDepth);
  vec4 visibility = vec4(1.0);
  for (int k = 0; k < FX_LIGHTS; ++k)
  {
    // (opaque receivers do not cast: no offset)
    visibility[k] = fxLightTransmittance(k, position, vec3(0.0));
  }
  gl_FragData[0] = visibility;
}
