//VTK::System::Dec
// vtkFXAVSMResolveFS: each shadow-map texel's list of fragments becomes a
// curve of FX_NODES nodes (depth, optical depth), linear in between, after
// Salvi, Vidimce, Lauritzen, Lefohn, "Adaptive Volumetric Shadow Maps"
// (EGSR 2010; seed 003): segments are inserted in depth order, each adding
// a node where it starts (the optical depth so far) and one where it ends
// (plus its own), and while the curve has more than FX_NODES nodes the
// interior node whose removal changes the area under the transmittance
// curve exp(-tau) least (the triangle it makes with its neighbours) goes.
// A surface is a segment of zero thickness: a vertical step, so up to
// FX_NODES / 2 surfaces per texel are kept exactly.
// Order independence: the FX_MAX_LIST (the frame's longest list, up to 64)
// nearest fragments (by depth, then
// optical depth) are kept sorted and inserted in that order, so the curve does not depend
// on the order fragments arrived in; fragments beyond them are summed into
// one last segment from the nearest to the farthest of them (exact past
// it). Optical depth is summed, capped at 1e4 (transmittance 0 in float).
// Output: FX_NODES / 4 targets of depths, then FX_NODES / 4 of optical
// depths; unused nodes have depth 3e38 and the last optical depth.

//VTK::FXAVSMLists::Dec

in vec2 texCoord;
uniform vec2 fxSliceRange; // FX_SLICES: the casters' light depths, near and far

//VTK::Output::Dec

// Local arrays are indexed with loop counters only (constant after
// unrolling); list walks take the same number of steps for every pixel
// (see fxAVSMWalk in vtkFXAVSMLists.glsl).
float fxZ[FX_NODES + 1];
float fxTau[FX_NODES + 1];
int fxCount = 0;

// Exp(-tau) of a node: the transmittance the area rule weighs.
float fxT(float tau)
{
  return exp(-tau);
}

void fxInsert(float z, float tau)
{
  for (int i = 0; i <= FX_NODES; ++i)
  {
    if (i == fxCount)
    {
      fxZ[i] = z;
      fxTau[i] = tau;
    }
  }
  ++fxCount;
  if (fxCount <= FX_NODES)
  {
    return;
  }
  // Full: the interior node whose removal changes the area under the
  // transmittance curve least (the triangle with its neighbours) goes.
  int victim = 1;
  float smallest = 3e38;
  for (int i = 1; i < FX_NODES; ++i)
  {
    float area = abs((fxZ[i] - fxZ[i - 1]) * (fxT(fxTau[i + 1]) - fxT(fxTau[i - 1])) -
      (fxT(fxTau[i]) - fxT(fxTau[i - 1])) * (fxZ[i + 1] - fxZ[i - 1]));
    if (area < smallest)
    {
      smallest = area;
      victim = i;
    }
  }
  for (int i = 1; i < FX_NODES; ++i)
  {
    if (i >= victim)
    {
      fxZ[i] = fxZ[i + 1];
      fxTau[i] = fxTau[i + 1];
    }
  }
  fxCount = FX_NODES;
}

// (a, b) before (c, d): by depth, then by optical depth.
bool fxBefore(float a, float b, float c, float d)
{
  return a < c || (a == c && b < d);
}

void main()
{
  if (texCoord.x < -1.0)
  {
    discard; // never: keeps texCoord in the program
  }
  ivec2 texel = ivec2(gl_FragCoord.xy);
  uint node = fxAVSMHeads[texel.y * fxAVSMSize + texel.x];
  if (node == fxAVSMEnd)
  {
    // Nothing here (most of a map): an empty curve, at once.
    //VTK::FXAVSMResolve::Empty
    return;
  }
#if FX_SLICES
  // An opacity shadow map instead (Kim and Neumann, "Opacity Shadow Maps",
  // EGWR 2001), for comparison at equal memory: FX_SLICES regular slices
  // of the casters' light depth range fxSliceRange, each holding the
  // optical depth accumulated up to its far side. Order independent: sums.
  float bins[FX_SLICES];
  for (int k = 0; k < FX_SLICES; ++k)
  {
    bins[k] = 0.0;
  }
  for (int step = 0; step < fxAVSMWalk; ++step)
  {
    if (node != fxAVSMEnd && node < uint(fxAVSMCapacity))
    {
      float x = (fxAVSMNodes[node].depth - fxSliceRange.x) /
        max(fxSliceRange.y - fxSliceRange.x, 1e-30) * float(FX_SLICES);
      int slice = int(clamp(floor(x), 0.0, float(FX_SLICES - 1)));
      float t = fxAVSMNodes[node].opticalDepth;
      node = fxAVSMNodes[node].next;
      for (int k = 0; k < FX_SLICES; ++k)
      {
        bins[k] = k == slice ? min(bins[k] + t, 1e4) : bins[k];
      }
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
  // The FX_MAX_LIST nearest fragments, kept sorted as they come (each new
  // one bubbles to its place; what falls off the end is the farthest):
  // empty slots hold depth 3e38.
  float depth[FX_MAX_LIST];
  float tau[FX_MAX_LIST];
  for (int i = 0; i < FX_MAX_LIST; ++i)
  {
    depth[i] = 3e38;
    tau[i] = 0.0;
  }
  int n = 0;
  float droppedTau = 0.0;
  float droppedNear = 3e38;
  float droppedFar = -3e38;
  for (int step = 0; step < fxAVSMWalk; ++step)
  {
    if (node == fxAVSMEnd || node >= uint(fxAVSMCapacity))
    {
      continue; // past the end: nothing (see fxAVSMWalk)
    }
    float d = fxAVSMNodes[node].depth;
    float t = fxAVSMNodes[node].opticalDepth;
    node = fxAVSMNodes[node].next;
    // Full, and no nearer than the farthest kept: dropped at once (a list
    // arrives farthest-last when drawn back to front; a loop per fragment
    // would cost 64 steps, and llvmpipe stops a shader's loops after
    // 65535 iterations).
    if (n == FX_MAX_LIST && !fxBefore(d, t, depth[FX_MAX_LIST - 1], tau[FX_MAX_LIST - 1]))
    {
      droppedTau = min(droppedTau + t, 1e4);
      droppedNear = min(droppedNear, d);
      droppedFar = max(droppedFar, d);
      continue;
    }
    for (int i = 0; i < FX_MAX_LIST; ++i)
    {
      if (fxBefore(d, t, depth[i], tau[i]))
      {
        float swapD = depth[i];
        float swapT = tau[i];
        depth[i] = d;
        tau[i] = t;
        d = swapD;
        t = swapT;
      }
    }
    if (n < FX_MAX_LIST)
    {
      ++n; // an empty slot fell off
    }
    else
    {
      droppedTau = min(droppedTau + t, 1e4);
      droppedNear = min(droppedNear, d);
      droppedFar = max(droppedFar, d);
    }
  }
  float sum = 0.0;
  for (int i = 0; i < FX_MAX_LIST; ++i)
  {
    if (i < n)
    {
      fxInsert(depth[i], sum);
      sum = min(sum + tau[i], 1e4);
      fxInsert(depth[i], sum);
    }
  }
  if (droppedTau > 0.0)
  {
    fxInsert(droppedNear, sum);
    sum = min(sum + droppedTau, 1e4);
    fxInsert(droppedFar, sum);
  }
  for (int i = 0; i < FX_NODES; ++i)
  {
    if (i >= fxCount)
    {
      fxZ[i] = 3e38;
      fxTau[i] = sum;
    }
  }
  //VTK::FXAVSMResolve::Output
}
