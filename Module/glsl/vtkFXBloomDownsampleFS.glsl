//VTK::System::Dec
// vtkFXBloomDownsampleFS: one step down the bloom's pyramid, after Jimenez,
// "Next Generation Post Processing in Call of Duty: Advanced Warfare"
// (SIGGRAPH 2014 course): 13 bilinear taps of the level above, read as
// five overlapping 2x2-texel boxes (the centre box weighs 1/2, the four
// corner boxes 1/8 each), so the step neither aliases nor shifts.
// FX_FIRST: the first step reads the sources at full resolution instead:
// the emission channel (FX_EMISSION) and, with FX_THRESHOLD, the lit HDR
// colour's part above a threshold with a quadratic soft knee (the curve of
// Unity's and Unreal's bloom prefilters): for brightness b (largest
// component), threshold t and knee k,
//   weight = max(b - t, min(max(b - t + k, 0), 2k)^2 / (4k)) / b,
// per texel (36 texel reads), before the taps average them.
// Every source texel is finite before any filter averages it: NaN counts
// as 0 and anything above 65504 (the largest half float, +inf included) as
// 65504, so no pixel spreads NaN and none weighs more than it is. The
// emission channel is written so (vtkFXGBufferPass: fxFiniteEmission), and
// the lit colour is made so per texel here. With both sources, the
// threshold applies to the lit colour minus the emission (the light the
// surface reflects; its emission, part of the lit colour too, glows in
// full from the channel: counted once). With FX_KARIS (firefly suppression, first step only)
// each tap is weighted by 1 / (1 + luma) (Karis 2013; see fxAccumulate),
// so one very bright pixel adds about as much as one pixel of value 1,
// not a square of its own value.

in vec2 texCoord;

uniform sampler2D fxSource;    // the level above (not FX_FIRST)
uniform sampler2D fxEmission;  // FX_FIRST && FX_EMISSION
uniform sampler2D fxColor;     // FX_FIRST && FX_THRESHOLD
uniform vec2 fxSourceTexel;    // 1 / size of what is read
uniform float fxThreshold;
uniform float fxKnee;

//VTK::Output::Dec

vec3 fxFinite(vec3 c)
{
  c = mix(c, vec3(0.0), bvec3(isnan(c.x), isnan(c.y), isnan(c.z)));
  return clamp(c, 0.0, 65504.0);
}

// This texel covers source texels 2p and 2p + 1 per axis: the corner
// between them, in source texels. (Exactly twice the position, also for an
// odd source size, whose last texel then covers one texel and the mirrored
// copy of it: no stretch, so every source texel weighs the same.)
ivec2 fxCentreCorner()
{
  return 2 * ivec2(gl_FragCoord.xy) + 1;
}

#if FX_FIRST && FX_THRESHOLD
// The light above the threshold, per texel: thresholding is not linear, so
// it comes before any averaging (a bilinear tap across an edge between 2
// and 0 would read 1 and lose what the 2 had above the threshold).
// (`lit`: finite)
vec3 fxAboveThreshold(vec3 lit)
{
  float brightness = max(lit.r, max(lit.g, lit.b));
  float soft = clamp(brightness - fxThreshold + fxKnee, 0.0, 2.0 * fxKnee);
  soft = soft * soft / (4.0 * fxKnee + 1e-5);
  return lit * (max(brightness - fxThreshold, soft) / max(brightness, 1e-5));
}

// Texel t of a texture of `size` texels, mirrored at the borders as the
// bilinear reads are (GL_MIRRORED_REPEAT).
ivec2 fxMirror(ivec2 t, ivec2 size)
{
  t = ivec2(t.x < 0 ? -t.x - 1 : t.x, t.y < 0 ? -t.y - 1 : t.y);
  t = ivec2(t.x >= size.x ? 2 * size.x - t.x - 1 : t.x, t.y >= size.y ? 2 * size.y - t.y - 1 : t.y);
  return clamp(t, ivec2(0), size - 1);
}

// The 6 x 6 texels under the 13 taps, thresholded once each; tap o (from
// -2 to 2 texels off the centre corner) averages the 2 x 2 from o + 2.
vec3 fxLight[36];
void fxThresholdTexels()
{
  ivec2 size = textureSize(fxColor, 0);
  ivec2 first = fxCentreCorner() - 3;
  for (int y = 0; y < 6; ++y)
  {
    for (int x = 0; x < 6; ++x)
    {
      ivec2 t = fxMirror(first + ivec2(x, y), size);
      vec3 lit = fxFinite(texelFetch(fxColor, t, 0).rgb);
#if FX_EMISSION
      lit = max(lit - texelFetch(fxEmission, t, 0).rgb, 0.0);
#endif
      fxLight[6 * y + x] = fxAboveThreshold(lit);
    }
  }
}
#endif

// Tap o: texel offsets from -2 to 2 around the centre corner.
vec3 fxTap(ivec2 o)
{
  vec2 uv = fxSourceTexel * vec2(fxCentreCorner() + o);
#if FX_FIRST
  vec3 value = vec3(0.0);
#if FX_EMISSION
  value += texture(fxEmission, uv).rgb; // finite per texel: see the top
#endif
#if FX_THRESHOLD
  int i = 6 * (o.y + 2) + o.x + 2;
  value += 0.25 * (fxLight[i] + fxLight[i + 1] + fxLight[i + 6] + fxLight[i + 7]);
#endif
  return value;
#else
  return texture(fxSource, uv).rgb;
#endif
}

// Adds tap value v with its share of the kernel; with FX_KARIS the share
// is divided by 1 + luma (Karis 2013). Jimenez weighs each 2x2 box that
// way; here each tap is, because the five boxes overlap at the centre: a
// lone bright pixel there lies in every box and no box average would
// discount it, but it lies in at most two of the 13 taps.
void fxAccumulate(vec3 v, float share, inout vec3 sum, inout float weightSum)
{
#if FX_KARIS
  share /= 1.0 + dot(v, vec3(0.2126, 0.7152, 0.0722));
#endif
  sum += share * v;
  weightSum += share;
}

void main()
{
  if (texCoord.x < -1.0)
  {
    discard; // never: keeps the quad's texture coordinates in the program
  }
#if FX_FIRST && FX_THRESHOLD
  fxThresholdTexels();
#endif
  // The five boxes' weights per tap: the centre box (1/2) gives its four
  // taps 1/8 each; each corner box (1/8) gives its four 1/32, so the
  // centre tap (in four boxes) gets 1/8, the edge middles 1/16, the
  // corners 1/32.
  vec3 sum = vec3(0.0);
  float weightSum = 0.0;
  fxAccumulate(fxTap(ivec2(-1, 1)), 0.125, sum, weightSum);
  fxAccumulate(fxTap(ivec2(1, 1)), 0.125, sum, weightSum);
  fxAccumulate(fxTap(ivec2(-1, -1)), 0.125, sum, weightSum);
  fxAccumulate(fxTap(ivec2(1, -1)), 0.125, sum, weightSum);
  fxAccumulate(fxTap(ivec2(0, 0)), 0.125, sum, weightSum);
  fxAccumulate(fxTap(ivec2(0, 2)), 0.0625, sum, weightSum);
  fxAccumulate(fxTap(ivec2(-2, 0)), 0.0625, sum, weightSum);
  fxAccumulate(fxTap(ivec2(2, 0)), 0.0625, sum, weightSum);
  fxAccumulate(fxTap(ivec2(0, -2)), 0.0625, sum, weightSum);
  fxAccumulate(fxTap(ivec2(-2, 2)), 0.03125, sum, weightSum);
  fxAccumulate(fxTap(ivec2(2, 2)), 0.03125, sum, weightSum);
  fxAccumulate(fxTap(ivec2(-2, -2)), 0.03125, sum, weightSum);
  fxAccumulate(fxTap(ivec2(2, -2)), 0.03125, sum, weightSum);
  gl_FragData[0] = vec4(sum / weightSum, 1.0);
}
