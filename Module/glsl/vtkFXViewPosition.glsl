// vtkFXViewPosition: the view-space position of the surface seen through a
// point of the image at linear depth `depth`,
//   P = origin(ndc) + depth * direction(ndc),
// with origin and direction affine in the point's normalized device
// coordinates (vtkFXRenderUtilities::SetFrustumRayUniforms; the "frustum
// corner ray" reconstruction of Crytek's SSAO, Mittring 2007). No world
// position is stored: it would lose precision far from the origin.
uniform vec3 fxRayOrigin[3];
uniform vec3 fxRayDirection[3];

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
