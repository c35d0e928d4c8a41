// vtkFXAVSMLists: the per-texel fragment lists of vtkFXAVSMPass's capture
// (the linked lists of order-independent transparency, Yang et al., "Real-
// time concurrent linked list construction on the GPU", EGSR 2010, as the
// AVSM demo of seed 003 captures its blockers). Shared by the capture (in
// VTK's mapper shaders), the resolve and the exact look-up.
// Each fragment is a segment along the light ray: where it starts and
// ends in light depth (the same for a surface; the chord through a
// point-gaussian splat's sphere otherwise) and its optical depth
// tau = -ln(transmittance across it), spread evenly over its length (a
// uniform density, seed 003's segments): products of transmittances
// become sums, which do not underflow (1000 layers of opacity 0.9999 sum
// to 9210, not 1e-4000).
struct fxAVSMNode
{
  float depth;        // entry
  float opticalDepth;
  uint next;          // index of the next node, 0xFFFFFFFF at the end
  float exitDepth;    // >= depth
};

// The part of a segment's optical depth in front of light depth z: all of
// it past the exit, a linear share inside (uniform density), none before
// the entry (a surface at exactly z does not count).
float fxSegmentShare(float entry, float exitDepth, float tau, float z)
{
  if (exitDepth > entry)
  {
    return tau * clamp((z - entry) / (exitDepth - entry), 0.0, 1.0);
  }
  return entry < z ? tau : 0.0;
}
layout(std430) buffer FXAVSMHeads
{
  uint fxAVSMHeads[];
};
layout(std430) buffer FXAVSMNodes
{
  fxAVSMNode fxAVSMNodes[];
};
// A fragment takes its node's slot from one of fxAVSMNodeCounters
// counters, each on a cache line of its own (16 words apart), chosen by
// the fragment's 64 x 64-pixel tile (smaller in small shadow maps:
// fxAVSMCounterTileShift): llvmpipe rasterises a tile per thread
// and hands out tiles in raster order, so neighbouring tiles, the ones its
// threads run at the same time, use different counters. With one counter
// the threads fought over its cache line at every fragment (the capture of
// scene:particles at 1024^2, the bench's seven settings, took 30-38 ms,
// 20-27 with eight counters, in back-to-back runs). With n counters in use,
// counter k hands out slots k, k + n, k + 2n, ...: the slots asked for
// span about n times the busiest counter's count (vtkFXAVSMPass reads them
// all back, and goes back to one counter for captures whose fragments
// crowd into a few tiles, where the span would reach n times the
// fragments).
const uint fxAVSMNodeCounters = 8u;
layout(std430) buffer FXAVSMCounter
{
  uint fxAVSMNodeCounts[16u * fxAVSMNodeCounters]; // counter k at word 16 k: its fragments, stored or not
  // (the longest list on a cache line of its own too: every fragment reads
  // it while others count)
  uint fxAVSMLongestList; // the longest list stored
};

// The slot of a new node for the fragment at window position `pixel`, or
// 0xFFFFFFFF, past any capacity, once its counter has run past what 32
// bits index (rather than wrapping round onto slots in use).
uniform int fxAVSMCounterTileShift; // log2 of the tiles' side: 6, less in small atlases
uniform int fxAVSMCountersInUse;    // 1..fxAVSMNodeCounters (vtkFXAVSMPass::ChooseNodeCounters)
uint fxAVSMNewSlot(ivec2 pixel)
{
  uint n = uint(clamp(fxAVSMCountersInUse, 1, int(fxAVSMNodeCounters)));
  ivec2 tile = pixel >> fxAVSMCounterTileShift;
  uint k = uint(tile.x + 3 * tile.y) % n;
  uint taken = atomicAdd(fxAVSMNodeCounts[16u * k], 1u);
  return taken < 0xFFFFFFFFu / n ? taken * n + k : 0xFFFFFFFFu;
}
layout(std430) buffer FXAVSMCounts
{
  uint fxAVSMCounts[]; // nodes stored per texel
};
uniform ivec2 fxAVSMAtlas;  // texels of the atlas of light views (lists are per texel)
uniform int fxAVSMCapacity; // nodes the buffer holds
// Steps of the list walks drawn over meshes (the exact look-up of
// translucent receivers): the longest list of the frame, the same for all
// pixels. A walk that stopped at its own list's end (a loop whose exit
// differs between neighbouring pixels) went wrong on llvmpipe for pixels
// along a primitive's inner edge; such walks step fxAVSMWalk times and do
// nothing past the end. The resolve, drawn as one point per tile (or one
// triangle over the map), has no inner edge and stops at the texel's own
// count (fxAVSMCounts).
uniform int fxAVSMWalk;
const uint fxAVSMEnd = 0xFFFFFFFFu;
