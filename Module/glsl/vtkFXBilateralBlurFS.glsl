//VTK::System::Dec
// vtkFXBilateralBlurFS: depth- and normal-aware (cross-bilateral) blur and
// joint-bilateral upsampling of 1 to 4 values per pixel.
//
// Bilateral filtering after Tomasi and Manduchi (1998), guided by the
// G-buffer instead of the image itself ("cross"/"joint" bilateral, Eisemann
// and Durand 2004; upsampling: Kopf et al. 2007), as SSAO write-ups of the
// time blur their occlusion (e.g. the SSAO article on gamerendering.com,
// 2009, over 17 taps): a tap counts with a Gaussian of its distance times
//   1 / (1 + (gap / (sigma d0))^2)        (d against the depth e that the
//                                          pixel's tangent plane has at the
//                                          tap, fxPlaneDepthAt, or against
//                                          d0, the nearer, fxPlaneGap: a surface at a
//                                          grazing angle blurs much as one
//                                          facing the eye, and a crease's
//                                          sides stay apart; relative to the
//                                          depth: the same at every scene
//                                          scale; a Cauchy weight, as
//                                          selective as a Gaussian near 0
//                                          and cheaper than exp)
//   max(0, n . n0)^p                      (no bleeding across creases; p is
//                                          a compile-time integer, FX_NORMAL_POWER)
// With FX_BOX the distance weight is a box whose two end taps weigh 1/2:
// every phase of a period-(2 x radius) pattern, such as the SSAO pass's
// tiled noise, then counts once, up to the depth weights (the tiled-noise
// blur of Crytek's SSAO, Mittring 2007, centred).
// The upsample is vtkFXJointUpsample.glsl's.
// FX_MODE: 3 guide: normal and depth of each input texel, once, so that the
//            taps below fetch one texel instead of two and decode nothing;
//          0 horizontal pass, 1 vertical pass (input resolution),
//          2 upsample from input to G-buffer resolution,
//          4 the full 2D filter in one pass (input resolution; Separable
//            off): every tap of the square weighted against the pixel
//            itself, which the two passes approximate (a tap off the
//            pixel's row is weighted against the row's tap that carried it).
// Inputs that carry their own guide need no guide stage, and every tap is
// a single fetch (a software rasteriser pays per fetch):
// FX_PACKED: one value whose linear depth rides in .g (vtkFXSSAOPass's
//            output), weighted by depth only (the depth against the
//            pixel's tangent plane, whose normal comes from the G-buffer,
//            keeps a crease's sides apart with no normal per tap);
// FX_PACKED_NORMALS: three values with their normal and depth
//            (vtkFXDirectionalOcclusionPass's packing: R = two values, 12
//            bits each, G = the third, B = the octahedral normal, 12 bits
//            a coordinate, A = depth), weighted by normal and depth as the
//            guide would: the channels are relative to each pixel's own
//            basis and must not mix across a crease. The horizontal pass
//            keeps the packing; the vertical one writes the three values
//            and the depth (.a) as they are, for bilinear reads.
// FX_DEPTH_COMPONENT: where the depth rides in what the blur writes.

// Texels are addressed through gl_FragCoord; texCoord is read once only so
// that the quad's texture-coordinate attribute stays in the program
// (vtkOpenGLQuadHelper binds it and complains when it is optimised away).
in vec2 texCoord;

uniform sampler2D fxInput;
uniform sampler2D fxGuide;   // (normal, linear depth) per input texel
uniform sampler2D fxLinearDepth;
uniform sampler2D fxNormal;
uniform ivec2 fxGBufferSize;
uniform ivec2 fxInputSize;
uniform int fxStep;          // G-buffer texels per input texel
// Taps on each side, and the weight of a tap i texels from the pixel along
// one axis, at |i| (1 at 0), computed on the CPU (an exp() per tap cost
// llvmpipe more than the rest of the weight): a Gaussian of sigma
// radius / 2, or the box (FX_BOX). Compile-time constants, so that the
// taps' loop unrolls.
const int fxRadius = FX_RADIUS;
const float fxTapWeights[FX_RADIUS + 1] = float[FX_RADIUS + 1](FX_TAP_WEIGHTS);
uniform float fxDepthSigma;  // fraction of the depth

//VTK::FXNormalCoding::Dec

//VTK::FXViewPosition::Dec

//VTK::FXJointUpsample::Dec

//VTK::Output::Dec

ivec2 fxGuideTexel(ivec2 inputTexel)
{
  return min(inputTexel * fxStep, fxGBufferSize - 1);
}

// Values `value` of input texel q and their guide (normal, depth); `n0`
// stands in for the normal of inputs that carry depth alone. Returns the
// texel as stored.
vec4 fxReadTap(ivec2 q, vec3 n0, out vec4 value, out vec4 guide)
{
  vec4 texel = texelFetch(fxInput, q, 0);
#if FX_PACKED_NORMALS
  value = vec4(fxUnpack12(texel.r), texel.g, 0.0);
  guide = vec4(fxDecodeNormal(fxUnpack12(texel.b) * 2.0 - 1.0), texel.a);
#elif FX_PACKED
  value = texel;
  guide = vec4(n0, texel.g);
#else
  value = texel;
  guide = texelFetch(fxGuide, q, 0);
#endif
  return texel;
}

// What a blur pass writes for values `value` of a pixel whose input texel
// is `center` and depth d0.
vec4 fxBlurOutput(vec4 value, vec4 center, float d0)
{
#if FX_PACKED_NORMALS && FX_MODE == 0
  return vec4(fxPack12(value.xy), value.z, center.b, d0); // for the vertical pass
#elif FX_PACKED_NORMALS
  return vec4(value.xyz, d0);
#elif FX_PACKED
  return vec4(value.r, d0, value.ba); // the depth travels on to the next stage
#else
  return value;
#endif
}

// The normal of a G-buffer texel's tangent plane, or 0 (judge depth
// against the pixel's own) where VTK does not light the surface: its code
// decodes to no normal.
vec3 fxPlaneNormal(vec2 code)
{
  return fxIsUnlit(code) ? vec3(0.0) : fxDecodeNormal(code);
}

// 1 / the depth tolerance of a pixel at depth d0 (a fraction of
// fxToleranceDepth(d0): the same when a parallel view's camera moves back), once per pixel rather
// than a division per tap. (The tolerance is kept a normal
// float: at depths below about 1e-34 world units, past what the occlusion
// passes serve but not what a blur of another input may see, the product
// underflows, and 0 / 0 is NaN.)
float fxToleranceInverse(float d0)
{
  return 1.0 / max(fxDepthSigma * fxToleranceDepth(d0), 1e-37);
}

// Weight of a tap whose guide (normal, depth) is g, for a pixel (n0, d0)
// that expects the tap at depth `expected` (d0, or on its tangent plane);
// `toleranceInverse` from fxToleranceInverse(d0).
float fxGuideWeight(float d0, float toleranceInverse, float expected, vec3 n0, vec4 g)
{
  if (!(g.w > 0.0))
  {
    return 0.0; // background never contributes
  }
  float r = fxPlaneGap(g.w, expected, d0) * toleranceInverse;
  // c^FX_NORMAL_POWER (0..32) by squaring, unrolled at compile time (the
  // bit tests are constant and fold away): a loop here, nested in the
  // taps' loop, cost llvmpipe a quarter of a directional occlusion frame
  // (10 ms at 640x480).
  // (One line: GLSL before 4.20 has no line continuation.)
#define FX_POWER_BIT(bit) if ((FX_NORMAL_POWER & bit) != 0) { wn *= c; } c *= c;
  float c = max(dot(n0, g.xyz), 0.0);
  float wn = 1.0;
  FX_POWER_BIT(1)
  FX_POWER_BIT(2)
  FX_POWER_BIT(4)
  FX_POWER_BIT(8)
  FX_POWER_BIT(16)
  FX_POWER_BIT(32)
  return wn / (1.0 + r * r);
}


void main()
{
  if (texCoord.x < -1.0)
  {
    discard; // never: see the declaration of texCoord
  }
  ivec2 p = ivec2(gl_FragCoord.xy);
#if FX_MODE == 3
  ivec2 texel = fxGuideTexel(p);
  gl_FragData[0] = vec4(fxDecodeNormal(texelFetch(fxNormal, texel, 0).rg),
    texelFetch(fxLinearDepth, texel, 0).r);
#elif FX_MODE != 2
  vec4 value0, g0;
  vec4 center = fxReadTap(p, vec3(0.0, 0.0, 1.0), value0, g0);
  float d0 = g0.w;
  if (!(d0 > 0.0))
  {
    gl_FragData[0] = fxBlurOutput(value0, center, d0);
    return;
  }
  // The pixel's tangent plane, against which its taps' depths are judged
  // (input that carries depth alone: the normal from the G-buffer).
#if FX_PACKED
  vec3 n0 = fxPlaneNormal(texelFetch(fxNormal, fxGuideTexel(p), 0).rg);
#else
  vec3 n0 = g0.xyz;
#endif
  // Input texel q holds G-buffer texel q x step (never past the G-buffer's
  // edge: the input is its size divided by step, rounded up), so taps are
  // step G-buffer texels apart.
  vec3 planeA, planeB;
  fxPlaneDepthRatio(n0, d0, fxTexelNdc(fxGuideTexel(p), fxGBufferSize),
    2.0 * float(fxStep) / vec2(fxGBufferSize), planeA, planeB);
  // Taps (i, j): i along the pass's direction, j across it (the 2D
  // filter's rows; one row, j = 0, for the separable passes).
  ivec2 along = FX_MODE == 1 ? ivec2(0, 1) : ivec2(1, 0);
#if FX_MODE == 4
  int rows = fxRadius;
#else
  int rows = 0;
#endif
  float toleranceInverse = fxToleranceInverse(d0);
  vec4 sum = value0;
  float total = 1.0;
  for (int j = -rows; j <= rows; ++j)
  {
    float rowWeight = fxTapWeights[abs(j)];
    for (int i = -fxRadius; i <= fxRadius; ++i)
    {
      ivec2 q = p + i * along + ivec2(0, j);
      if ((i == 0 && j == 0) || any(lessThan(q, ivec2(0))) ||
        any(greaterThanEqual(q, fxInputSize)))
      {
        continue;
      }
      vec4 tap, guide;
      fxReadTap(q, n0, tap, guide);
      float expected = fxPlaneDepthAt(planeA, planeB, vec2(q - p), d0);
      float w = fxTapWeights[abs(i)] * rowWeight *
        fxGuideWeight(d0, toleranceInverse, expected, n0, guide);
      sum += w * tap;
      total += w;
    }
  }
  gl_FragData[0] = fxBlurOutput(sum / total, center, d0);
#else
  float d0 = texelFetch(fxLinearDepth, p, 0).r;
  if (!(d0 > 0.0))
  {
    gl_FragData[0] = texelFetch(fxInput, clamp(p / fxStep, ivec2(0), fxInputSize - 1), 0);
    return;
  }
  // The pixel's tangent plane, as the blur judged its taps.
  vec3 n0 = fxPlaneNormal(texelFetch(fxNormal, p, 0).rg);
#if FX_PACKED || FX_PACKED_NORMALS
  gl_FragData[0] = fxJointUpsample(fxInput, true, fxInput, FX_DEPTH_COMPONENT, fxInputSize,
    fxStep, p, d0, fxDepthSigma, n0, fxGBufferSize, vec4(1.0));
#else
  // (where the four texels are background, what the source holds there, as
  // for a background pixel above: 0 for bounced light)
  gl_FragData[0] = fxJointUpsample(fxInput, false, fxGuide, 3, fxInputSize, fxStep, p, d0,
    fxDepthSigma, n0, fxGBufferSize, texelFetch(fxInput, clamp(p / fxStep, ivec2(0), fxInputSize - 1), 0));
#endif
#endif
}
