//VTK::System::Dec
// vtkFXBloomDownsampleFS: one step down the bloom's pyramid, after Jimenez,
// "Next Generation Post Processing in Call of Duty: Advanced Warfare"
// (SIGGRAPH 2014 course): 13 bilinear taps of the level above, read as
// five overlapping 2x2-texel boxes (the centre box weighs 1/2, the four
// corner boxes 1/8 each), so the step neither aliases nor shifts.
// FX_FIRST: the first step reads the G-buffer's emission channel at full
// resolution instead (with a threshold, the first step reads the
// full-resolution output of vtkFXBloomPrefilterFS as any level, FX_FIRST
// 0). The emission channel is finite (vtkFXGBufferPass:
// fxFiniteEmission), so no pixel spreads NaN.
// FX_BOX (the first step, from full resolution): only the four inner
// boxes, equally, a 4x4 box filter. There the 13 taps were the bloom's
// largest cost (about 5 of its 12 ms on scene:glow at 1280x720,
// llvmpipe); the box took 2.3 ms off and came out closer to the exact
// glow (vtkfx-bench bloom: RMSE 0.00081 against 0.00091), the next steps'
// 13 taps smoothing what it leaves. With FX_KARIS (firefly
// suppression, first step only)
// each tap is weighted by 1 / (1 + luma) (Karis 2013; see fxAccumulate),
// so one very bright pixel adds about as much as one pixel of value 1,
// not a square of its own value.

in vec2 texCoord;

uniform sampler2D fxSource;    // the level above (not FX_FIRST)
uniform sampler2D fxEmission;  // FX_FIRST
uniform vec2 fxSourceTexel;    // 1 / size of what is read
uniform vec2 fxSourceExtent;   // the image's extent in what is read, in its texels

//VTK::FXBloomMirror::Dec

//VTK::Output::Dec

// This texel covers source texels 2p and 2p + 1 per axis: the corner
// between them, in source texels. (Exactly twice the position, also for an
// odd source size, whose last texel then covers one texel and the mirrored
// copy of it: no stretch, so every source texel weighs the same.)
ivec2 fxCentreCorner()
{
  return 2 * ivec2(gl_FragCoord.xy) + 1;
}

// Tap o: texel offsets from -2 to 2 around the centre corner.
vec3 fxTap(ivec2 o)
{
  vec2 uv = fxSourceTexel * fxMirrorInside(vec2(fxCentreCorner() + o), fxSourceExtent);
#if FX_FIRST
  return texture(fxEmission, uv).rgb;
#else
  return texture(fxSource, uv).rgb;
#endif
}

// Adds tap value v with its share of the kernel; with FX_KARIS (the first
// step, always the 4x4 box) the share is divided by 1 + luma (Karis
// 2013), per tap: each tap is one of the box's four non-overlapping 2x2
// boxes, which is Jimenez's per-box weighting.
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
#if !FX_BOX
  fxAccumulate(fxTap(ivec2(0, 0)), 0.125, sum, weightSum);
  fxAccumulate(fxTap(ivec2(0, 2)), 0.0625, sum, weightSum);
  fxAccumulate(fxTap(ivec2(-2, 0)), 0.0625, sum, weightSum);
  fxAccumulate(fxTap(ivec2(2, 0)), 0.0625, sum, weightSum);
  fxAccumulate(fxTap(ivec2(0, -2)), 0.0625, sum, weightSum);
  fxAccumulate(fxTap(ivec2(-2, 2)), 0.03125, sum, weightSum);
  fxAccumulate(fxTap(ivec2(2, 2)), 0.03125, sum, weightSum);
  fxAccumulate(fxTap(ivec2(-2, -2)), 0.03125, sum, weightSum);
  fxAccumulate(fxTap(ivec2(2, -2)), 0.03125, sum, weightSum);
#endif
  gl_FragData[0] = vec4(sum / weightSum, 1.0);
}
