// vtkFXAVSMLists: the per-texel fragment lists of vtkFXAVSMPass's capture
// (the linked lists of order-independent transparency, Yang et al., "Real-
// time concurrent linked list construction on the GPU", EGSR 2010, as the
// AVSM demo of seed 003 captures its blockers). Shared by the capture (in
// VTK's mapper shaders), the resolve and the exact look-up.
// Each fragment keeps its light-space depth and its optical depth
// tau = -ln(1 - opacity): products of transmittances become sums, which
// do not underflow (1000 layers of opacity 0.9999 sum to 9210, not 1e-4000).
struct fxAVSMNode
{
  float depth;
  float opticalDepth;
  uint next;   // index of the next node, 0xFFFFFFFF at the end
  uint unused;
};
layout(std430) buffer FXAVSMHeads
{
  uint fxAVSMHeads[];
};
layout(std430) buffer FXAVSMNodes
{
  fxAVSMNode fxAVSMNodes[];
};
layout(std430) buffer FXAVSMCounter
{
  uint fxAVSMNodeCount;   // every fragment counts, stored or not
  uint fxAVSMLongestList; // the longest list stored
};
layout(std430) buffer FXAVSMCounts
{
  uint fxAVSMCounts[]; // nodes stored per texel
};
uniform int fxAVSMSize;     // shadow map texels per side
uniform int fxAVSMCapacity; // nodes the buffer holds
// Steps of every list walk: the longest list of the frame, the same for
// all pixels. A walk that stopped at its own list's end (a loop whose exit
// differs between neighbouring pixels) went wrong on llvmpipe for pixels
// along a primitive's inner edge; walks step fxAVSMWalk times and do
// nothing past the end.
uniform int fxAVSMWalk;
const uint fxAVSMEnd = 0xFFFFFFFFu;
