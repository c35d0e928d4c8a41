//VTK::System::Dec
// vtkFXToonEdgesFS: where feature lines go, between G-buffer pixels.
//
// The deferred toon shader of seed 004 marks a pixel as an edge when its
// depth or normal differs "obviously" from its neighbours'. Here the two
// tests are made to hold at any scene scale and viewing angle:
// - silhouette: one pixel is background and the other is not, or the
//   positions p, q (view space, from linear depth and the frustum ray)
//   are off each other's tangent planes,
//     max(|n_p . (q - p)|, |n_q . (p - q)|) > threshold x min(depth),
//   which is 0 for two pixels of one plane at any angle (a raw depth
//   difference grows without bound at grazing angles) and scales with the
//   scene; an unlit pixel stores no normal: its plane is the one through
//   its neighbours' positions, on each axis the neighbour nearer in depth
//   (on its own surface where the other lies across an edge; exact for a
//   plane), and where it has no covered neighbour on an axis it compares
//   depths directly, as does a lit pixel beside an unlit one (at a lit
//   limb the lit side's plane holds the unlit one's point at nearly any
//   depth);
// - crease: n_p . n_q < cos(crease angle), both pixels lit.
// Output (R8): (r + 2 g) / 3 with r = 1 where the pixel and its right
// neighbour are separated, g = 1 for the neighbour above. FX_SILHOUETTES,
// FX_CREASES select the tests; FX_GATHER reads 2x2 blocks with
// textureGather (GL 4.0 / ARB_gpu_shader5) where the context has it.
// With FX_TILE_MASK (image stores: GL 4.2 / ARB_shader_image_load_store) a
// marked pixel also flags, in fxTileMask, the FX_TILE x FX_TILE tiles of
// the pixels whose lines can reach it (vtkFXTilePointsVS draws only
// those), and the marks themselves are image stores into fxEdges (cleared
// to no mark): then the pass needs to run at covered pixels only (the
// G-buffer's depth test rejects the rest before the shader), because a
// covered pixel also writes the marks of its left and lower neighbours
// where those are background. A background pixel's marks (silhouettes
// only) say whether its right and upper neighbours are covered, which
// both covered neighbours that write them know, so they write the same
// value. "Covered" is linear depth above 0 here, below 1 in the depth
// test: they differ only for a fragment at the far plane (window depth 1,
// which the composite shows as background), whose own marks are then not
// stored. Without image stores the marks are the pass's colour output,
// and every pixel that can have one runs (vtkFXToonEdgeMaskFS).

// Texels are addressed through gl_FragCoord; texCoord is read once only so
// that the quad's texture-coordinate attribute stays in the program
// (vtkOpenGLQuadHelper binds it and complains when it is optimised away).
in vec2 texCoord;

uniform sampler2D fxLinearDepth;
uniform sampler2D fxNormal;
uniform ivec2 fxGBufferSize;
uniform float fxSilhouetteThreshold; // fraction of the depth (fxToleranceDepth)
uniform float fxCreaseCosine;
#if FX_TILE_MASK
// The depth test against the G-buffer's depth before the shader: with
// image stores it would otherwise run after it, and reject nothing's cost.
layout(early_fragment_tests) in;
layout(r8) uniform writeonly image2D fxEdges;
layout(r8) uniform writeonly image2D fxTileMask;
uniform ivec2 fxLineWindow; // texel offsets a line pixel reads: first, last
#endif

//VTK::FXNormalCoding::Dec

//VTK::FXViewPosition::Dec

//VTK::Output::Dec

struct fxSurface
{
  bool covered;
  bool lit;
  bool planar; // lit, or unlit with a plane from its neighbours' depths
  vec3 normal; // 0 where not planar
  float depth;
};

fxSurface fxSurfaceOf(float depth, vec2 encoded)
{
  fxSurface s;
  s.depth = depth;
  // Background is cleared to depth 0; NaN depth counts as background too.
  s.covered = s.depth > 0.0;
  s.lit = s.covered && !fxIsUnlit(encoded);
  s.planar = s.lit;
  s.normal = s.lit ? fxDecodeNormal(encoded) : vec3(0.0);
  return s;
}

#if !FX_GATHER
fxSurface fxSurfaceAt(ivec2 texel)
{
  ivec2 t = min(texel, fxGBufferSize - 1);
  return fxSurfaceOf(texelFetch(fxLinearDepth, t, 0).r, texelFetch(fxNormal, t, 0).rg);
}

float fxDepthAt(ivec2 texel)
{
  return texelFetch(fxLinearDepth, clamp(texel, ivec2(0), fxGBufferSize - 1), 0).r;
}
#endif

#if FX_TILE_MASK
// Both marks of a texel in one byte (0, 1/3, 2/3, 1: r, its right side,
// g, its upper side), so that one gather reads four pixels' marks in
// vtkFXToonLinesFS. The image holds no mark where nothing is stored.
void fxStoreMarks(ivec2 texel, float r, float g)
{
  if (r + g > 0.0)
  {
    imageStore(fxEdges, texel, vec4((r + 2.0 * g) / 3.0));
  }
}

// Flags the tiles whose lines can reach a mark of the texels `first` ..
// `last`: pixel q reads the marks of texels q + fxLineWindow.x ..
// q + fxLineWindow.y, so texel t's reach pixels t - fxLineWindow.y ..
// t - fxLineWindow.x.
void fxFlagTiles(ivec2 first, ivec2 last)
{
  ivec2 firstTile = max(first - fxLineWindow.y, 0) / FX_TILE;
  ivec2 lastTile = max(last - fxLineWindow.x, 0) / FX_TILE;
  for (int y = firstTile.y; y <= lastTile.y; ++y)
  {
    for (int x = firstTile.x; x <= lastTile.x; ++x)
    {
      imageStore(fxTileMask, ivec2(x, y), vec4(1.0));
    }
  }
}
#endif

#if FX_SILHOUETTES
// The unit normal of the plane through an unlit pixel's position and two
// neighbours' (offsets from it, view space), one per axis: of the two on
// an axis, the one nearer in depth (`*Gap`: |depth difference|, +inf where
// not covered). 0 where an axis has no covered neighbour or the offsets
// are parallel.
vec3 fxPlaneFromDepths(vec3 toRight, float rightGap, vec3 toLeft, float leftGap, vec3 toAbove,
  float aboveGap, vec3 toBelow, float belowGap)
{
  vec3 across = rightGap <= leftGap ? toRight : toLeft;
  vec3 up = aboveGap <= belowGap ? toAbove : toBelow;
  vec3 n = cross(across, up);
  float length2 = dot(n, n);
  bool valid = min(rightGap, leftGap) < 1e30 && min(aboveGap, belowGap) < 1e30 && length2 > 0.0;
  return valid ? n * inversesqrt(max(length2, 1e-37)) : vec3(0.0);
}
#endif

// `d`: from a's position to b's (view space); a lit or background.
float fxSeparated(fxSurface a, fxSurface b, vec3 d)
{
  // Selects, not branches: a software rasteriser runs every branch any
  // pixel of a block takes.
  float separated = 0.0;
#if FX_SILHOUETTES
  // Unlit normals are 0, so only lit sides count in the plane gap. A lit
  // and an unlit pixel are two primitives: their depth gap counts too (at
  // a lit limb the lit side's plane holds the unlit one's point at nearly
  // any depth).
  float planeGap = max(abs(dot(a.normal, d)), abs(dot(b.normal, d)));
  float gap = (a.lit && b.lit) ? planeGap : max(planeGap, abs(b.depth - a.depth));
  float scale = fxToleranceDepth(min(a.depth, b.depth));
  bool apart = a.covered && gap > fxSilhouetteThreshold * scale;
  separated = (a.covered != b.covered || apart) ? 1.0 : 0.0;
#endif
#if FX_CREASES
  separated = (a.lit && b.lit && dot(a.normal, b.normal) < fxCreaseCosine) ? 1.0 : separated;
#endif
  return separated;
}

#if FX_SILHOUETTES
// fxSeparated for a covered unlit a, whose plane (if it has one) comes
// from its neighbours' depths; `otherStep`: |depth step| from a to its
// neighbour on the far side from b (1e38: none). Without a plane the
// depth gap counts. At a limb, where the surface turns away from the view,
// the plane holds a point just behind at nearly any depth (and b may be
// the neighbour it was made from): between two unlit pixels a depth step
// also counts where it is well beyond the step on a's other side (a
// plane's steps change little from one pixel to the next, at any angle).
// No crease: an unlit pixel has no normal of its own.
float fxSeparatedUnlit(fxSurface a, fxSurface b, vec3 d, float otherStep)
{
  float planeGap = max(abs(dot(a.normal, d)), abs(dot(b.normal, d)));
  float depthGap = abs(b.depth - a.depth);
  float gap = a.planar ? planeGap : max(planeGap, depthGap);
  float scale = fxToleranceDepth(min(a.depth, b.depth));
  float limit = fxSilhouetteThreshold * scale;
  bool jump = a.planar && !b.lit && depthGap > limit && depthGap > 2.0 * otherStep + limit;
  return (!b.covered || gap > limit || jump) ? 1.0 : 0.0;
}
#endif

void main()
{
  if (texCoord.x < -1.0)
  {
    discard; // never: see the declaration of texCoord
  }
  ivec2 texel = ivec2(gl_FragCoord.xy);
#if FX_GATHER
  // One gather per value fetches a 2x2 block; a software rasteriser pays
  // per fetch. The normals: the block whose corner is this pixel's, (w)
  // here, (z) right, (x) above.
  vec2 texelSize = 1.0 / vec2(fxGBufferSize);
  vec2 corner = vec2(texel + 1) * texelSize;
  vec4 normalX = textureGather(fxNormal, corner, 0);
  vec4 normalY = textureGather(fxNormal, corner, 1);
#if FX_TILE_MASK
  // The depths, also of the left and lower neighbours (see the marks
  // below), from the blocks to the left, (x) left-above, (y) above,
  // (z) here, (w) left, and below, (x) here, (y) right, (z) below-right,
  // (w) below.
  vec4 leftBlock = textureGather(fxLinearDepth, vec2(texel + ivec2(0, 1)) * texelSize, 0);
  vec4 lowerBlock = textureGather(fxLinearDepth, vec2(texel + ivec2(1, 0)) * texelSize, 0);
  vec3 depths = vec3(leftBlock.z, lowerBlock.y, leftBlock.y); // here, right, above
  vec2 left = leftBlock.wx;   // left, and the one above it
  vec2 lower = lowerBlock.wz; // below, and the one right of it
#else
  vec3 depths = textureGather(fxLinearDepth, corner, 0).wzx; // here, right, above
  // (for the planes of unlit pixels)
  vec2 left = vec2(texelFetch(fxLinearDepth, max(texel - ivec2(1, 0), ivec2(0)), 0).r, 0.0);
  vec2 lower = vec2(texelFetch(fxLinearDepth, max(texel - ivec2(0, 1), ivec2(0)), 0).r, 0.0);
#endif
  fxSurface here = fxSurfaceOf(depths.x, vec2(normalX.w, normalY.w));
  fxSurface right = fxSurfaceOf(depths.y, vec2(normalX.z, normalY.z));
  fxSurface above = fxSurfaceOf(depths.z, vec2(normalX.x, normalY.x));
#else
  fxSurface here = fxSurfaceAt(texel);
  fxSurface right = fxSurfaceAt(texel + ivec2(1, 0));
  fxSurface above = fxSurfaceAt(texel + ivec2(0, 1));
  vec2 left = vec2(fxDepthAt(texel + ivec2(-1, 0)), fxDepthAt(texel + ivec2(-1, 1)));
  vec2 lower = vec2(fxDepthAt(texel + ivec2(0, -1)), fxDepthAt(texel + ivec2(1, -1)));
#endif
  // The neighbours' positions relative to this one's, from one frustum
  // ray (fxViewPosition is affine in the image point): P(x + h) - P(x) =
  // (z' - z) direction(x) + h (origin'(x) + z' direction'(x)).
  vec2 ndcStep = 2.0 / vec2(fxGBufferSize);
  vec3 origin, direction;
  fxRay(ndcStep * (vec2(texel) + 0.5) - 1.0, origin, direction);
  vec3 toRight = (right.depth - here.depth) * direction +
    ndcStep.x * (fxRayOrigin[1] + right.depth * fxRayDirection[1]);
  vec3 toAbove = (above.depth - here.depth) * direction +
    ndcStep.y * (fxRayOrigin[2] + above.depth * fxRayDirection[2]);
  bool hasRightSide = texel.x + 1 < fxGBufferSize.x;
  bool hasUpperSide = texel.y + 1 < fxGBufferSize.y;
  float r = 0.0, g = 0.0;
#if FX_SILHOUETTES
  // (the unlit pixels' tests apart; llvmpipe runs a branch's body whatever
  // its pixels take: 0.7 ms at 1280x720 on a lit mesh)
  if (here.covered && !here.lit)
  {
    vec3 toLeft = (left.x - here.depth) * direction -
      ndcStep.x * (fxRayOrigin[1] + left.x * fxRayDirection[1]);
    vec3 toBelow = (lower.x - here.depth) * direction -
      ndcStep.y * (fxRayOrigin[2] + lower.x * fxRayDirection[2]);
    const float none = 1e38;
    float rightStep = right.covered && hasRightSide ? abs(right.depth - here.depth) : none;
    float aboveStep = above.covered && hasUpperSide ? abs(above.depth - here.depth) : none;
    float leftStep = left.x > 0.0 && texel.x > 0 ? abs(left.x - here.depth) : none;
    float belowStep = lower.x > 0.0 && texel.y > 0 ? abs(lower.x - here.depth) : none;
    here.normal = fxPlaneFromDepths(
      toRight, rightStep, toLeft, leftStep, toAbove, aboveStep, toBelow, belowStep);
    here.planar = dot(here.normal, here.normal) > 0.0;
    r = hasRightSide ? fxSeparatedUnlit(here, right, toRight, leftStep) : 0.0;
    g = hasUpperSide ? fxSeparatedUnlit(here, above, toAbove, belowStep) : 0.0;
  }
  else
#endif
  {
    r = hasRightSide ? fxSeparated(here, right, toRight) : 0.0;
    g = hasUpperSide ? fxSeparated(here, above, toAbove) : 0.0;
  }
#if FX_TILE_MASK
  fxStoreMarks(texel, r, g);
  // A covered pixel also stores the marks of its left and lower
  // neighbours where those are background (see the top of this file): a
  // background pixel's right (upper) side is marked where its right
  // (upper) neighbour is covered.
  // (NaN depth is background, as everywhere in this pass; without
  // silhouettes a background pixel has no mark)
  bool leftMarked = FX_SILHOUETTES != 0 && here.covered && texel.x > 0 && !(left.x > 0.0);
  bool lowerMarked = FX_SILHOUETTES != 0 && here.covered && texel.y > 0 && !(lower.x > 0.0);
  fxStoreMarks(texel - ivec2(1, 0), leftMarked ? 1.0 : 0.0,
    (leftMarked && texel.y + 1 < fxGBufferSize.y && left.y > 0.0) ? 1.0 : 0.0);
  fxStoreMarks(texel - ivec2(0, 1),
    (lowerMarked && texel.x + 1 < fxGBufferSize.x && lower.y > 0.0) ? 1.0 : 0.0,
    lowerMarked ? 1.0 : 0.0);
  if (r + g > 0.0 || leftMarked || lowerMarked)
  {
    // One loop for the three texels (it may flag a tile that only the
    // unmarked diagonal neighbour would reach: lines are then drawn over
    // it and find no mark).
    fxFlagTiles(texel - ivec2(1), texel);
  }
#else
  // Both marks in one byte (0, 1/3, 2/3, 1), so one gather reads four
  // pixels' marks in vtkFXToonLinesFS.
  gl_FragData[0] = vec4((r + 2.0 * g) / 3.0, 0.0, 0.0, 1.0);
#endif
}
