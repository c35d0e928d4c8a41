// vtkFXReferenceAO: ray-traced ambient occlusion (Embree) of a renderer's
// scene, the ground truth against which vtkfx-bench measures screen-space
// occlusion.
//
// For each pixel, a primary ray through the pixel centre finds the visible
// surface and its geometric normal (faced towards the viewer); from it,
// RaysPerPixel cosine-distributed rays (stratified on a square grid, jittered
// by a per-pixel hash: deterministic) look for the nearest hit within the
// radius R. The occlusion of a ray that hits at distance t is
//   Binary:   f(t) = 1 (any hit within R: OSPRay's aoDistance, Blender), or
//   CubeRoot: f(t) = 1 - (t / R)^(1/3) (what sample lengths u^3 estimate),
// as vtkFXSSAOPass::Falloff chooses, and the pixel's value is 1 - mean f. Pixels whose primary ray misses hold
// -1 (no surface).
// Directional occlusion (vtkFXDirectionalOcclusionPass) is traced with a
// shading normal per pixel: the rays are cosine-distributed around it and
// those below the geometric surface (w . n_g <= 0) are left out, so the
// value is the visibility weighted by max(0, n_s . w) over the geometric
// hemisphere, normalised by that weight's integral there.
//
// Geometry: triangles of every visible vtkActor whose mapper is a
// vtkPolyDataMapper (its input, through the actor's matrix) or a
// vtkCompositePolyDataMapper2 (its leaves), and the spheres and sticks of a
// vtkMoleculeMapper (ball-and-stick radii). Other props are left out.
#ifndef vtkFXReferenceAO_h
#define vtkFXReferenceAO_h

#include <memory>
#include <string>
#include <vector>

class vtkMatrix4x4;
class vtkRenderer;

class vtkFXReferenceAO
{
public:
  vtkFXReferenceAO();
  ~vtkFXReferenceAO();

  /**
   * Builds the ray-tracing scene from the renderer's visible actors, in
   * world coordinates. Returns false (with a message) when nothing usable
   * is found or Embree fails.
   */
  bool Build(vtkRenderer* renderer, std::string& error);

  /**
   * The visible props the last Build could not trace (their mapper's or
   * their own class name; e.g. glyph and point-sprite mappers, volumes):
   * figures measured against the reference leave them out.
   */
  const std::vector<std::string>& GetSkippedProps() const { return this->Skipped; }

  struct Result
  {
    int Width = 0;
    int Height = 0;
    std::vector<float> Occlusion;     // 1 = open, -1 = no surface; rows bottom-up
    // Per pixel, sqrt(variance of the rays' values / rays counted): the
    // standard error of an unstratified mean, an upper bound for the
    // stratified one traced here.
    std::vector<float> StandardError;
    double StandardErrorRMS = 0.0;    // RMS over covered pixels of StandardError
    int CoveredPixels = 0;
    double Seconds = 0.0;
  };

  enum Falloff
  {
    Binary = 0, // the values of vtkFXSSAOPass::Falloff
    CubeRoot
  };

  /**
   * Traces the renderer's current view at width x height pixels with the
   * given radius (world units), rays per pixel (rounded up to a square) and
   * falloff (Binary or CubeRoot; another value is reported and traced as
   * Binary).
   */
  Result Trace(vtkRenderer* renderer, int width, int height, double radius, int raysPerPixel,
    int falloff = Binary, int threads = 2,
    const std::vector<float>* shadingNormals = nullptr) const;
  // shadingNormals: 3 world-space values per pixel (rows bottom-up), or
  // nullptr for ambient occlusion; a zero vector there means "the
  // geometric normal".

  /**
   * World-space ray through the centre of pixel (x, y) of a width x height
   * view, from the inverse of the camera's composite projection (double
   * precision; any projection). `direction` is unit length.
   */
  static void PixelRay(vtkMatrix4x4* inverseProjection, int x, int y, int width, int height,
    double origin[3], double direction[3]);

  /**
   * One bounce of diffuse light within the radius (the reference of
   * vtkFXDirectionalOcclusionPass's bleeding): per pixel, the mean over
   * cosine-distributed rays around the geometric normal of the albedo of
   * what a ray hits before R (its actor's diffuse colour x Diffuse; scalar
   * colours and textures are not seen) times that point's direct diffuse
   * light, unshadowed, from the renderer's lights as VTK's Phong model
   * applies them. RGB per pixel, rows bottom-up; -1 where no surface is.
   */
  std::vector<float> TraceBleeding(vtkRenderer* renderer, int width, int height, double radius,
    int raysPerPixel, int threads = 2) const;

private:
  std::vector<std::string> Skipped;
  struct Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
