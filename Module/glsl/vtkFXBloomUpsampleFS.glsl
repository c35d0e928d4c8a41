//VTK::System::Dec
// vtkFXBloomUpsampleFS: one step up the bloom's pyramid (Jimenez 2014): a
// 3x3 tent ([1 2 1] x [1 2 1] / 16) of the coarser level, added to this
// level's own share. The tent is read as four bilinear taps half a texel
// off diagonally: at a coarse texel's centre they overlap into exactly the
// [1 2 1] x [1 2 1] weights (4 reads instead of 9); at the fine texels, a
// quarter of a coarse texel off centre, into [1 4 3] / 8 per axis, the
// same smoothing (variance 7/16 of a coarse texel^2), still normalised:
//   up_k = w_k down_k + tent(up_k+1),
// so the full-resolution result is the sum over levels of w_k times level
// k brought up, and with sum w_k = 1 its total equals the source's total
// (energy kept: each normalised filter moves light, never adds any).
// FX_FINAL: the last step, to full resolution, scaled by the intensity and
// added onto the image by blending (no own share; its alpha, the glow's
// largest component up to 1, composited over the image's), with one bilinear read
// instead of the tent: at full resolution the glow is already smooth, and
// the three reads saved were a fifth of the bloom's time (vtkfx-bench bloom:
// RMSE against the exact glow 0.00091 against 0.00090); the blur it adds, 3/16
// of a coarse texel^2 instead of 7/16, is in GetLevelSigma.

in vec2 texCoord;

uniform sampler2D fxCoarse;   // up_k+1 (or the last down level)
uniform sampler2D fxLevel;    // down_k (not FX_FINAL)
uniform vec2 fxCoarseTexel;   // 1 / size of fxCoarse
uniform vec2 fxCoarseExtent;  // the image's extent in fxCoarse, in its texels
uniform float fxCoarseScale;  // factor on fxCoarse (w_N when it is the last down level)
uniform float fxShare;        // w_k
uniform float fxIntensity;    // FX_FINAL
uniform ivec2 fxOrigin;       // the target's corner in the framebuffer

//VTK::Output::Dec

//VTK::FXBloomMirror::Dec

// fxCoarse at `at` coarse texels, mirrored at the image's edges.
vec3 fxCoarseAt(vec2 at)
{
  return texture(fxCoarse, fxCoarseTexel * fxMirrorInside(at, fxCoarseExtent)).rgb;
}

void main()
{
  if (texCoord.x < -1.0)
  {
    discard; // never: keeps the quad's texture coordinates in the program
  }
  // This texel's centre at exactly half its position in the coarse level
  // (the inverse of the step down's mapping, also for odd sizes).
  vec2 fine = gl_FragCoord.xy - vec2(fxOrigin);
  vec2 at = 0.5 * fine;
#if FX_FINAL
  // (the glow term at most the largest half float: an intensity of 100 on
  // a source of 65504 gives 6.5e6, which a driver may store as +inf. The
  // sum with what the target holds can still overflow where that is near
  // 65504 itself; the write-back turns +inf into white.)
  vec3 glow = min(fxIntensity * fxCoarseScale * fxCoarseAt(at), vec3(65504.0));
  // Its coverage, blended over the target's alpha as VTK blends a
  // translucent surface's (a + c (1 - a)): over a transparent background
  // the halo keeps its light in an RGBA screenshot; where a is already 1
  // or a transmittance mark (1 or more) it stays 1 or more.
  float coverage = clamp(max(glow.r, max(glow.g, glow.b)), 0.0, 1.0);
  gl_FragData[0] = vec4(glow, coverage);
#else
  vec3 tent = fxCoarseAt(at + vec2(0.5, 0.5)) + fxCoarseAt(at - vec2(0.5, 0.5)) +
    fxCoarseAt(at + vec2(0.5, -0.5)) + fxCoarseAt(at + vec2(-0.5, 0.5));
  tent *= 0.25 * fxCoarseScale;
  gl_FragData[0] = vec4(fxShare * texelFetch(fxLevel, ivec2(fine), 0).rgb + tent, 1.0);
#endif
}
