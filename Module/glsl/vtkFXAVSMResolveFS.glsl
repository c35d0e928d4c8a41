//VTK::System::Dec
// vtkFXAVSMResolveFS: each shadow-map texel's list of segments becomes a
// curve of FX_NODES nodes (depth, optical depth), linear in between, after
// Salvi, Vidimce, Lauritzen, Lefohn, "Adaptive Volumetric Shadow Maps"
// (EGSR 2010; seed 003): segments are inserted in order of entry depth,
// each adding a node where it enters (the curve's optical depth there) and
// one where it exits (plus its own), and raising the nodes it covers by
// its share (uniform density: linear); while the curve has more than
// FX_NODES nodes, the interior node whose removal changes the area under
// the transmittance curve exp(-tau) least (the triangle it makes with its
// neighbours) goes. A surface is a segment of zero thickness: a vertical
// step, so up to FX_NODES / 2 segments per texel are kept exactly.
// Order independence: the segments are inserted in order (of entry depth,
// then optical depth, then exit depth; equal ones together), so the curve
// does not depend on the order fragments arrived in; past the first
// FX_MAX_LIST (fewer for lists over 1764 segments: the rounds stay within
// llvmpipe's loop budget, see below), the rest are summed into one last
// segment from the nearest entry to the farthest exit among them (exact
// past it). Optical depth is summed, capped at 1e4 (transmittance 0
// in float).
// Output: FX_NODES / 4 targets of depths, then FX_NODES / 4 of optical
// depths; unused nodes have depth 3e38 and the last optical depth.

//VTK::FXAVSMLists::Dec

// FX_SLICES: each view's casters' light depths, near and far; the views
// are squares of fxViewSize texels, FX_ATLAS_COLUMNS to a row.
uniform vec2 fxViewSliceRange[FX_VIEWS];
uniform int fxViewSize;

//VTK::Output::Dec

// Local arrays are indexed with loop counters only (constant after
// unrolling). A segment adds two nodes before the curve is trimmed back to
// FX_NODES. The area rule weighs transmittance: fxTr holds exp(-fxTau),
// computed only before a trim (fxTrimCurve).
float fxZ[FX_NODES + 2];
float fxTau[FX_NODES + 2];
float fxTr[FX_NODES + 2];
int fxCount = 0;

// Where depth z falls on the curve: the last node at or before it (low)
// and the one after (high), read by fxTrack during an ascending walk of
// the nodes, so that fxValueAt divides once per depth, not once per node.
struct fxBracket
{
  float lowZ;
  float lowTau;
  float highZ;
  float highTau;
  bool between; // a node after low exists
};

fxBracket fxNoBracket()
{
  return fxBracket(0.0, 0.0, 0.0, 0.0, false);
}

void fxTrack(inout fxBracket b, float z, int i, int next)
{
  if (fxZ[i] <= z)
  {
    b = fxBracket(fxZ[i], fxTau[i], fxZ[next], fxTau[next], i + 1 < fxCount && fxZ[next] > z);
  }
}

// The curve's optical depth at z: 0 before the first node, the last
// node's past the last, linear in between.
float fxValueAt(fxBracket b, float z)
{
  return b.between ? mix(b.lowTau, b.highTau, (z - b.lowZ) / (b.highZ - b.lowZ)) : b.lowTau;
}

float fxCurveAt(float z)
{
  fxBracket b = fxNoBracket();
  for (int i = 0; i < FX_NODES + 2; ++i)
  {
    if (i < fxCount)
    {
      fxTrack(b, z, i, min(i + 1, FX_NODES + 1));
    }
  }
  return fxValueAt(b, z);
}

// A segment's two nodes, entry <= exit, each after the nodes at or before
// its depth, in one pass from the end down: nodes past the exit move up
// two, nodes between entry and exit one. Every array index is a constant
// once the loop is unrolled: node i reads itself and nodes i - 1 and
// i - 2 and selects, where it used to read the node at an index chosen
// at run time, which cost the particles' resolve 15-20% more on llvmpipe
// (an array indexed at run time cannot be kept in registers).
void fxAddNodes(float entry, float entryTau, float exitDepth, float exitTau)
{
  bool exitPlaced = false;
  bool entryPlaced = false;
  for (int i = FX_NODES + 1; i >= 0; --i)
  {
    int one = max(i - 1, 0);
    int two = max(i - 2, 0);
    bool moves = !entryPlaced && i <= fxCount + 1;
    bool placeExit = moves && !exitPlaced && !(i >= 2 && fxZ[two] > exitDepth);
    bool placeEntry = moves && exitPlaced && !(i >= 1 && fxZ[one] > entry);
    bool fromTwo = moves && !exitPlaced && !placeExit;
    bool fromOne = moves && exitPlaced && !placeEntry;
    float z = fromTwo ? fxZ[two] : (fromOne ? fxZ[one] : fxZ[i]);
    float tau = fromTwo ? fxTau[two] : (fromOne ? fxTau[one] : fxTau[i]);
    fxZ[i] = placeExit ? exitDepth : (placeEntry ? entry : z);
    fxTau[i] = placeExit ? exitTau : (placeEntry ? entryTau : tau);
    exitPlaced = exitPlaced || placeExit;
    entryPlaced = entryPlaced || placeEntry;
  }
  fxCount += 2;
}

// The interior node whose removal changes the area under the transmittance
// curve least (the triangle with its neighbours) goes.
void fxRemoveNode()
{
  int victim = 1;
  float smallest = 3e38;
  for (int i = 1; i < FX_NODES + 1; ++i)
  {
    if (i + 1 < fxCount)
    {
      float area = abs((fxZ[i] - fxZ[i - 1]) * (fxTr[i + 1] - fxTr[i - 1]) -
        (fxTr[i] - fxTr[i - 1]) * (fxZ[i + 1] - fxZ[i - 1]));
      if (area < smallest)
      {
        smallest = area;
        victim = i;
      }
    }
  }
  for (int i = 1; i < FX_NODES + 1; ++i)
  {
    if (i >= victim)
    {
      fxZ[i] = fxZ[i + 1];
      fxTau[i] = fxTau[i + 1];
      fxTr[i] = fxTr[i + 1];
    }
  }
  --fxCount;
}

// Back to FX_NODES nodes. Loops, not ifs, around the work: llvmpipe runs
// both sides of an if for a group of pixels whatever their values, but
// ends a loop when no pixel of the group needs another turn, so a group
// whose curves all still fit (the first FX_NODES / 2 segments of a texel)
// pays neither the exponentials nor the search (the particles' resolve,
// 1024^2 map: 157, 186 and 226 ms to 154, 182 and 213 for 4, 8 and 16
// nodes; most groups hold some texel whose curve is full).
void fxTrimCurve()
{
  for (int once = 0; once < min(fxCount - FX_NODES, 1); ++once)
  {
    for (int i = 0; i < FX_NODES + 2; ++i)
    {
      fxTr[i] = exp(-fxTau[i]);
    }
  }
  int excess = fxCount - FX_NODES;
  for (int k = 0; k < excess; ++k)
  {
    fxRemoveNode();
  }
}

// Seed 003's insertion of a segment into the curve: nodes where it enters
// and exits (the curve's value there before, plus all of the segment at
// the exit), its share added to every node it reaches (all of it past the
// exit). One pass reads the old curve at both ends and adds the shares:
// nodes i and i + 1 are read before node i changes.
void fxInsertSegment(float entry, float exitDepth, float tau)
{
  fxBracket atEntry = fxNoBracket();
  fxBracket atExit = fxNoBracket();
  for (int i = 0; i < FX_NODES + 2; ++i)
  {
    if (i < fxCount)
    {
      int next = min(i + 1, FX_NODES + 1);
      fxTrack(atEntry, entry, i, next);
      fxTrack(atExit, exitDepth, i, next);
      float share = fxSegmentShare(entry, exitDepth, tau, fxZ[i]);
      if (share > 0.0)
      {
        fxTau[i] = min(fxTau[i] + share, 1e4);
      }
    }
  }
  fxAddNodes(entry, fxValueAt(atEntry, entry), exitDepth,
    min(fxValueAt(atExit, exitDepth) + tau, 1e4));
  fxTrimCurve();
}

// (a, b, c) before (d, e, f): by entry depth, then optical depth, then
// exit depth.
bool fxBefore(float a, float b, float c, float d, float e, float f)
{
  return a < d || (a == d && (b < e || (b == e && c < f)));
}

// The four least segments of a walk so far, in order (unfilled: 3e38),
// and how many identical copies of each it met: component k of each.
vec4 fxPickEntry;
vec4 fxPickTau;
vec4 fxPickExit;
vec4 fxPickSame; // whole numbers, exact in float

// Componentwise fxBefore: (e, t, x) before pick k.
bvec4 fxBeforePicks(float e, float t, float x)
{
  vec4 entryBefore = vec4(lessThan(vec4(e), fxPickEntry));
  vec4 entryEqual = vec4(equal(vec4(e), fxPickEntry));
  vec4 tauBefore = vec4(lessThan(vec4(t), fxPickTau));
  vec4 tauEqual = vec4(equal(vec4(t), fxPickTau));
  vec4 exitBefore = vec4(lessThan(vec4(x), fxPickExit));
  return greaterThan(entryBefore + entryEqual * (tauBefore + tauEqual * exitBefore), vec4(0.0));
}

// Segment (e, t, x) into the picks: counted if it is one of them, else
// placed in order when it is before the last, which then drops out. In
// vector operations, without loops: llvmpipe counts every loop iteration
// of the walk that calls this against one budget (see main).
void fxPick(float e, float t, float x)
{
  bvec4 same = equal(vec4(equal(vec4(e), fxPickEntry)) * vec4(equal(vec4(t), fxPickTau)) *
      vec4(equal(vec4(x), fxPickExit)), vec4(1.0));
  if (any(same))
  {
    fxPickSame += vec4(same);
    return;
  }
  // Each pick after the segment moves down one, unless the one above is
  // after it too; the first pick after the segment takes the segment.
  bvec4 after = fxBeforePicks(e, t, x);
  bvec4 aboveAfter = bvec4(false, after.xyz);
  vec4 newEntry = mix(vec4(e), fxPickEntry.xxyz, aboveAfter);
  vec4 newTau = mix(vec4(t), fxPickTau.xxyz, aboveAfter);
  vec4 newExit = mix(vec4(x), fxPickExit.xxyz, aboveAfter);
  vec4 newSame = mix(vec4(1.0), fxPickSame.xxyz, aboveAfter);
  fxPickEntry = mix(fxPickEntry, newEntry, after);
  fxPickTau = mix(fxPickTau, newTau, after);
  fxPickExit = mix(fxPickExit, newExit, after);
  fxPickSame = mix(fxPickSame, newSame, after);
}

void main()
{
  ivec2 texel = ivec2(gl_FragCoord.xy);
  uint node = fxAVSMHeads[texel.y * fxAVSMAtlas.x + texel.x];
  if (node == fxAVSMEnd)
  {
    // Nothing here (most of a map): an empty curve, at once.
    //VTK::FXAVSMResolve::Empty
    return;
  }
  // Walks stop at the texel's own count: the draw is one point per 8x8
  // tile, or one triangle, so no primitive edge splits a 2x2 group (see
  // fxAVSMWalk in vtkFXAVSMLists.glsl); a texel pays for its own list only.
  // llvmpipe stops a shader's loops after some 65535 iterations, nested
  // loops' together (59 rounds of 1000 steps lost the tail walk after
  // them): at most 15000 segments are walked, and the rounds below and the
  // tail walk stay within 30000 steps.
  int count = min(int(fxAVSMCounts[texel.y * fxAVSMAtlas.x + texel.x]), 15000);
#if FX_SLICES
  // An opacity shadow map instead (Kim and Neumann, "Opacity Shadow Maps",
  // EGWR 2001), for comparison at equal memory: FX_SLICES regular slices
  // of the casters' light depth range in the texel's view, each holding the
  // optical depth accumulated up to its far side; a segment puts into each
  // slice the share of it the slice holds (the first and last slices reach
  // out to whatever lies before and after the range). Order independent:
  // sums.
  float bins[FX_SLICES];
  for (int k = 0; k < FX_SLICES; ++k)
  {
    bins[k] = 0.0;
  }
  vec2 range = fxViewSliceRange[min((texel.y / fxViewSize) * FX_ATLAS_COLUMNS + texel.x / fxViewSize,
    FX_VIEWS - 1)];
  float sliceWidth = max(range.y - range.x, 1e-30) / float(FX_SLICES);
  for (int step = 0; step < count; ++step)
  {
    if (node == fxAVSMEnd || node >= uint(fxAVSMCapacity))
    {
      break;
    }
    fxAVSMNode segment = fxAVSMNodes[node];
    node = segment.next;
    for (int k = 0; k < FX_SLICES; ++k)
    {
      float near = k == 0 ? -3e38 : range.x + float(k) * sliceWidth;
      float far = k == FX_SLICES - 1 ? 3e38 : range.x + float(k + 1) * sliceWidth;
      float share = fxSegmentShare(segment.depth, segment.exitDepth, segment.opticalDepth, far) -
        fxSegmentShare(segment.depth, segment.exitDepth, segment.opticalDepth, near);
      bins[k] = min(bins[k] + share, 1e4);
    }
  }
  float accumulated = 0.0;
  for (int k = 0; k < FX_SLICES; ++k)
  {
    accumulated = min(accumulated + bins[k], 1e4);
    bins[k] = accumulated;
  }
  //VTK::FXAVSMResolve::SliceOutput
  return;
#endif
  // The texel's segments in order, by selection: each round walks the
  // list once and keeps the four least segments after the last one
  // taken (fxPick; identical ones count as one, with their number), which
  // then go in in order; past `rounds` rounds, one last walk sums the rest
  // into one segment. No list in local memory: about count^2 / 4 reads of
  // the texel's own list.
  uint head = node;
  float lastEntry = -3e38;
  float lastTau = -3e38;
  float lastExit = -3e38;
  int taken = 0;
  int rounds = min((FX_MAX_LIST + 3) / 4, 30000 / max(count, 1) - 1);
  for (int round = 0; round <= FX_MAX_LIST; ++round)
  {
    if (taken >= count)
    {
      break;
    }
    bool rest = round >= rounds; // the tail: sums instead of the least
    fxPickEntry = vec4(3e38);
    fxPickTau = vec4(3e38);
    fxPickExit = vec4(3e38);
    fxPickSame = vec4(0.0);
    float restTau = 0.0;
    float restNear = 3e38;
    float restFar = -3e38;
    node = head;
    for (int step = 0; step < count; ++step)
    {
      if (node == fxAVSMEnd || node >= uint(fxAVSMCapacity))
      {
        break;
      }
      fxAVSMNode segment = fxAVSMNodes[node];
      node = segment.next;
      if (!fxBefore(lastEntry, lastTau, lastExit, segment.depth, segment.opticalDepth,
            segment.exitDepth))
      {
        continue; // taken already
      }
      if (rest)
      {
        restTau = min(restTau + segment.opticalDepth, 1e4);
        restNear = min(restNear, segment.depth);
        restFar = max(restFar, segment.exitDepth);
      }
      else
      {
        fxPick(segment.depth, segment.opticalDepth, segment.exitDepth);
      }
    }
    if (rest)
    {
      if (restTau > 0.0)
      {
        fxInsertSegment(restNear, restFar, restTau);
      }
      break;
    }
    if (fxPickSame[0] == 0.0)
    {
      break; // the list was shorter than its count (never)
    }
    for (int k = 0; k < 4; ++k)
    {
      if (fxPickSame[k] > 0.0)
      {
        fxInsertSegment(fxPickEntry[k], fxPickExit[k], min(fxPickTau[k] * fxPickSame[k], 1e4));
        taken += int(fxPickSame[k]);
        lastEntry = fxPickEntry[k];
        lastTau = fxPickTau[k];
        lastExit = fxPickExit[k];
      }
    }
  }
  float total = fxCurveAt(3e38);
  for (int i = 0; i < FX_NODES; ++i)
  {
    if (i >= fxCount)
    {
      fxZ[i] = 3e38;
      fxTau[i] = total;
    }
  }
  //VTK::FXAVSMResolve::Output
}
