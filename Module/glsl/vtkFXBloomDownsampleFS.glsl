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
//   weight = max(b - t, min(max(b - t + k, 0), 2k)^2 / (4k)) / b.
// Every source value is made finite first: NaN counts as 0 and anything
// above 65504 (the largest half float, +inf included) as 65504, so no
// pixel spreads NaN. With FX_KARIS (firefly suppression, first step only)
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

vec3 fxTap(vec2 uv)
{
#if FX_FIRST
  vec3 value = vec3(0.0);
#if FX_EMISSION
  value += fxFinite(texture(fxEmission, uv).rgb);
#endif
#if FX_THRESHOLD
  vec3 lit = fxFinite(texture(fxColor, uv).rgb);
  float brightness = max(lit.r, max(lit.g, lit.b));
  float soft = clamp(brightness - fxThreshold + fxKnee, 0.0, 2.0 * fxKnee);
  soft = soft * soft / (4.0 * fxKnee + 1e-5);
  value += lit * (max(brightness - fxThreshold, soft) / max(brightness, 1e-5));
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
  vec2 uv = texCoord;
  vec2 t = fxSourceTexel;
  // The five boxes' weights per tap: the centre box (1/2) gives its four
  // taps 1/8 each; each corner box (1/8) gives its four 1/32, so the
  // centre tap (in four boxes) gets 1/8, the edge middles 1/16, the
  // corners 1/32.
  vec3 sum = vec3(0.0);
  float weightSum = 0.0;
  fxAccumulate(fxTap(uv + t * vec2(-1.0, 1.0)), 0.125, sum, weightSum);
  fxAccumulate(fxTap(uv + t * vec2(1.0, 1.0)), 0.125, sum, weightSum);
  fxAccumulate(fxTap(uv + t * vec2(-1.0, -1.0)), 0.125, sum, weightSum);
  fxAccumulate(fxTap(uv + t * vec2(1.0, -1.0)), 0.125, sum, weightSum);
  fxAccumulate(fxTap(uv), 0.125, sum, weightSum);
  fxAccumulate(fxTap(uv + t * vec2(0.0, 2.0)), 0.0625, sum, weightSum);
  fxAccumulate(fxTap(uv + t * vec2(-2.0, 0.0)), 0.0625, sum, weightSum);
  fxAccumulate(fxTap(uv + t * vec2(2.0, 0.0)), 0.0625, sum, weightSum);
  fxAccumulate(fxTap(uv + t * vec2(0.0, -2.0)), 0.0625, sum, weightSum);
  fxAccumulate(fxTap(uv + t * vec2(-2.0, 2.0)), 0.03125, sum, weightSum);
  fxAccumulate(fxTap(uv + t * vec2(2.0, 2.0)), 0.03125, sum, weightSum);
  fxAccumulate(fxTap(uv + t * vec2(-2.0, -2.0)), 0.03125, sum, weightSum);
  fxAccumulate(fxTap(uv + t * vec2(2.0, -2.0)), 0.03125, sum, weightSum);
  gl_FragData[0] = vec4(sum / weightSum, 1.0);
}
