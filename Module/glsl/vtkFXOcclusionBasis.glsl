// vtkFXOcclusionBasis: the three directions over which
// vtkFXDirectionalOcclusionPass splits the hemisphere, shared by its
// estimator and its resolve in the composite so both use the same frame.
//
// The basis is Half-Life 2's radiosity normal-mapping basis (McTaggart,
// "Half-Life 2 / Valve Source Shading", GDC 2004), which Vizerie's 2009
// demo (seed 000) applies to screen-space occlusion: three unit vectors at
// acos(1/sqrt 3) = 54.7 degrees from the normal, 120 degrees apart around
// it, so that they are orthonormal and their squared cosines with the
// normal are 1/3 each.
#ifndef FX_OCCLUSION_BASIS
#define FX_OCCLUSION_BASIS

// Tangent frame of a view-space normal n: the rotation taking +z to n along
// the great circle through both (Frisvad 2012's construction with the sign
// fixed). Unlike a frame built from a helper axis it varies continuously
// with n everywhere except at n = -z, which visible front faces never
// have: neighbouring pixels' channels refer to nearly the same directions,
// so blurring them stays meaningful.
void fxOcclusionFrame(vec3 n, out vec3 t, out vec3 b)
{
  float k = 1.0 / max(1.0 + n.z, 1e-4);
  float xy = -n.x * n.y * k;
  t = vec3(1.0 - n.x * n.x * k, xy, -n.x);
  b = vec3(xy, 1.0 - n.y * n.y * k, -n.y);
}

// The basis in tangent coordinates: (sqrt(2/3) cos phi_k, sqrt(2/3) sin
// phi_k, 1/sqrt 3) for phi_k = 0, 120, 240 degrees.
const vec3 fxBasis0 = vec3(0.816496581, 0.0, 0.577350269);
const vec3 fxBasis1 = vec3(-0.408248290, 0.707106781, 0.577350269);
const vec3 fxBasis2 = vec3(-0.408248290, -0.707106781, 0.577350269);

// How much of direction d (unit) each channel takes: squared clamped
// cosines with the basis, normalised to sum 1 (Half-Life 2's weights).
// Every direction of the hemisphere has a positive cosine with at least one
// basis vector; below it (or for a zero vector) the weights are equal.
vec3 fxBasisWeights(vec3 d)
{
  vec3 c = max(vec3(dot(d, fxBasis0), dot(d, fxBasis1), dot(d, fxBasis2)), 0.0);
  vec3 w = c * c;
  float sum = w.x + w.y + w.z;
  return sum > 1e-12 ? w / sum : vec3(1.0 / 3.0);
}

// Weights of the three channels for a shading normal s (view space) on a
// surface of geometric normal n: s in n's tangent coordinates, then
// fxBasisWeights. For s = n they are exactly 1/3 each, so the resolve
// gives the channels' mean: plain ambient occlusion.
vec3 fxResolveWeights(vec3 n, vec3 s)
{
  vec3 t, b;
  fxOcclusionFrame(n, t, b);
  return fxBasisWeights(vec3(dot(s, t), dot(s, b), dot(s, n)));
}

// For channels that are each the visibility under the unclamped cosine
// around their basis vector over the geometric hemisphere (vtkFXSSAOPass's
// horizon method): that cosine is linear in its axis, and the basis is
// orthonormal, so the cosine around s is sum_k (b_k . s) (b_k . w), and
// with the lobes' open integrals alike (pi / sqrt 3 each) the visibility
// around s is the channels weighted by b_k . s, normalised to sum 1. For
// s = n the weights are 1/3 each: the channels' mean, the cosine-weighted
// visibility of plain ambient occlusion. Negative weights are dropped:
// exact while s lies within the basis' octant (up to 35 degrees from n),
// and beyond it a mix of the channels rather than an extrapolation, which
// grows without bound as s nears the tangent plane (the weights sum to
// sqrt 3 s . n before normalising: 84 degrees from n gave 5, -2, -2).
vec3 fxResolveWeightsLinear(vec3 n, vec3 s)
{
  vec3 t, b;
  fxOcclusionFrame(n, t, b);
  vec3 d = vec3(dot(s, t), dot(s, b), dot(s, n));
  vec3 c = max(vec3(dot(d, fxBasis0), dot(d, fxBasis1), dot(d, fxBasis2)), 0.0);
  float sum = c.x + c.y + c.z;
  return sum > 1e-6 ? c / sum : vec3(1.0 / 3.0);
}
#endif
