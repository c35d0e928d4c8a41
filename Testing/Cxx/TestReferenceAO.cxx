// The ray-traced reference (vtkFXReferenceAO) against closed forms: a point
// on a floor at distance h from an infinite wall. A cosine-distributed ray
// w hits the wall at t = h / w.x (w.x > 0), and
//   A(h) = 1 - (1/pi) Int_{w.x > 0, t < R} f(t) cos(theta) dw,
// for both falloffs: Binary (f = 1; exact: one minus a disk segment over
// pi) and CubeRoot (f(t) = 1 - (t/R)^(1/3); midpoint rule on (theta, phi)),
// independently of Embree. On a tiny image of a floor and a wall, every
// traced pixel on the floor agrees with A(h) of its distance to the wall
// within 4 standard errors (plus 2e-3 for the quadrature and the pixel's
// footprint), pixels farther than R from the wall are exactly 1, and the
// traced standard error is far below the screen-space errors that
// vtkfx-bench measures (< 0.01).
#include "vtkFXReferenceAO.h"
#include "vtkFXScenes.h"
#include "vtkFXTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"

namespace
{
vtkSmartPointer<vtkActor> Plane(double ox, double oy, double oz, double ax, double ay, double az,
  double bx, double by, double bz)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(ox, oy, oz);
  plane->SetPoint1(ax, ay, az);
  plane->SetPoint2(bx, by, bz);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(plane->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}
}

int TestReferenceAO(int, char*[])
{
  const double R = 1.0;
  vtkNew<vtkRenderer> renderer;
  // Floor z = 0 for x < 0; wall x = 0 rising along z; both far larger than R.
  renderer->AddActor(Plane(-20, -20, 0, 0, -20, 0, -20, 20, 0));
  renderer->AddActor(Plane(0, -20, 0, 0, 20, 0, 0, -20, 20));
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(-1.5, 0, 0);
  camera->SetPosition(-1.5, -0.5, 6);
  camera->SetViewUp(1, 0, 0);
  camera->SetViewAngle(40);
  camera->SetClippingRange(0.1, 100);

  vtkFXReferenceAO reference;
  std::string error;
  FX_CHECK(reference.Build(renderer, error), error);
  const int w = 48, h = 32, rays = 1024;
  vtkNew<vtkMatrix4x4> inverse;
  inverse->DeepCopy(camera->GetCompositeProjectionTransformMatrix(double(w) / h, -1, 1));
  inverse->Invert();
  for (int falloff : { vtkFXReferenceAO::Binary, vtkFXReferenceAO::CubeRoot })
  {
    const char* name = vtkFXTest::FalloffName(falloff);
    const auto result = reference.Trace(renderer, w, h, R, rays, falloff);
    std::cout << name << ": " << result.CoveredPixels << " pixels, " << rays
              << " rays each, standard error (RMS) " << result.StandardErrorRMS << ", "
              << result.Seconds << " s" << std::endl;
    FX_CHECK(result.CoveredPixels == w * h, "floor and wall fill the view");
    FX_CHECK(result.StandardErrorRMS < 0.01, "the reference's own noise is small");
    int checked = 0, open = 0;
    double worst = 0.0;
    for (int y = 0; y < h; ++y)
    {
      for (int x = 0; x < w; ++x)
      {
        double o[3], d[3];
        vtkFXReferenceAO::PixelRay(inverse, x, y, w, h, o, d);
        const double t = -o[2] / d[2]; // where the ray meets the floor's plane
        const double px = o[0] + t * d[0];
        if (px > -1e-3)
        {
          continue; // on the wall
        }
        const float traced = result.Occlusion[static_cast<size_t>(y) * w + x];
        const double distance = -px;
        if (distance > R)
        {
          FX_CHECK(traced == 1.0f, "beyond the radius nothing occludes: " << traced);
          ++open;
          continue;
        }
        const double expected = vtkFXTest::CreaseOcclusion(distance, R, falloff);
        const double tolerance =
          4.0 * result.StandardError[static_cast<size_t>(y) * w + x] + 2e-3;
        worst = std::max(worst, std::fabs(traced - expected));
        FX_CHECK(std::fabs(traced - expected) <= tolerance,
          name << " pixel (" << x << "," << y << ") at h = " << distance << ": traced " << traced
               << ", closed form " << expected);
        ++checked;
      }
    }
    std::cout << name << ": " << checked << " floor pixels within R of the wall (worst difference "
              << worst << "), " << open << " beyond it" << std::endl;
    FX_CHECK(checked > 50 && open > 50, "both regions in view");
  }
  return EXIT_SUCCESS;
}
