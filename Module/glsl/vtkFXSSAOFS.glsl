//VTK::System::Dec
// vtkFXSSAOFS: screen-space ambient occlusion from the vtkFX G-buffer.
// FX_METHOD 0: hemisphere sampling (below); 1: horizon-based (GTAO, further
// down). FX_CHANNELS 3 (vtkFXDirectionalOcclusionPass): the occlusion of
// each third of the hemisphere (see fxHemisphereOcclusion), or of each
// basis vector's cosine lobe (fxHorizonOcclusion).
//
// Normal-oriented hemisphere sampling (Crytek's SSAO with the normal-aligned
// kernel of later practice): FX_SAMPLES points around the receiver p,
//   q_i = p + R * l_i * (T x_i + B y_i + N z_i),
// with directions (x_i, y_i, z_i) cosine-distributed around the normal and
// lengths l_i = u^3 (FX_FALLOFF 1), both after Vizerie's "Normal mapped
// screen space diffuse occlusion" demo (2009), citing the Global
// Illumination Compendium: "more sampling importance for the occluders that
// are close to the sampling location". A sample counts as occluded when the
// surface seen through it lies in front of it. With solid occluders the
// expectation over this distribution is the cosine-weighted obscurance
//   A(p) = 1 - (1/pi) Int f(t(w)) cos(theta) dw,  f(t) = 1 - (t/R)^(1/3),
// because P(l < t/R) = (t/R)^(1/3): the reference vtkfx-bench traces.
// With FX_FALLOFF 0 (visibility within R, the ray-traced AO of OSPRay,
// ParaView and Blender), f(t) = 1 for t < R: every l_i = 1, a sample at
// distance R, which (for a height field) is hidden exactly when its ray hit
// something before R.
// The kernel is rotated per pixel by a 4x4 tile of angles (the small tiled
// rotation texture of Crytek's SSAO, Mittring 2007), a range check fades
// out occluders more than R in front of the receiver, and only surfaces in
// front of the receiver's tangent plane can occlude (a surface never
// occludes itself, at any viewing angle). Positions come from linear depth
// and the per-pixel frustum ray (the frustum-corner reconstruction of
// deferred renderers, e.g. Mittring 2007), radii are world units, biases
// fractions of R: scaling the scene changes nothing.

// Texels are addressed through gl_FragCoord; texCoord is read once only so
// that the quad's texture-coordinate attribute stays in the program
// (vtkOpenGLQuadHelper binds it and complains when it is optimised away).
in vec2 texCoord;

uniform sampler2D fxLinearDepth;
uniform sampler2D fxNormal;
uniform ivec2 fxGBufferSize;  // full-resolution G-buffer texels
uniform int fxStep;           // G-buffer texels per occlusion texel (1 or 2)
uniform mat4 fxProjection;    // view -> clip coordinates
#if FX_METHOD == 0
uniform vec4 fxKernel[FX_SAMPLES];
#endif
// Per entry of the FX_TILE x FX_TILE tile (4: Crytek's; 8: the repeating
// pattern of Vizerie's demo): the kernel's rotation (hemisphere) or the
// first slice's direction (horizon) as (cos, sin), and the horizon steps'
// offset.
uniform vec4 fxTile[FX_TILE * FX_TILE];
uniform float fxRadius;       // world units
uniform float fxBias;         // world units
#if FX_THIN
uniform float fxThickness;    // fractions of fxRadius (vtkFXSSAOPass::OccluderThickness)
#endif
const float fxPi = 3.14159265358979;

//VTK::FXNormalCoding::Dec

//VTK::Output::Dec

//VTK::FXViewPosition::Dec

//VTK::FXOcclusionBasis::Dec

#ifndef FX_BLEED
#define FX_BLEED 0
#endif

// Ray through the centre of G-buffer texel `texel`: origin and direction,
// so that the surface there is at origin + depth * direction.
void fxTexelRay(ivec2 texel, out vec3 origin, out vec3 direction)
{
  fxRay(fxTexelNdc(texel, fxGBufferSize), origin, direction);
}

//VTK::FXExtension::Dec

#if FX_CHANNELS == 3
#define fxOcclusionValue vec3
#else
#define fxOcclusionValue float
#endif

#if FX_METHOD == 0
// Hemisphere sampling (see the top of this file). With FX_CHANNELS 3 each
// sample's occlusion goes to the three channels by its direction's weights
// against the basis of vtkFXOcclusionBasis.glsl (seed 000: "the occlusion
// over each third of the hemisphere"), and a channel's value is
// 1 - (3 / FX_SAMPLES) x its weighted occlusion: the cosine-weighted
// visibility under the lobe 3 w_k(direction), whose mean over the three
// channels is exactly the one-channel estimate from the same samples,
// because the weights of every direction sum to 1. A channel is an
// unbiased estimate of its lobe's visibility up to the kernel's quadrature:
// its weights sum to FX_SAMPLES / 3 only on average over the rotations, so
// it is clamped to [0, 1].
fxOcclusionValue fxHemisphereOcclusion(vec3 p, vec3 n, float depth, vec2 rotation)
{
#if FX_CHANNELS == 3
  // The frame the basis is defined in, continuous over the visible normals.
  vec3 t0, b0;
  fxOcclusionFrame(n, t0, b0);
  vec3 occlusion = vec3(0.0);
#else
  vec3 helper = abs(n.z) < 0.999 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
  vec3 t0 = normalize(cross(helper, n));
  vec3 b0 = cross(n, t0);
  float occlusion = 0.0;
#endif
  vec3 t = rotation.x * t0 + rotation.y * b0;
  vec3 b = cross(n, t);

  // Start just above the surface so that it does not occlude itself.
  vec3 origin = p + fxBias * n;
  for (int i = 0; i < FX_SAMPLES; ++i)
  {
    vec4 k = fxKernel[i];
    vec3 q = origin + fxRadius * k.w * (k.x * t + k.y * b + k.z * n);
    vec4 clip = fxProjection * vec4(q, 1.0);
    if (clip.w <= 0.0)
    {
      continue; // behind the camera: nothing on screen can hide it
    }
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0))))
    {
      continue; // off screen: unknown, counted as open
    }
    ivec2 texelQ = ivec2(uv * vec2(fxGBufferSize));
    float sceneDepth = texelFetch(fxLinearDepth, texelQ, 0).r;
    float sampleDepth = -q.z;
    // The texel may show the receiver's own surface: at a grazing angle its
    // depth changes a lot across the texel, and a sample just above the
    // surface would look occluded by it. What occludes lies in front of the
    // receiver's tangent plane, so compare with where that plane crosses
    // this texel's ray (exact for planes, conservative for convex surfaces),
    // less a tolerance, as the receiver's own plane sits exactly on it up to
    // rounding: 1e-3 of the depth, but at most R / 20, so that a camera far
    // from its scene (parallel projection draws the same image from any
    // distance) does not take every occluder within R for the receiver's
    // own surface (from 1000 R away, 1e-3 of the depth is R itself);
    // and at least 2e-6 of the depth, float rounding's reach there (some 20
    // float steps; 1e-5 lost the occlusion again from 3e4 times the distance).
    if (!(sceneDepth > 0.0 && sceneDepth < sampleDepth))
    {
      continue; // nothing in front of the sample (most samples, on open surfaces)
    }
    vec3 rayOrigin, rayDirection;
    fxTexelRay(texelQ, rayOrigin, rayDirection);
    float facing = dot(n, rayDirection);
    float planeDepth = abs(facing) > 1e-8 ? dot(n, p - rayOrigin) / facing : -1.0;
    float tolerance = max(2e-6 * planeDepth, min(1e-3 * planeDepth, 0.05 * fxRadius));
    if (planeDepth <= 0.0 || sceneDepth < planeDepth - tolerance)
    {
      // Range check: a surface far in front of the receiver is not between
      // the receiver and the sample.
      float gap = depth - sceneDepth;
      float blocked = gap < fxRadius ? 1.0 : max(0.0, 2.0 - gap / fxRadius);
#if FX_BLEED
      // (fxBleed and fxOccluderLight: vtkFXDirectionalOcclusionPass)
      if (blocked > 0.0)
      {
        fxBleed += blocked * fxOccluderLight(texelQ, sceneDepth);
      }
#endif
#if FX_CHANNELS == 3
      // The sample's direction in the fixed frame (t0, b0, n).
      vec3 d = vec3(rotation.x * k.x - rotation.y * k.y, rotation.y * k.x + rotation.x * k.y, k.z);
      occlusion += blocked * fxBasisWeights(d);
#else
      occlusion += blocked;
#endif
    }
  }
#if FX_CHANNELS == 3
  return clamp(1.0 - occlusion * (3.0 / float(FX_SAMPLES)), 0.0, 1.0);
#else
  return clamp(1.0 - occlusion / float(FX_SAMPLES), 0.0, 1.0);
#endif
}
#else
// acos to within about 0.007 rad (one linear term times sqrt(1 - |x|), as
// XeGTAO does after Lagarde): llvmpipe evaluates acos in software, and
// three per slice were a good part of the pass.
float fxFastAcos(float x)
{
  float a = abs(x);
  float r = (-0.156583 * a + 0.5 * fxPi) * sqrt(max(1.0 - a, 0.0));
  return x >= 0.0 ? r : fxPi - r;
}

// Horizon-based, cosine-weighted visibility: Jimenez, Wu, Pesce, Jarabo,
// "Practical Realtime Strategies for Accurate Indirect Occlusion" (GTAO,
// 2016), in the formulation of Intel's XeGTAO. FX_SLICES screen-space
// slices through the pixel, FX_STEPS depth samples on each side of it find
// the two horizons; the visible arc between them, cosine-weighted around the
// normal projected into the slice, integrates in closed form: exact for a
// height field with enough steps; with FX_STEPS of 2 to 8 an estimate. A
// horizon sample counts fully within R (FX_FALLOFF 0) or fades out
// (towards the lowest horizon) from 0.385 R to R (FX_FALLOFF 1).
#if FX_CHANNELS == 3
// One side of a slice's integral of the (unclamped) cosine around a vector
// whose projection into the slice has components u along the view and w
// along the slice's direction: from the view (angle 0) to horizon angle h,
// integral of |sin t| (u cos t + w sin t) dt =
// (u (1 - cos 2h) + w (2h - sin 2h)) / 4 for either sign of h (XeGTAO's
// per-side arc; `trig` is (cos 2h, sin 2h)). Linear in (u, w), so the
// three basis vectors' integrals weighted by b_k . s are the integral
// around s.
float fxLobeSide(float h, vec2 trig, float u, float w)
{
  return (u * (1.0 - trig.x) + w * (2.0 * h - trig.y)) / 4.0;
}
#endif

#if FX_CHANNELS != 3
// One slice's cosine-weighted visible arc between the horizon angles h0 <=
// 0 <= h1 (from the view direction), around the normal projected into the
// slice at angle normalAngle, each side kept within the normal's
// hemisphere (XeGTAO's closed form).
float fxSliceArcs(float h0, float h1, float normalAngle, float cosNormal, float sinNormal)
{
  h0 = normalAngle + clamp(h0 - normalAngle, -0.5 * fxPi, 0.5 * fxPi);
  h1 = normalAngle + clamp(h1 - normalAngle, -0.5 * fxPi, 0.5 * fxPi);
  float arc0 = (cosNormal + 2.0 * h0 * sinNormal - cos(2.0 * h0 - normalAngle)) / 4.0;
  float arc1 = (cosNormal + 2.0 * h1 * sinNormal - cos(2.0 * h1 - normalAngle)) / 4.0;
  return arc0 + arc1;
}
#endif

#if FX_THIN
// Occluders of finite thickness: the visibility bitmask of Therrien,
// Levesque and Gilet, "Screen Space Indirect Lighting with Visibility
// Bitmasks" (2023). A horizon sample hides the directions between its own
// elevation and that of the point fxThickness x R behind it (away from the
// eye), not everything below it as GTAO's height field assumes: rays pass
// behind an atom of a ball-and-stick model, or under a branch, as the
// ray-traced reference's do. Each side of a slice has 32 sectors of equal
// weight: the side's cosine-weighted arc (the integrand of fxSliceArcs) is
// split into 32 equal parts, so that the visible fraction of the weight is
// the fraction of sectors left unmarked.

// The side's arc from the view direction to the direction of elevation
// cosine c (angle sideSign x acos c from the view; +1 on side 0), after
// fxSliceArcs without its trigonometry: cos(2h - N) from cos h and sin h.
float fxSideArc(float c, float sideSign, float cosNormal, float sinNormal)
{
  c = clamp(c, -1.0, 1.0);
  float h = sideSign * fxFastAcos(c);
  float sinH = sideSign * sqrt(max(1.0 - c * c, 0.0));
  float cosTwiceHMinusNormal = (2.0 * c * c - 1.0) * cosNormal + 2.0 * c * sinH * sinNormal;
  return (cosNormal + 2.0 * h * sinNormal - cosTwiceHMinusNormal) / 4.0;
}

// The sectors (of 32 over [0, 1]) whose centres lie in [from, to).
uint fxSectors(float from, float to)
{
  int first = int(clamp(ceil(from * 32.0 - 0.5), 0.0, 32.0));
  int last = int(clamp(ceil(to * 32.0 - 0.5), 0.0, 32.0));
  uint belowLast = last >= 32 ? 0xFFFFFFFFu : (1u << uint(last)) - 1u;
  uint belowFirst = first >= 32 ? 0xFFFFFFFFu : (1u << uint(first)) - 1u;
  return belowLast & ~belowFirst;
}

// Set bits (GLSL 1.50 has no bitCount).
float fxSectorCount(uint v)
{
  v = v - ((v >> 1u) & 0x55555555u);
  v = (v & 0x33333333u) + ((v >> 2u) & 0x33333333u);
  return float((((v + (v >> 4u)) & 0x0F0F0F0Fu) * 0x01010101u) >> 24u);
}
#endif

fxOcclusionValue fxHorizonOcclusion(ivec2 texel, vec3 p, vec3 n, float depth, vec4 tile)
{
#if FX_CHANNELS == 3
  // Each channel: the visibility under the cosine lobe around its basis
  // vector, restricted to the geometric hemisphere, normalised by that
  // lobe's open integral there (the definition the reference traces with
  // a shading normal along the basis vector).
  vec3 t0, b0;
  fxOcclusionFrame(n, t0, b0);
  vec3 basis[3] = vec3[](fxBasis0.x * t0 + fxBasis0.y * b0 + fxBasis0.z * n,
    fxBasis1.x * t0 + fxBasis1.y * b0 + fxBasis1.z * n,
    fxBasis2.x * t0 + fxBasis2.y * b0 + fxBasis2.z * n);
  vec3 visibleLobes = vec3(0.0), openLobes = vec3(0.0);
#endif
  vec3 rayOrigin, rayDirection;
  fxTexelRay(texel, rayOrigin, rayDirection);
  vec3 view = normalize(-rayDirection); // towards the eye, any projection
  // R in texels at this depth along each image axis: pixels need not be
  // square (an off-axis screen, an explicit projection of another aspect;
  // with R taken along x alone, pixels twice as wide as high read a
  // crease 0.11 off its closed form on average, TestSSAO), so a slice's
  // direction (view space) takes each axis's own count. The longer at
  // most the image's diagonal (steps past it would all land outside the
  // image; the bound also keeps a surface at the eye finite). A fixed
  // bound of 512 texels shrank R in images over about 2000 pixels wide:
  // scene:corner at 6400 x 4800 lost the wall's occlusion and showed rings
  // at 512 texels, 35 levels off the 400 x 300 image in 20-pixel cells;
  // TestSSAOScale.
  // (world units per texel kept normal floats, so that the axes' ratio
  // stays finite where R in texels overflows)
  vec2 worldPerTexel = max(2.0 / vec2(fxGBufferSize) *
      vec2(length(fxRayOrigin[1] + depth * fxRayDirection[1]),
        length(fxRayOrigin[2] + depth * fxRayDirection[2])),
    vec2(1e-37));
  float finest = min(worldPerTexel.x, worldPerTexel.y);
  float longest = fxRadius / finest; // R in texels along the finer axis
  float bounded = clamp(longest, 1.0, length(vec2(fxGBufferSize)));
  vec2 radiusTexels = bounded * (finest / worldPerTexel); // equal on square pixels
  // The steps' reach as a fraction of R: 1, or less where the image's
  // diagonal bounds them. Offsets are measured in units of that reach
  // (for R far beyond the image, in units of R they fell below 1e-15,
  // where the squares' floor bent every elevation: an open plane seen at
  // 30 degrees read 0.62 under R = 1e20, TestSSAO), and distances to R
  // through its square.
  float reach = bounded < longest ? bounded / longest : 1.0;
  float reachSquared = reach * reach;
  // Horizons fade out over the last part of R: XeGTAO's 61.5% for the
  // near-weighted falloff; for visibility within R (FX_FALLOFF 0) a step at
  // R, as the definition says (a 10% fade biased the crease of TestSSAO
  // bright by up to 0.08 in a band, the step by about half that; the step
  // also measured 0.5 to 1.3 dB closer to the ray-traced reference on three
  // of the four bench scenes).
  // Distances are measured in units of R (a sample's offset divided by R
  // before it is squared): the same numbers at any scene scale, where
  // world-unit squares underflow below 1e-15 units and overflow above 1e19.
#if FX_FALLOFF == 1
  const float falloffRange = 0.615;
  const float falloffMul = -1.0 / falloffRange;
  const float falloffAdd = (1.0 - falloffRange) / falloffRange + 1.0;
#endif
  float inverseReach = 1.0 / (fxRadius * max(reach, 1e-30));
#if FX_THIN
  // (in the offsets' units; at most 1e6 of them, a million times the
  // steps' reach, where the point behind is straight behind to within
  // 1e-12: beyond it the square of its offset overflowed, under R or
  // thicknesses of about 1e19 and more, and an open plane read 0.62)
  float thickness = min(fxThickness / max(reach, 1e-30), 1e6);
#endif
  // The tile entry: the first slice's direction, at (jitter / FX_SLICES) x pi
  // for the entry's jitter within its stratum, and the steps' offset (both
  // computed once on the CPU, vtkFXSSAOPass::SetKernelUniforms). The offset
  // comes from the low bits of the entry's rank: each offset meets
  // rotations spread over the whole stratum, so the blur averages step
  // positions independently of directions. (The high bits, a finer 2x2
  // pattern, follow the rotation: offset and direction then move together
  // and draw arcs at the step distances around raised objects, as did an
  // offset spread over half a step. The low bits form 2x2 blocks, which any
  // blur of radius 2 or more averages.) Shifted by half a step so the steps
  // sample out to R (starting at 0, the last step stopped at 0.77 R on
  // average and creases read too open); clamped there.
  vec3 direction = vec3(tile.xy, 0.0);
  float stepJitter = tile.z;
  float visibility = 0.0;
  float openArcs = 0.0;
  // The next slices' directions by rotating the first (no trigonometry per
  // slice).
  const float sliceStep = fxPi / float(FX_SLICES);
  const vec2 sliceRotation = vec2(cos(sliceStep), sin(sliceStep));
  for (int slice = 0; slice < FX_SLICES; ++slice)
  {
    if (slice > 0)
    {
      direction.xy = vec2(sliceRotation.x * direction.x - sliceRotation.y * direction.y,
        sliceRotation.y * direction.x + sliceRotation.x * direction.y);
    }
    vec3 orthoDirection = direction - dot(direction, view) * view;
    vec3 axis = normalize(cross(orthoDirection, view));
    vec3 projectedNormal = n - axis * dot(n, axis);
    float projectedLength = length(projectedNormal);
    float cosNormal = clamp(dot(projectedNormal, view) / max(projectedLength, 1e-8), -1.0, 1.0);
    float normalSign = sign(dot(orthoDirection, projectedNormal));
    float normalAngle = normalSign * fxFastAcos(cosNormal);
    // The direction within the tangent plane that crosses the slice plane
    // at unit speed (its part along `axis` is 1): axis minus its part
    // along n, over what is left of it along axis. Near a slice that sees
    // the receiver edge-on (n within 1.8 degrees of axis) it has no such
    // direction; the bound leaves the slide partial there, where the
    // one-channel estimate weighs the slice by projectedLength, near 0
    // (directional occlusion's lobes weigh it by their basis vectors: a
    // sliver of false occlusion at such pixels).
    float axisNormal = dot(axis, n);
    vec3 slide = (axis - axisNormal * n) / max(1.0 - axisNormal * axisNormal, 1e-3);
    // sin(normalAngle) without trigonometry; cos(normalAngle -+ pi/2).
    float sinNormal = normalSign * sqrt(max(1.0 - cosNormal * cosNormal, 0.0));
    float lowest0 = -sinNormal;
    float lowest1 = sinNormal;
    float horizon0 = lowest0, horizon1 = lowest1;
#if FX_THIN
    // Each side's whole arc (to its tangent line), and its hidden sectors.
    vec2 sideArcs = vec2(fxSideArc(lowest0, 1.0, cosNormal, sinNormal),
      fxSideArc(lowest1, -1.0, cosNormal, sinNormal));
    vec2 perArc = 1.0 / max(sideArcs, vec2(1e-8));
    uint hidden0 = 0u, hidden1 = 0u;
#endif
    for (int step = 0; step < FX_STEPS; ++step)
    {
      // Quadratic spacing: more samples near the pixel, as in XeGTAO.
      float s = min(1.0, (float(step) + 0.5 + stepJitter) / float(FX_STEPS));
      // On the grid of texels the output stands for (every fxStep-th
      // one): at half resolution the steps then read only the even rows
      // and columns of the depth image, half its cache lines (alone, 1.5
      // ms off the pass at 1280x720 on llvmpipe, which the slide below
      // and the open arcs spend again; PSNR within 0.1 dB, the detail
      // score up to 0.03 higher on the bench scenes, README). Each
      // sample is still the surface point its texel shows (its ray); only
      // the steps' lengths round, and a step shorter than half a grid
      // texel lands on the pixel and is skipped (at half resolution,
      // occluders within about 2 pixels count from the next step on).
      vec2 gridOffset = direction.xy * radiusTexels * (s * s / float(fxStep));
      for (int side = 0; side < 2; ++side)
      {
        ivec2 q = texel + fxStep * ivec2(round(side == 0 ? gridOffset : -gridOffset));
        if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, fxGBufferSize)) || q == texel)
        {
          continue;
        }
        float sampleDepth = texelFetch(fxLinearDepth, q, 0).r;
        if (!(sampleDepth > 0.0))
        {
          continue;
        }
        vec3 o, d;
        fxTexelRay(q, o, d);
        vec3 delta = (o + sampleDepth * d - p) * inverseReach;
        float distanceSquared = dot(delta, delta) * reachSquared; // (in units of R)
        // The texel is off the slice by up to fxStep / sqrt 2 texels: slide it
        // into the slice plane along the receiver's tangent plane, which
        // keeps its height above that plane, so a flat receiver's own
        // texels land on its tangent line (the lowest horizon) whatever
        // the plane's tilt. (Removing delta's part along `axis` instead
        // moved them off the plane: a grey speckle over open tilted floors
        // and walls once the steps were on the half-resolution grid.)
        vec3 inSlice = delta - dot(delta, axis) * slide;
        float c = dot(inSlice, view) * inversesqrt(max(dot(inSlice, inSlice), 1e-30));
#if FX_FALLOFF == 0
        float weight = distanceSquared < 1.0 ? 1.0 : 0.0;
#else
        float weight = clamp(sqrt(distanceSquared) * falloffMul + falloffAdd, 0.0, 1.0);
#endif
        // A texel rounded onto the grid can lie on the slice's other side
        // of the pixel (a short step across the slice's direction): its
        // elevation would be measured against the wrong horizon.
        weight = dot(inSlice, orthoDirection) * (side == 0 ? 1.0 : -1.0) > 0.0 ? weight : 0.0;
#if FX_THIN
        // (FX_FALLOFF 0: the weight is 0 or 1) The sample's direction and
        // that of the point behind it, as fractions of the side's arc.
        vec3 behind = inSlice - thickness * view;
        float cBehind = dot(behind, view) * inversesqrt(max(dot(behind, behind), 1e-30));
        float sideSign = side == 0 ? 1.0 : -1.0;
        float lowest = side == 0 ? lowest0 : lowest1;
        float toFraction = side == 0 ? perArc.x : perArc.y;
        float front = fxSideArc(max(c, lowest), sideSign, cosNormal, sinNormal) * toFraction;
        float back = fxSideArc(max(cBehind, lowest), sideSign, cosNormal, sinNormal) * toFraction;
        uint sectors = weight > 0.0 ? fxSectors(min(front, back), max(front, back)) : 0u;
        hidden0 |= side == 0 ? sectors : 0u;
        hidden1 |= side == 0 ? 0u : sectors;
#else
        if (side == 0)
        {
          horizon0 = max(horizon0, mix(lowest0, c, weight));
        }
        else
        {
          horizon1 = max(horizon1, mix(lowest1, c, weight));
        }
#endif
      }
    }
    float h0 = -fxFastAcos(clamp(horizon1, -1.0, 1.0));
    float h1 = fxFastAcos(clamp(horizon0, -1.0, 1.0));
    // The open horizons: those of the tangent line (the lowest ones),
    // measured as the visible ones are, so that a slice where nothing
    // rises above that line gives exactly its open value.
    float open0 = -fxFastAcos(clamp(lowest1, -1.0, 1.0));
    float open1 = fxFastAcos(clamp(lowest0, -1.0, 1.0));
#if FX_CHANNELS == 3
    // The visible arc and the open one (down to the geometric tangent line).
    vec4 h = vec4(h0, h1, open0, open1);
    vec4 cos2h = cos(2.0 * h), sin2h = sin(2.0 * h);
    for (int k = 0; k < 3; ++k)
    {
      vec3 projected = basis[k] - axis * dot(basis[k], axis);
      float u = dot(projected, view);
      float w = sign(dot(orthoDirection, projected)) *
        sqrt(max(dot(projected, projected) - u * u, 0.0));
      visibleLobes[k] += fxLobeSide(h.x, vec2(cos2h.x, sin2h.x), u, w) +
        fxLobeSide(h.y, vec2(cos2h.y, sin2h.y), u, w);
      openLobes[k] += fxLobeSide(h.z, vec2(cos2h.z, sin2h.z), u, w) +
        fxLobeSide(h.w, vec2(cos2h.w, sin2h.w), u, w);
    }
#elif FX_THIN
    visibility += projectedLength * (sideArcs.x * (1.0 - fxSectorCount(hidden0) / 32.0) +
                                      sideArcs.y * (1.0 - fxSectorCount(hidden1) / 32.0));
    openArcs += projectedLength * (sideArcs.x + sideArcs.y);
#else
    visibility += projectedLength * fxSliceArcs(h0, h1, normalAngle, cosNormal, sinNormal);
    openArcs += projectedLength * fxSliceArcs(open0, open1, normalAngle, cosNormal, sinNormal);
#endif
  }
  // The slices' visible arcs over their open arcs. GTAO divides by the
  // number of slices instead, which is right on average over directions
  // only: two slices saw a tilted receiver's open hemisphere as 0.77 to
  // 1.2 depending on their direction, a pattern the noise tile and the
  // blur had to average away (and could not everywhere). The ratio is 1
  // wherever nothing occludes; elsewhere it is a ratio estimator (its
  // denominator varies with the slices' directions), which measured
  // within 0.1 dB of the division on the bench scenes.
#if FX_CHANNELS == 3
  // Each lobe's visible part of its open integral. The lobes are
  // unclamped (negative below their basis vector's tangent plane), so a
  // ratio lies within [-0.37, 1.37]: stored as (v + 0.5) / 2, in [0, 1]
  // as the packing needs; vtkFXDirectionalOcclusionPass's resolve maps it
  // back.
  vec3 lobes = visibleLobes / max(openLobes, vec3(1e-8));
  return clamp((lobes + 0.5) * 0.5, 0.0, 1.0);
#else
  // (no open arc at all: a receiver every slice sees edge-on)
  return openArcs > 1e-6 ? clamp(visibility / openArcs, 0.0, 1.0) : 1.0;
#endif
}
#endif

void main()
{
  if (texCoord.x < -1.0)
  {
    discard; // never: see the declaration of texCoord
  }
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  ivec2 texel = min(pixel * fxStep, fxGBufferSize - 1);
  float depth = texelFetch(fxLinearDepth, texel, 0).r;
  vec2 code = texelFetch(fxNormal, texel, 0).rg;
  if (!(depth > 0.0) || fxIsUnlit(code))
  {
    // No surface, or one VTK does not light: open.
#if FX_CHANNELS == 3
#if FX_METHOD == 1
    // (stored as (v + 0.5) / 2, see fxHorizonOcclusion)
    gl_FragData[0] = vec4(fxPack12(vec2(0.75)), 0.75, fxPack12(vec2(0.5)), depth);
#else
    gl_FragData[0] = vec4(fxPack12(vec2(1.0)), 1.0, fxPack12(vec2(0.5)), depth);
#endif
#if FX_BLEED
    gl_FragData[1] = vec4(0.0, 0.0, 0.0, 1.0);
#endif
#else
    gl_FragData[0] = vec4(1.0, depth, 0.0, 1.0);
#endif
    return;
  }
  vec3 p = fxViewPosition(fxTexelNdc(texel, fxGBufferSize), depth);
  vec3 n = fxDecodeNormal(code);

  int tileEntry = (pixel.x & (FX_TILE - 1)) + FX_TILE * (pixel.y & (FX_TILE - 1));
#if FX_CHANNELS == 3
  // Packed with the normal and the depth, the blur's guide
  // (vtkFXBilateralBlurFS: FX_PACKED_NORMALS).
#if FX_METHOD == 0
  vec3 channels = fxHemisphereOcclusion(p, n, depth, fxTile[tileEntry].xy);
#else
  vec3 channels = fxHorizonOcclusion(texel, p, n, depth, fxTile[tileEntry]);
#endif
  gl_FragData[0] = vec4(fxPack12(channels.xy), channels.z,
    fxPack12(fxEncodeNormal(n) * 0.5 + 0.5), depth);
#if FX_BLEED
  gl_FragData[1] = vec4(fxBleed / float(FX_SAMPLES), 1.0);
#endif
#else
#if FX_METHOD == 0
  float ao = fxHemisphereOcclusion(p, n, depth, fxTile[tileEntry].xy);
#else
  float ao = fxHorizonOcclusion(texel, p, n, depth, fxTile[tileEntry]);
#endif
  // The depth rides along as the blur's guide.
  gl_FragData[0] = vec4(ao, depth, 0.0, 1.0);
#endif
}
