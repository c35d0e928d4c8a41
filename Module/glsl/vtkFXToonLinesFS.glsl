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
// one block for lines under 1 px, four under 3 px.
// The result is blended over the image: colour and coverage as alpha.

in vec2 texCoord;

uniform sampler2D fxEdges;  // (r + 2 g) / 3, see vtkFXToonEdgesFS; 0 outside
uniform ivec2 fxEdgeSize;
uniform ivec2 fxOrigin;     // the viewport's corner in the framebuffer
uniform float fxHalfWidth;  // pixels
uniform ivec2 fxWindow;     // first and last texel offset visited (even count)
uniform vec3 fxLineColor;

//VTK::Output::Dec

// The two marked side midpoints nearest the pixel's centre (offsets from
// it, and their distances, 1e30 when none).
struct fxNearest
{
  vec2 first;
  vec2 second;
  float firstDistance;
  float secondDistance;
};

void fxConsider(inout fxNearest n, vec2 midpoint)
{
  float d = length(midpoint);
  if (d < n.firstDistance)
  {
    n.second = n.first;
    n.secondDistance = n.firstDistance;
    n.first = midpoint;
    n.firstDistance = d;
  }
  else if (d < n.secondDistance)
  {
    n.second = midpoint;
    n.secondDistance = d;
  }
}

// Adds the marked side midpoints of the texel `offset` away, whose marks
// byte is `markByte`.
void fxConsiderTexel(inout fxNearest n, vec2 offset, float markByte)
{
  int marks = int(markByte * 3.0 + 0.5);
  if ((marks & 1) != 0)
  {
    fxConsider(n, offset + vec2(0.5, 0.0));
  }
  if ((marks & 2) != 0)
  {
    fxConsider(n, offset + vec2(0.0, 0.5));
  }
}

// Distance from the centre to the contour: to the segment between the two
// nearest midpoints when they are neighbours on it (at most a pixel apart:
// a diagonal run's midpoints are 0.71 apart, a straight one's 1), so that
// the line keeps its width between them; else to the nearest midpoint.
float fxContourDistance(fxNearest n)
{
  vec2 along = n.second - n.first;
  float length2 = dot(along, along);
  if (n.secondDistance > 1e29 || length2 > 1.0001)
  {
    return n.firstDistance;
  }
  float t = clamp(-dot(n.first, along) / length2, 0.0, 1.0);
  return length(n.first + t * along);
}

void main()
{
  if (texCoord.x < -1.0)
  {
    discard; // never: see vtkFXToonEdgesFS
  }
  ivec2 pixel = ivec2(gl_FragCoord.xy) - fxOrigin;
  fxNearest nearest = fxNearest(vec2(0.0), vec2(0.0), 1e30, 1e30);
  for (int dy = fxWindow.x; dy <= fxWindow.y; dy += 2)
  {
    for (int dx = fxWindow.x; dx <= fxWindow.y; dx += 2)
    {
      // The 2x2 block from (dx, dy): w (dx, dy), z (dx+1, dy),
      // x (dx, dy+1), y (dx+1, dy+1).
#if FX_GATHER
      vec4 block = textureGather(fxEdges, vec2(pixel + ivec2(dx + 1, dy + 1)) / vec2(fxEdgeSize), 0);
#else
      ivec2 t = pixel + ivec2(dx, dy);
      vec4 block = vec4(texelFetch(fxEdges, t + ivec2(0, 1), 0).r,
        texelFetch(fxEdges, t + ivec2(1, 1), 0).r, texelFetch(fxEdges, t + ivec2(1, 0), 0).r,
        texelFetch(fxEdges, t, 0).r);
      // texelFetch outside the texture is undefined: no marks there.
      bvec4 outside = bvec4(t.x < 0 || t.y + 1 < 0 || t.x >= fxEdgeSize.x || t.y + 1 >= fxEdgeSize.y,
        t.x + 1 < 0 || t.y + 1 < 0 || t.x + 1 >= fxEdgeSize.x || t.y + 1 >= fxEdgeSize.y,
        t.x + 1 < 0 || t.y < 0 || t.x + 1 >= fxEdgeSize.x || t.y >= fxEdgeSize.y,
        t.x < 0 || t.y < 0 || t.x >= fxEdgeSize.x || t.y >= fxEdgeSize.y);
      block = mix(block, vec4(0.0), outside);
#endif
      if (block == vec4(0.0))
      {
        continue;
      }
      vec2 offset = vec2(dx, dy);
      fxConsiderTexel(nearest, offset, block.w);
      fxConsiderTexel(nearest, offset + vec2(1.0, 0.0), block.z);
      fxConsiderTexel(nearest, offset + vec2(0.0, 1.0), block.x);
      fxConsiderTexel(nearest, offset + vec2(1.0, 1.0), block.y);
    }
  }
  float coverage = clamp(fxHalfWidth + 0.5 - fxContourDistance(nearest), 0.0, 1.0);
  if (coverage <= 0.0)
  {
    discard;
  }
  gl_FragData[0] = vec4(fxLineColor, coverage);
}
