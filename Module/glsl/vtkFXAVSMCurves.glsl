// vtkFXAVSMCurves: the light's transmittance at a view-space position,
// from vtkFXAVSMPass's curves (or, with FX_EXACT, its lists). Shared by the
// look-up pass (opaque receivers) and VTK's translucent shaders (translucent
// receivers). The position goes to the light's clip space (fxViewToLight);
// its depth there, less a bias, is looked up in the texel's curve:
// - FX_SLICES 0: the AVSM curve of the resolve (FX_NODES nodes, optical
//   depth linear between them; before the first node 0, past the last its
//   value);
// - FX_SLICES > 0: an opacity shadow map of FX_SLICES slices (for
//   comparison);
// - FX_EXACT 1: the deep shadow map itself, the sum of the optical depths
//   of every segment of the texel's list in front of the receiver (the
//   share in front of it, for a segment it lies in): exact, whatever the
//   order or number of fragments.
// With FX_BILINEAR the four texels around the point are looked up and
// their transmittances blended bilinearly (percentage-closer filtering of
// the curves, as the AVSM demo's AVSMBilinearSample). Outside the map the
// light is unshadowed.
//VTK::FXAVSMLightDepth::Dec
uniform mat4 fxViewToLight;
uniform float fxBias;      // light depth (0..1, vtkFXAVSMLightDepth)
uniform vec2 fxSliceRange; // FX_SLICES
#if !FX_EXACT
//VTK::FXAVSMLookup::Samplers
uniform int fxAVSMSize;
#endif

float fxOpticalDepth(ivec2 texel, float depth)
{
#if FX_EXACT
  float sum = 0.0;
  uint node = fxAVSMHeads[texel.y * fxAVSMSize + texel.x];
  for (int step = 0; step < fxAVSMWalk; ++step)
  {
    if (node != fxAVSMEnd && node < uint(fxAVSMCapacity))
    {
      fxAVSMNode segment = fxAVSMNodes[node];
      sum = min(sum + fxSegmentShare(segment.depth, segment.exitDepth, segment.opticalDepth, depth), 1e4);
      node = segment.next;
    }
  }
  return sum;
#elif FX_SLICES
  // Opacity shadow map: the optical depth accumulated at each slice's far
  // side, linear in between (0 at the near side of the first).
  float c[FX_SLICES];
  //VTK::FXAVSMLookup::SliceFetch
  float x = (depth - fxSliceRange.x) / max(fxSliceRange.y - fxSliceRange.x, 1e-30) * float(FX_SLICES);
  if (!(x > 0.0))
  {
    return 0.0;
  }
  float result = c[FX_SLICES - 1];
  for (int k = 0; k < FX_SLICES; ++k)
  {
    if (x >= float(k) && x < float(k + 1))
    {
      result = mix(k == 0 ? 0.0 : c[k == 0 ? 0 : k - 1], c[k], x - float(k));
    }
  }
  return result;
#else
  float z[FX_NODES];
  float tau[FX_NODES];
  //VTK::FXAVSMLookup::Fetch
  // The last node at or before the receiver decides; its segment to the
  // next node is interpolated (unused nodes lie at 3e38: their segment
  // gives the last node's value). Constant indices only.
  float opticalDepth = 0.0;
  for (int j = 0; j + 1 < FX_NODES; ++j)
  {
    if (z[j] <= depth)
    {
      float span = z[j + 1] - z[j];
      float f = span > 0.0 ? clamp((depth - z[j]) / span, 0.0, 1.0) : 1.0;
      opticalDepth = mix(tau[j], tau[j + 1], f);
    }
  }
  return z[FX_NODES - 1] <= depth ? tau[FX_NODES - 1] : opticalDepth;
#endif
}

float fxTransmittance(ivec2 texel, float depth)
{
  if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, ivec2(fxAVSMSize))))
  {
    return 1.0;
  }
  return exp(-fxOpticalDepth(texel, depth));
}

// Transmittance of the light's path to view-space position `positionVC`.
float fxLightTransmittance(vec3 positionVC)
{
  vec4 light = fxViewToLight * vec4(positionVC, 1.0);
  vec2 uv = (0.5 * light.xy / light.w + 0.5) * float(fxAVSMSize);
  float depth = fxLightDepthFromClip(light) - fxBias;
  float visibility;
#if FX_BILINEAR
  vec2 corner = uv - 0.5;
  ivec2 base = ivec2(floor(corner));
  vec2 f = corner - vec2(base);
  visibility = mix(mix(fxTransmittance(base, depth), fxTransmittance(base + ivec2(1, 0), depth), f.x),
    mix(fxTransmittance(base + ivec2(0, 1), depth), fxTransmittance(base + ivec2(1, 1), depth), f.x),
    f.y);
#else
  visibility = fxTransmittance(ivec2(floor(uv)), depth);
#endif
  return clamp(visibility, 0.0, 1.0);
}
