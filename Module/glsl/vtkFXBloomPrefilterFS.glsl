//VTK::System::Dec
// vtkFXBloomPrefilterFS: what glows, per full-resolution texel, when the
// bloom has a threshold or emission to mask by depth (FX_MASK): the lit
// HDR colour's part above the threshold (FX_THRESHOLD),
// with a quadratic soft knee (the curve of Unity's and Unreal's bloom
// prefilters): for brightness b (largest component), threshold t and
// knee k,
//   weight = max(b - t, min(max(b - t + k, 0), 2k)^2 / (4k)) / b,
// plus the emission channel (FX_EMISSION). Thresholding is not linear, so
// it comes per texel, before any averaging (a bilinear tap across an edge
// between 2 and 0 would read 1 and lose what the 2 had above the
// threshold); the first step down then reads this image with its 13
// bilinear taps like any level, where it used to threshold the 36 texels
// under its taps itself (36 texel reads per half-resolution texel, 9
// times the texels read here).
// Every texel is finite before any filter averages it: NaN counts as 0 and
// anything above 65504 (the largest half float, +inf included) as 65504,
// the sum too, so no pixel spreads NaN and none weighs more than it is.
// With both sources, the threshold applies to the lit colour minus the
// emission (the light the surface reflects; its emission, part of the lit
// colour too, glows in full from the channel: counted once).

in vec2 texCoord;

uniform sampler2D fxColor;    // FX_THRESHOLD: the lit HDR image
uniform sampler2D fxEmission; // FX_EMISSION (finite: vtkFXGBufferPass's fxFiniteEmission)
uniform float fxThreshold;
uniform float fxKnee;         // knee x threshold
// FX_MASK: the G-buffer's window depth and the target's. Where the
// target's is nearer, something drawn in front (an opaque prop drawn
// forward, a lower layer's preserved depth) hides the surface: its
// emission is not seen and does not glow. (1e-7: a 32-bit fixed-point
// depth read as a float and written back may differ by 3e-8.)
uniform sampler2D fxSurfaceDepth;
uniform sampler2D fxTargetDepth;
// FX_COVERAGE: the target's colour, whose alpha over an emitter is
// T fxAlphaMark + f, f in [0, 1] (vtkFXCompositePass::SetMarksTransmittance:
// the composite wrote fxAlphaMark there, and what was drawn over it since
// blended alpha with the factor 1 - a_s on what was there), T the fraction
// of the emitter's light that reaches the image: its emission glows T
// times, as the emitter shows T times.
uniform float fxAlphaMark;
uniform sampler2D fxCoverage;

//VTK::Output::Dec

vec3 fxFinite(vec3 c)
{
  c = mix(c, vec3(0.0), bvec3(isnan(c.x), isnan(c.y), isnan(c.z)));
  return clamp(c, 0.0, 65504.0);
}

// (`lit`: finite)
vec3 fxAboveThreshold(vec3 lit)
{
  float brightness = max(lit.r, max(lit.g, lit.b));
  float soft = clamp(brightness - fxThreshold + fxKnee, 0.0, 2.0 * fxKnee);
  soft = soft * soft / (4.0 * fxKnee + 1e-5);
  return lit * (max(brightness - fxThreshold, soft) / max(brightness, 1e-5));
}

void main()
{
  if (texCoord.x < -1.0)
  {
    discard; // never: keeps the quad's texture coordinates in the program
  }
  ivec2 texel = ivec2(gl_FragCoord.xy);
  vec3 emission = vec3(0.0);
#if FX_EMISSION
  emission = texelFetch(fxEmission, texel, 0).rgb;
#if FX_COVERAGE
  float alpha = texelFetch(fxCoverage, texel, 0).a;
  emission *= isnan(alpha) ? 1.0 : clamp((alpha - 1.0) / (fxAlphaMark - 1.0), 0.0, 1.0);
#endif
#if FX_MASK
  bool hidden =
    texelFetch(fxSurfaceDepth, texel, 0).r > texelFetch(fxTargetDepth, texel, 0).r + 1e-7;
  emission = hidden ? vec3(0.0) : emission;
#endif
#endif
#if FX_THRESHOLD
  vec3 lit = fxFinite(texelFetch(fxColor, texel, 0).rgb);
  vec3 glow = emission + fxAboveThreshold(max(lit - emission, 0.0));
#else
  vec3 glow = emission;
#endif
  gl_FragData[0] = vec4(min(glow, 65504.0), 1.0);
}
