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
// Order independence: the FX_MAX_LIST nearest fragments (by depth, then
// optical depth) are sorted before insertion, so the curve does not depend
// on the order fragments arrived in; fragments beyond them are summed into
// one last segment from the nearest to the farthest of them (exact past
// it). Optical depth is summed, capped at 1e4 (transmittance 0 in float).
// Output: FX_NODES / 4 targets of depths, then FX_NODES / 4 of optical
// depths; unused nodes have depth 3e38 and the last optical depth.

//VTK::FXAVSMLists::Dec

in vec2 texCoord;

//VTK::Output::Dec

float fxZ[FX_NODES + 1];
float fxTau[FX_NODES + 1];
int fxCount = 0;

// Exp(-tau) of node i: the transmittance the area rule weighs.
float fxT(int i)
{
  return exp(-fxTau[i]);
}

void fxInsert(float z, float tau)
{
  fxZ[fxCount] = z;
  fxTau[fxCount] = tau;
  ++fxCount;
  if (fxCount <= FX_NODES)
  {
    return;
  }
  int victim = 1;
  float smallest = 3e38;
  for (int i = 1; i + 1 < fxCount; ++i)
  {
    float area = abs((fxZ[i] - fxZ[i - 1]) * (fxT(i + 1) - fxT(i - 1)) -
      (fxT(i) - fxT(i - 1)) * (fxZ[i + 1] - fxZ[i - 1]));
    if (area < smallest)
    {
      smallest = area;
      victim = i;
    }
  }
  for (int i = victim; i + 1 < fxCount; ++i)
  {
    fxZ[i] = fxZ[i + 1];
    fxTau[i] = fxTau[i + 1];
  }
  --fxCount;
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
    discard; // never: keeps texCoord, which the quad binds, in the program
  }
  ivec2 texel = ivec2(gl_FragCoord.xy);
  float depth[FX_MAX_LIST];
  float tau[FX_MAX_LIST];
  int n = 0;
  float droppedTau = 0.0;
  float droppedNear = 3e38;
  float droppedFar = -3e38;
  uint node = fxAVSMHeads[texel.y * fxAVSMSize + texel.x];
  for (int guard = 0; node != fxAVSMEnd && node < uint(fxAVSMCapacity) && guard < 1000000; ++guard)
  {
    float d = fxAVSMNodes[node].depth;
    float t = fxAVSMNodes[node].opticalDepth;
    node = fxAVSMNodes[node].next;
    if (n < FX_MAX_LIST)
    {
      depth[n] = d;
      tau[n] = t;
      ++n;
      continue;
    }
    // Full: keep the nearest; the farthest kept one, or this one, drops.
    int far = 0;
    for (int i = 1; i < FX_MAX_LIST; ++i)
    {
      far = fxBefore(depth[far], tau[far], depth[i], tau[i]) ? i : far;
    }
    if (fxBefore(d, t, depth[far], tau[far]))
    {
      float swapD = depth[far];
      float swapT = tau[far];
      depth[far] = d;
      tau[far] = t;
      d = swapD;
      t = swapT;
    }
    droppedTau = min(droppedTau + t, 1e4);
    droppedNear = min(droppedNear, d);
    droppedFar = max(droppedFar, d);
  }
  // Insertion sort: lists are short.
  for (int i = 1; i < n; ++i)
  {
    float d = depth[i];
    float t = tau[i];
    int j = i - 1;
    while (j >= 0 && fxBefore(d, t, depth[j], tau[j]))
    {
      depth[j + 1] = depth[j];
      tau[j + 1] = tau[j];
      --j;
    }
    depth[j + 1] = d;
    tau[j + 1] = t;
  }
  float sum = 0.0;
  for (int i = 0; i < n; ++i)
  {
    fxInsert(depth[i], sum);
    sum = min(sum + tau[i], 1e4);
    fxInsert(depth[i], sum);
  }
  if (droppedTau > 0.0)
  {
    fxInsert(droppedNear, sum);
    sum = min(sum + droppedTau, 1e4);
    fxInsert(droppedFar, sum);
  }
  for (int i = fxCount; i < FX_NODES; ++i)
  {
    fxZ[i] = 3e38;
    fxTau[i] = sum;
  }
  //VTK::FXAVSMResolve::Output
}
