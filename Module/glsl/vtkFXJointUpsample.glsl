// Joint-bilateral upsampling (Kopf, Cohen, Lischinski, Uyttendaele 2007):
// the value at a full-resolution pixel of linear depth d0 is the bilinear
// blend of the 4 nearest low-resolution texels, each weighted also by
// 1 / (1 + (gap / (sigma d0))^2) (d0: fxToleranceDepth of it in parallel
// projection), its depth d's agreement with the depth
// e the pixel's tangent plane (normal n0) has there or with d0, whichever
// is nearer (fxPlaneGap)
// (fxPlaneDepthAt of vtkFXViewPosition.glsl: a crease keeps each side's
// value; relative to the depth: scale-free). With n0 = 0, or a plane that
// does not reach the texel, e = d0. The texels' linear depths are
// component `depthComponent` of `depths`, or, when `depthInValue` (a
// constant at every call, so the branch compiles away), of the values
// themselves, as the occlusion passes write them, saving a fetch per
// texel; with no agreeing texel (a feature thinner than a low-resolution
// texel) the texel closest to that depth wins, and `none` where all four are
// background (open occlusion 1, no bounced light 0). Low-resolution texel i holds the
// value of full-resolution texel i * step of fullSize.
// Used by vtkFXBilateralBlurFS and the occlusion passes' composite code,
// after vtkFXViewPosition.glsl.
#ifndef FX_JOINT_UPSAMPLE // (the composite may receive it from more than one effect)
#define FX_JOINT_UPSAMPLE
// The offset from full-resolution pixel `pixel` to the texel that
// low-resolution texel q (clamped to lowSize) holds.
vec2 fxLowTexelOffset(ivec2 q, ivec2 lowSize, int step, ivec2 fullSize, ivec2 pixel)
{
  return vec2(min(clamp(q, ivec2(0), lowSize - 1) * step, fullSize - 1) - pixel);
}

// The coefficients of fxPlaneDepthAt for a full-resolution pixel.
void fxPixelPlane(vec3 n0, float d0, ivec2 pixel, ivec2 fullSize, out vec3 a, out vec3 b)
{
  fxPlaneDepthRatio(n0, d0, fxTexelNdc(pixel, fullSize), 2.0 / vec2(fullSize), a, b);
}

vec4 fxJointUpsample(sampler2D lowResolution, bool depthInValue, sampler2D depths, int depthComponent,
  ivec2 lowSize, int step, ivec2 pixel, float d0, float depthSigma, vec3 n0, ivec2 fullSize,
  vec4 none)
{
  vec2 x = vec2(pixel) / float(step);
  ivec2 base = ivec2(floor(x));
  vec2 f = x - vec2(base);
  vec3 planeA, planeB;
  fxPixelPlane(n0, d0, pixel, fullSize, planeA, planeB);
  vec4 sum = vec4(0.0);
  float total = 0.0;
  vec4 nearest = none;
  float nearestGap = 1e30;
  for (int j = 0; j < 2; ++j)
  {
    for (int i = 0; i < 2; ++i)
    {
      ivec2 q = clamp(base + ivec2(i, j), ivec2(0), lowSize - 1);
      vec4 v = texelFetch(lowResolution, q, 0);
      float d = depthInValue ? v[depthComponent] : texelFetch(depths, q, 0)[depthComponent];
      float bilinear = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y);
      float e = fxPlaneDepthAt(
        planeA, planeB, fxLowTexelOffset(base + ivec2(i, j), lowSize, step, fullSize, pixel), d0);
      float r = fxPlaneGap(d, e, d0) / max(depthSigma * fxToleranceDepth(d0), 1e-37); // (see vtkFXBilateralBlurFS)
      float w = d > 0.0 ? bilinear / (1.0 + r * r) : 0.0;
      sum += w * v;
      total += w;
      float gap = d > 0.0 ? fxPlaneGap(d, e, d0) : 1e30; // background never stands in
      if (gap < nearestGap)
      {
        nearestGap = gap;
        nearest = v;
      }
    }
  }
  return total > 1e-4 ? sum / total : nearest;
}

#ifdef FX_GATHER // (undefined in the blur: a strict compiler refuses it in #if)
#if FX_GATHER
// The same for one value with its depth in the next component (.r, .g:
// the occlusion passes' output), from two gathers instead of four fetches
// (a software rasteriser pays per fetch; used where textureGather reads
// any component, FX_GATHER). With no agreeing texel, the one closest in
// depth, or 1 (open) where all four are background.
float fxJointUpsampleGathered(sampler2D valueAndDepth, ivec2 lowSize, int step, ivec2 pixel,
  float d0, float depthSigma, vec3 n0, ivec2 fullSize)
{
  vec2 x = vec2(pixel) / float(step);
  ivec2 base = ivec2(floor(x));
  vec2 f = x - vec2(base);
  // The 2x2 block from `base` (clamped to the edge as the fetches are), in
  // textureGather's order: (0, 1), (1, 1), (1, 0), (0, 0).
  vec2 at = vec2(base + 1) / vec2(lowSize);
  vec4 v = textureGather(valueAndDepth, at, 0);
  vec4 d = textureGather(valueAndDepth, at, 1);
  vec4 bilinear = vec4((1.0 - f.x) * f.y, f.x * f.y, f.x * (1.0 - f.y), (1.0 - f.x) * (1.0 - f.y));
  vec3 planeA, planeB;
  fxPixelPlane(n0, d0, pixel, fullSize, planeA, planeB);
  vec4 e = vec4(
    fxPlaneDepthAt(planeA, planeB, fxLowTexelOffset(base + ivec2(0, 1), lowSize, step, fullSize, pixel), d0),
    fxPlaneDepthAt(planeA, planeB, fxLowTexelOffset(base + ivec2(1, 1), lowSize, step, fullSize, pixel), d0),
    fxPlaneDepthAt(planeA, planeB, fxLowTexelOffset(base + ivec2(1, 0), lowSize, step, fullSize, pixel), d0),
    fxPlaneDepthAt(planeA, planeB, fxLowTexelOffset(base, lowSize, step, fullSize, pixel), d0));
  vec4 r = fxPlaneGap(d, e, d0) / max(depthSigma * fxToleranceDepth(d0), 1e-37);
  bvec4 covered = greaterThan(d, vec4(0.0));
  vec4 w = mix(vec4(0.0), bilinear / (1.0 + r * r), covered);
  float total = dot(w, vec4(1.0));
  // (the fetches' order among equal gaps: (0, 0), (1, 0), (0, 1), (1, 1))
  vec4 gap = mix(vec4(1e30), fxPlaneGap(d, e, d0), covered);
  float nearest = 1.0;
  float nearestGap = 1e30;
  if (gap.w < nearestGap) { nearestGap = gap.w; nearest = v.w; }
  if (gap.z < nearestGap) { nearestGap = gap.z; nearest = v.z; }
  if (gap.x < nearestGap) { nearestGap = gap.x; nearest = v.x; }
  if (gap.y < nearestGap) { nearestGap = gap.y; nearest = v.y; }
  return total > 1e-4 ? dot(w, v) / total : nearest;
}
#endif
#endif
#endif
