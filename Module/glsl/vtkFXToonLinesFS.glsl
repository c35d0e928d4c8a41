//VTK::System::Dec
// vtkFXToonLinesFS: anti-aliased feature lines of a given width, centred on
// the pixel boundaries vtkFXToonEdgesFS marked.
//
// Each marked boundary is a unit side of a pixel (R: the side shared with
// the right neighbour; G: with the one above); together they form the
// staircase contour of the discontinuity. The sides' midpoints lie on the
// discontinuity itself wherever it runs straight (at 45 degrees the
// midpoints of both kinds of side fall on one line, where the staircase's
// corners stray 0.35 px from it), so the line is drawn around them: a
// pixel's coverage is
//   clamp(w / 2 + 1/2 - d, 0, 1),  d = distance from the pixel's centre
//                                      to the contour through the marked
//                                      midpoints (see fxContourDistance),
// the box filter of a band of width w for an axis-aligned edge (a line of
// w = 0.8 covers 0.4 of each pixel beside it). Only midpoints within
// w / 2 + 1/2 can matter: texel offsets from -floor(w/2 + 1) to
// floor(w/2 + 1/2), in 2x2 blocks (one textureGather each with FX_GATHER):
// one block for lines under 1 px, four under 3 px, nine under 5 px; wider
// lines read the marks texel by texel.
// The result is blended over the image: colour and coverage as alpha, at
// the depth of the surface the line belongs to (depth-tested, not
// written).

uniform sampler2D fxEdges;  // (r + 2 g) / 3, see vtkFXToonEdgesFS; 0 outside
uniform ivec2 fxEdgeSize;
uniform ivec2 fxOrigin;     // the viewport's corner in the framebuffer
uniform float fxHalfWidth;  // pixels
uniform vec3 fxLineColor;
// The G-buffer's window depth (1 where nothing was drawn): a line is drawn
// at the depth of the nearest surface it belongs to, depth-tested against
// the target's, so that what hides a surface hides its lines (an opaque
// prop drawn forward, a lower layer's preserved depth).
uniform sampler2D fxSurfaceDepth;

//VTK::Output::Dec

// Each pixel needs the two marked side midpoints nearest its centre. The
// midpoints a pixel can see sit at fixed offsets from it, so
// vtkFXToonPass lists them once, sorted by distance from the centre (ties
// in a fixed order), and generates code that takes the first two marked
// ones in that order: no distances or compares per midpoint, which a
// software rasteriser would run for every pixel whatever the branches
// (every midpoint used to be measured and insertion-sorted: three times
// the cost at 1280x720 on llvmpipe). Straight-line code for lines under
// 5 px; a loop over a constant list for wider ones.
struct fxNearest
{
  vec2 first;
  vec2 second;
  int count; // marked midpoints taken so far (2 at most matter)
};

void fxTake(inout fxNearest n, bool marked, vec2 midpoint)
{
  n.second = (marked && n.count == 1) ? midpoint : n.second;
  n.first = (marked && n.count == 0) ? midpoint : n.first;
  n.count += marked ? 1 : 0;
}

// Marks bytes (r + 2 g) / 3 to bits: 1, the texel's side shared with its
// right neighbour; 2, the one above.
ivec4 fxMarkBits(vec4 markBytes)
{
  return ivec4(markBytes * 3.0 + 0.5);
}

// The marks byte of texel `t`, 0 outside the texture.
float fxMarkAt(ivec2 t)
{
  bool outside = any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, fxEdgeSize));
  return outside ? 0.0 : texelFetch(fxEdges, clamp(t, ivec2(0), fxEdgeSize - 1), 0).r;
}

// The marks of the 2x2 block whose lower-left texel is `t`: w (t), z (t +
// (1, 0)), x (t + (0, 1)), y (t + (1, 1)), 0 outside the texture.
vec4 fxMarkBlock(ivec2 t)
{
#if FX_GATHER
  return textureGather(fxEdges, vec2(t + 1) / vec2(fxEdgeSize), 0);
#else
  return vec4(fxMarkAt(t + ivec2(0, 1)), fxMarkAt(t + ivec2(1, 1)), fxMarkAt(t + ivec2(1, 0)),
    fxMarkAt(t));
#endif
}

// The G-buffer's window depth at texel `t`, 1 (nothing) outside it.
float fxSurfaceDepthAt(ivec2 t)
{
  bool outside = any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, fxEdgeSize));
  return outside ? 1.0 : texelFetch(fxSurfaceDepth, clamp(t, ivec2(0), fxEdgeSize - 1), 0).r;
}

// Distance from the centre to the contour: to the segment between the two
// nearest midpoints when they are neighbours on it (at most a pixel apart:
// a diagonal run's midpoints are 0.71 apart, a straight one's 1), so that
// the line keeps its width between them; else to the nearest midpoint.
float fxContourDistance(fxNearest n)
{
  vec2 along = n.second - n.first;
  float length2 = dot(along, along);
  if (n.count < 2 || length2 > 1.0001)
  {
    return length(n.first);
  }
  float t = clamp(-dot(n.first, along) / length2, 0.0, 1.0);
  return length(n.first + t * along);
}

void main()
{
  ivec2 pixel = ivec2(gl_FragCoord.xy) - fxOrigin;
  fxNearest nearest = fxNearest(vec2(0.0), vec2(0.0), 0);
  // Generated (vtkFXToonPass::MidpointCode): the marks, and fxTake of
  // every midpoint, nearest first.
  //VTK::FXToonLines::Midpoints
  if (nearest.count == 0)
  {
    discard;
  }
  float coverage = clamp(fxHalfWidth + 0.5 - fxContourDistance(nearest), 0.0, 1.0);
  if (coverage <= 0.0)
  {
    discard;
  }
  gl_FragData[0] = vec4(fxLineColor, coverage);
  // The nearest of this pixel and the two pixels the nearest marked side
  // separates (its midpoint is half a pixel from each along one axis):
  // on the near side of a silhouette the line is at that surface's depth,
  // on its far side in front of what lies behind, and a pixel of the
  // surface itself never puts its own line behind it. Less 1e-7: a 32-bit
  // fixed-point depth read as a float and written back can come out up to
  // 3e-8 farther than the target's copy of it (24-bit and float depths
  // come back exact).
  vec2 m = nearest.first;
  vec2 across = abs(fract(m.x) - 0.5) < 0.25 ? vec2(0.5, 0.0) : vec2(0.0, 0.5);
  float depth = min(fxSurfaceDepthAt(pixel),
    min(fxSurfaceDepthAt(pixel + ivec2(round(m - across))),
      fxSurfaceDepthAt(pixel + ivec2(round(m + across)))));
  gl_FragDepth = max(depth - 1e-7, 0.0);
}
