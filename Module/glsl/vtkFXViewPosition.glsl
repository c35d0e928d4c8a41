// vtkFXViewPosition: the view-space position of the surface seen through a
// point of the image at linear depth `depth`,
//   P = origin(ndc) + depth * direction(ndc),
// with origin and direction affine in the point's normalized device
// coordinates (vtkFXRenderUtilities::SetFrustumRayUniforms; the "frustum
// corner ray" reconstruction of Crytek's SSAO, Mittring 2007). No world
// position is stored: it would lose precision far from the origin.
uniform vec3 fxRayOrigin[3];
uniform vec3 fxRayDirection[3];
// 0 in perspective projection; in parallel projection, the distance at
// which VTK's default view angle (30 degrees) spans the parallel view: the
// camera's own angle changes nothing in a parallel image, so it must not
// change the tolerances either.
uniform float fxParallelDepth;

// The depth that scales a tolerance relative to depth at a surface at depth
// d: d itself in perspective projection, where a pixel's footprint grows
// with it; in parallel projection, where the footprint is the same at every
// depth, fxParallelDepth, so that moving the camera back, which leaves the
// image as it is, leaves the tolerance too (relative to d, a blur's depth
// tolerance outgrew the scene from 1000 times the distance, and occlusion
// bled across every silhouette).
float fxToleranceDepth(float d)
{
  return fxParallelDepth > 0.0 ? fxParallelDepth : d;
}

// Normalized device coordinates of the centre of texel `texel` of an image
// of `size` texels.
vec2 fxTexelNdc(ivec2 texel, ivec2 size)
{
  return (vec2(texel) + 0.5) / vec2(size) * 2.0 - 1.0;
}

void fxRay(vec2 ndc, out vec3 origin, out vec3 direction)
{
  origin = fxRayOrigin[0] + ndc.x * fxRayOrigin[1] + ndc.y * fxRayOrigin[2];
  direction = fxRayDirection[0] + ndc.x * fxRayDirection[1] + ndc.y * fxRayDirection[2];
}

vec3 fxViewPosition(vec2 ndc, float depth)
{
  vec3 origin, direction;
  fxRay(ndc, origin, direction);
  return origin + depth * direction;
}

// Linear depths at which the rays through a pixel's neighbours meet the
// plane with normal n0 through the surface the pixel sees at depth d0 (a
// receiver's tangent plane). The
// bilateral filters compare a neighbour's depth with this rather than with
// the receiver's own depth: on a surface seen at a grazing angle the depth
// changes fast from pixel to pixel while the plane predicts it, and across
// a crease, where depth is continuous, the neighbour leaves the plane (as
// the slope-adjusted depth edges of Intel's XeGTAO denoiser do, from the
// depth's screen-space slope). Ray origin and direction are affine in ndc,
// so the depth at the neighbour offset by (dx, dy) pixels from the one at
// `ndc`, pixels being `ndcStep` apart, is dot(a, v) / dot(b, v) with
// v = (1, dx, dy): fxPlaneDepthRatio computes a and b once per pixel,
// fxPlaneDepthAt evaluates them per neighbour. (The pixel's own point is
// origin + d0 direction, so a.x = d0 b.x, and the plane gives back d0 at
// the pixel exactly.)
void fxPlaneDepthRatio(vec3 n0, float d0, vec2 ndc, vec2 ndcStep, out vec3 a, out vec3 b)
{
  vec3 direction = fxRayDirection[0] + ndc.x * fxRayDirection[1] + ndc.y * fxRayDirection[2];
  b = vec3(dot(n0, direction), dot(n0, fxRayDirection[1]) * ndcStep.x,
    dot(n0, fxRayDirection[2]) * ndcStep.y);
  a = vec3(d0 * b.x, -dot(n0, fxRayOrigin[1]) * ndcStep.x, -dot(n0, fxRayOrigin[2]) * ndcStep.y);
}

// How far depth d is from agreeing with a pixel at depth d0 whose tangent
// plane has depth e there: the nearer of the two. The plane keeps a
// crease's sides apart and follows a surface seen at a grazing angle; the
// pixel's own depth keeps a curved surface's neighbours at its silhouette,
// where the tangent plane runs along the view rays and leaves them (alone
// there, the raw estimate of a pixel on the corner's sphere outline showed
// as a dark dot).
float fxPlaneGap(float d, float e, float d0)
{
  return min(abs(d - e), abs(d - d0));
}
vec4 fxPlaneGap(vec4 d, vec4 e, float d0)
{
  return min(abs(d - e), abs(d - d0));
}

// The plane's depth at offset (dx, dy), or `fallback` where the plane is
// not in front of the eye there (ray parallel to it, plane behind, or a
// normal that is not one: a 0 normal gives the fallback everywhere).
float fxPlaneDepthAt(vec3 a, vec3 b, vec2 offset, float fallback)
{
  vec3 v = vec3(1.0, offset);
  float facing = dot(b, v);
  float t = dot(a, v) / facing;
  return abs(facing) > 1e-8 && t > 0.0 && t < 3.0e38 ? t : fallback;
}
