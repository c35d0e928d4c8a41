// vtkFXAVSMCurves: a casting light's visibility at a view-space
// position, from vtkFXAVSMPass's curves (or, with FX_EXACT, its lists).
// Shared by the look-up pass (opaque receivers) and VTK's translucent
// shaders (translucent receivers). Each of the FX_LIGHTS casting lights
// has one view (directional, spot) or six (a cube around a point light)
// among the FX_VIEWS squares of the atlas; the view that sees the position
// takes it to its clip space (fxViewToLight), and its depth there, less a
// bias, is looked up in the texel's curve:
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
// the curves, as the AVSM demo's AVSMBilinearSample). Outside a single
// view's map the light is unshadowed; a cube face's taps stay on the face.
// The shadow darkens the light by its ShadowAttenuation (VTK's).
//VTK::FXAVSMLightDepth::Dec
uniform mat4 fxViewToLight[FX_VIEWS];
uniform vec2 fxViewNearFar[FX_VIEWS];
uniform int fxViewPerspective[FX_VIEWS];
uniform vec2 fxViewSliceRange[FX_VIEWS]; // FX_SLICES
uniform vec2 fxViewOrigin[FX_VIEWS];     // its corner's atlas texel
uniform int fxViewSize;                  // texels per side of a view
uniform int fxLightFirstView[FX_LIGHTS];
uniform int fxLightViewCount[FX_LIGHTS];
uniform float fxLightAttenuation[FX_LIGHTS];
uniform float fxViewBias[FX_VIEWS]; // light depth (0..1, vtkFXAVSMLightDepth)
#if !FX_EXACT
//VTK::FXAVSMLookup::Samplers
#endif

// At atlas texel `texel`, of a view whose casters span `sliceRange`.
float fxOpticalDepth(ivec2 texel, float depth, vec2 sliceRange)
{
#if FX_EXACT
  float sum = 0.0;
  uint node = fxAVSMHeads[texel.y * fxAVSMAtlas.x + texel.x];
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
  float x = (depth - sliceRange.x) / max(sliceRange.y - sliceRange.x, 1e-30) * float(FX_SLICES);
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
  // The last node before the receiver decides; its segment to the next
  // node is interpolated (unused nodes lie at 3e38: their segment gives
  // the last node's value). Strictly before: a surface (a step, two nodes
  // at one depth) exactly at the receiver's depth does not shadow it, as
  // in the exact mode (fxSegmentShare). Constant indices only.
  float opticalDepth = 0.0;
  for (int j = 0; j + 1 < FX_NODES; ++j)
  {
    if (z[j] < depth)
    {
      float span = z[j + 1] - z[j];
      float f = span > 0.0 ? clamp((depth - z[j]) / span, 0.0, 1.0) : 1.0;
      opticalDepth = mix(tau[j], tau[j + 1], f);
    }
  }
  return z[FX_NODES - 1] < depth ? tau[FX_NODES - 1] : opticalDepth;
#endif
}

// At texel `local` of view `view` (outside it: unshadowed, or with
// `onView`, the nearest texel on it).
float fxTransmittance(int view, ivec2 local, float depth, bool onView)
{
  if (onView)
  {
    local = clamp(local, ivec2(0), ivec2(fxViewSize - 1));
  }
  else if (any(lessThan(local, ivec2(0))) || any(greaterThanEqual(local, ivec2(fxViewSize))))
  {
    return 1.0;
  }
  return exp(-fxOpticalDepth(local + ivec2(fxViewOrigin[view]), depth, fxViewSliceRange[view]));
}

// Transmittance of the light's path to view-space position `positionVC`
// in one of its views.
float fxViewTransmittance(int view, vec3 positionVC, bool onView)
{
  vec4 light = fxViewToLight[view] * vec4(positionVC, 1.0);
  vec2 uv = (0.5 * light.xy / light.w + 0.5) * float(fxViewSize);
  float depth =
    fxLightDepthFromClip(light, fxViewPerspective[view], fxViewNearFar[view]) - fxViewBias[view];
#if FX_BILINEAR
  vec2 corner = uv - 0.5;
  ivec2 base = ivec2(floor(corner));
  vec2 f = corner - vec2(base);
  return mix(mix(fxTransmittance(view, base, depth, onView),
               fxTransmittance(view, base + ivec2(1, 0), depth, onView), f.x),
    mix(fxTransmittance(view, base + ivec2(0, 1), depth, onView),
      fxTransmittance(view, base + ivec2(1, 1), depth, onView), f.x),
    f.y);
#else
  return fxTransmittance(view, ivec2(floor(uv)), depth, onView);
#endif
}

// A translucent receiver casts too: its own surface is in the curves at
// its depth, and where it is tilted to the light a texel's footprint on it
// spans depths in front of the receiver, which would shadow it in stripes
// (acne). Moved along its normal, towards the light, by 1.5 of the view's
// texels at that point (normal-offset shadows, Holbert 2010), the look-up
// leaves its own footprint. `normalVC` 0: not moved.
vec3 fxNormalOffset(int view, vec3 positionVC, vec3 normalVC)
{
  mat4 m = fxViewToLight[view];
  vec4 clip = m * vec4(positionVC, 1.0);
  // A texel is 2 / size in NDC: 2 w / (|d clip.x / d p| size) in view units.
  vec3 row0 = vec3(m[0][0], m[1][0], m[2][0]);
  float texel = 2.0 * abs(clip.w) / (max(length(row0), 1e-30) * float(fxViewSize));
  // The direction of growing light depth: clip w (perspective) or z.
  vec3 away = fxViewPerspective[view] != 0 ? vec3(m[0][3], m[1][3], m[2][3])
                                           : vec3(m[0][2], m[1][2], m[2][2]);
  vec3 towardLight = dot(normalVC, away) > 0.0 ? -normalVC : normalVC;
  return positionVC + (1.5 * texel) * towardLight;
}

// Casting light `light`'s visibility at view-space position `positionVC`:
// the transmittance in the view that sees the position (of a cube's six,
// the first whose frustum holds it; a single view, any position in front
// of it), darkened by the light's ShadowAttenuation. The face is chosen
// first and the curves are read once, outside any loop; with one view in
// all, every index is a constant (llvmpipe is several times slower with
// the look-up inside a loop over dynamically indexed views).
float fxLightTransmittance(int light, vec3 positionVC, vec3 normalVC)
{
  int view = FX_VIEWS == 1 ? 0 : fxLightFirstView[light];
  int count = FX_VIEWS == 1 ? 1 : fxLightViewCount[light];
  if (count > 1)
  {
    int first = view;
    for (int k = 5; k >= 0; --k)
    {
      int face = min(first + k, FX_VIEWS - 1);
      vec4 clip = fxViewToLight[face] * vec4(positionVC, 1.0);
      if (k < count && clip.w > 0.0 && all(lessThanEqual(abs(clip.xy), vec2(clip.w))))
      {
        view = face;
      }
    }
  }
  if (!((fxViewToLight[view] * vec4(positionVC, 1.0)).w > 0.0))
  {
    return 1.0; // behind the light
  }
  if (dot(normalVC, normalVC) > 0.0)
  {
    positionVC = fxNormalOffset(view, positionVC, normalVC);
  }
  float transmittance = clamp(fxViewTransmittance(view, positionVC, count > 1), 0.0, 1.0);
  float attenuation = FX_LIGHTS == 1 ? fxLightAttenuation[0] : fxLightAttenuation[light];
  return 1.0 - attenuation * (1.0 - transmittance);
}
