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
// The same for the two other quantities vtkfx-bench do traces:
// - directional occlusion, with a shading normal s = (sin a, 0, cos a)
//   tilted towards the wall (a > 0) or away from it: the visibility
//   weighted by max(0, s . w) over the floor's hemisphere, normalised by
//   that weight's integral there (midpoint rule on (theta, phi));
// - one bounce of diffuse light from a wall of albedo rho lit by a
//   directional light with diffuse factor D (unshadowed, constant over the
//   wall): rho D times the cosine-weighted share of rays that hit the wall
//   within R, rho D (1 - A_binary(h)).
#include "vtkFXReferenceAO.h"
#include "vtkFXScenes.h"
#include "vtkFXTestUtilities.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"

#include <algorithm>
#include <functional>

namespace
{
// The directional visibility at distance h from the wall, shading normal
// tilted by `tilt` radians towards it (see the top of this file): the
// midpoint rule's directions on (theta, phi) once per tilt, sorted by
// their x component, with prefix sums of their weights (and of weight x
// w.x^(-1/3) for the cube-root falloff), so each h is a binary search.
class TiltedCrease
{
public:
  explicit TiltedCrease(double tilt)
  {
    const int n = 600;
    const double pi = 3.14159265358979323846;
    const double s[3] = { std::sin(tilt), 0.0, std::cos(tilt) };
    std::vector<std::pair<double, double>> wall; // (w.x, weight) of directions towards the wall
    for (int i = 0; i < n; ++i)
    {
      const double theta = (i + 0.5) / n * pi / 2;
      for (int j = 0; j < n; ++j)
      {
        const double phi = (j + 0.5) / n * 2 * pi;
        const double w[3] = { std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
          std::cos(theta) };
        const double weight = std::max(0.0, vtkMath::Dot(s, w)) * std::sin(theta);
        this->Total += weight;
        if (w[0] > 0.0)
        {
          wall.emplace_back(w[0], weight);
        }
      }
    }
    std::sort(wall.begin(), wall.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    this->X.push_back(2.0);
    this->Weight.push_back(0.0);
    this->Falling.push_back(0.0);
    for (const auto& d : wall)
    {
      this->X.push_back(d.first);
      this->Weight.push_back(this->Weight.back() + d.second);
      this->Falling.push_back(this->Falling.back() + d.second / std::cbrt(d.first));
    }
  }

  double operator()(double h, double R, int falloff) const
  {
    // Directions with w.x > h / R hit the wall within R.
    const double a = h / R;
    const size_t k = static_cast<size_t>(
      std::upper_bound(this->X.begin(), this->X.end(), a, std::greater<double>()) - this->X.begin());
    const double occluded = this->Weight[k - 1] -
      (falloff == 0 ? 0.0 : std::cbrt(a) * this->Falling[k - 1]); // f = 1 - (a / w.x)^(1/3)
    return 1.0 - occluded / this->Total;
  }

private:
  double Total = 0.0;
  std::vector<double> X, Weight, Falling; // descending w.x, prefix sums
};

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

// The floor's distance to the wall at pixel (x, y), or -1 on the wall.
double FloorDistance(vtkMatrix4x4* inverse, int x, int y, int w, int h)
{
  double o[3], d[3];
  vtkFXReferenceAO::PixelRay(inverse, x, y, w, h, o, d);
  const double px = o[0] - o[2] / d[2] * d[0]; // where the ray meets the floor's plane
  return px > -1e-3 ? -1.0 : -px;
}

vtkSmartPointer<vtkMatrix4x4> InversePixelProjection(vtkRenderer* renderer, int w, int h)
{
  auto inverse = vtkSmartPointer<vtkMatrix4x4>::New();
  inverse->DeepCopy(
    renderer->GetActiveCamera()->GetCompositeProjectionTransformMatrix(double(w) / h, -1, 1));
  inverse->Invert();
  return inverse;
}

// The floor's pixels within R of the wall in `result` against
// closedForm(h, R, falloff), within 4 standard errors plus 3e-3. Returns
// the pixels compared, or -1 where one differs.
template <typename ClosedForm>
int CompareFloorNearWall(vtkRenderer* renderer, const vtkFXReferenceAO::Result& result, int w,
  int h, double R, int falloff, ClosedForm closedForm, const std::string& what)
{
  auto inverse = InversePixelProjection(renderer, w, h);
  double worst = 0.0;
  int checked = 0;
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const double distance = FloorDistance(inverse, x, y, w, h);
      if (distance < 0.0 || distance > R)
      {
        continue;
      }
      const size_t i = static_cast<size_t>(y) * w + x;
      const double expected = closedForm(distance, R, falloff);
      worst = std::max(worst, std::fabs(result.Occlusion[i] - expected));
      if (!(std::fabs(result.Occlusion[i] - expected) <= 4.0 * result.StandardError[i] + 3e-3))
      {
        std::cerr << what << ", pixel (" << x << "," << y << ") at h = " << distance
                  << ": traced " << result.Occlusion[i] << ", closed form " << expected
                  << std::endl;
        return -1;
      }
      ++checked;
    }
  }
  std::cout << vtkFXTest::FalloffName(falloff) << ", " << what << ": " << checked
            << " floor pixels, worst difference " << worst << std::endl;
  return checked;
}

// Directional occlusion: the floor's pixels within R of the wall against
// TiltedCreaseOcclusion, for a shading normal tilted 40 degrees towards
// the wall and away from it (both falloffs), within 4 standard errors plus
// 3e-3; the two tilts differ by far more than that.
int CheckShadingNormals(
  vtkRenderer* renderer, const vtkFXReferenceAO& reference, int w, int h, double R)
{
  for (int falloff : { vtkFXReferenceAO::Binary, vtkFXReferenceAO::CubeRoot })
  {
    for (double degrees : { 40.0, -40.0 })
    {
      const double tilt = vtkMath::RadiansFromDegrees(degrees);
      const TiltedCrease closedForm(tilt);
      std::vector<float> normals;
      for (int i = 0; i < w * h; ++i)
      {
        normals.insert(normals.end(),
          { static_cast<float>(std::sin(tilt)), 0.0f, static_cast<float>(std::cos(tilt)) });
      }
      const auto result = reference.Trace(renderer, w, h, R, 1024, falloff, 2, &normals);
      const int checked = CompareFloorNearWall(renderer, result, w, h, R, falloff, closedForm,
        std::string("shading normal tilted ") + (degrees > 0 ? "towards" : "away from") +
          " the wall");
      FX_CHECK(checked > 50, "floor pixels near the wall in view, each as the closed form says");
    }
    const double toward = TiltedCrease(vtkMath::RadiansFromDegrees(40.0))(0.3 * R, R, falloff);
    const double away = TiltedCrease(vtkMath::RadiansFromDegrees(-40.0))(0.3 * R, R, falloff);
    // (untilted, the table gives the crease's own closed form)
    const double flat = TiltedCrease(0.0)(0.3 * R, R, falloff);
    FX_CHECK(std::fabs(flat - vtkFXTest::CreaseOcclusion(0.3 * R, R, falloff)) < 2e-3,
      "the tilted closed form without a tilt: " << flat);
    FX_CHECK(away - toward > 0.1, "the tilts must differ: " << toward << " and " << away);
  }
  return EXIT_SUCCESS;
}

// The normal a mesh is shaded with: the floor's point normals tilted 40
// degrees towards the wall. With VTK's default (Gouraud) interpolation the
// reference's lobe follows them, as the G-buffer's normal does: the tilted
// closed form, with no shading normals passed. With flat interpolation
// VTK shades the facet's normal: the crease's own closed form.
int CheckPointNormals(vtkRenderer* renderer, vtkActor* floor, int w, int h, double R)
{
  const double tilt = vtkMath::RadiansFromDegrees(40.0);
  vtkPolyDataMapper* mapper = vtkPolyDataMapper::SafeDownCast(floor->GetMapper());
  mapper->Update();
  vtkNew<vtkPolyData> tilted;
  tilted->DeepCopy(mapper->GetInput());
  vtkNew<vtkFloatArray> normals;
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(tilted->GetNumberOfPoints());
  for (vtkIdType i = 0; i < tilted->GetNumberOfPoints(); ++i)
  {
    normals->SetTuple3(i, std::sin(tilt), 0.0, std::cos(tilt));
  }
  tilted->GetPointData()->SetNormals(normals);
  vtkNew<vtkPolyDataMapper> tiltedMapper;
  tiltedMapper->SetInputData(tilted);
  vtkSmartPointer<vtkMapper> original = floor->GetMapper();
  floor->SetMapper(tiltedMapper);
  int status = EXIT_SUCCESS;
  for (int interpolation : { VTK_GOURAUD, VTK_FLAT })
  {
    floor->GetProperty()->SetInterpolation(interpolation);
    vtkFXReferenceAO reference;
    std::string error;
    FX_CHECK(reference.Build(renderer, error), error);
    const int falloff = vtkFXReferenceAO::Binary;
    const auto result = reference.Trace(renderer, w, h, R, 1024, falloff);
    const int checked = interpolation == VTK_GOURAUD
      ? CompareFloorNearWall(renderer, result, w, h, R, falloff, TiltedCrease(tilt),
          "point normals tilted towards the wall")
      : CompareFloorNearWall(renderer, result, w, h, R, falloff,
          [](double d, double radius, int f) { return vtkFXTest::CreaseOcclusion(d, radius, f); },
          "the same, shaded flat");
    status = checked > 50 ? status : EXIT_FAILURE;
  }
  floor->SetMapper(original);
  floor->GetProperty()->SetInterpolationToGouraud();
  return status;
}

// One bounce: the wall coloured (1, 0.5, 0.25) with Diffuse 0.8, lit by a
// white directional light of intensity 1 along (1, 0, -0.5) (diffuse factor
// on the wall D = 1 / sqrt(1.25), on the floor's side); the floor black.
// Each floor pixel within R: rho D (1 - A_binary(h)) per channel, within 4
// standard errors of a mean of values in [0, rho D] (at most rho D / 2 /
// sqrt(rays)) plus 2e-3; beyond R exactly 0.
int CheckBleeding(vtkRenderer* renderer, int w, int h, double R)
{
  vtkActor* floor = vtkActor::SafeDownCast(renderer->GetActors()->GetItemAsObject(0));
  vtkActor* wall = vtkActor::SafeDownCast(renderer->GetActors()->GetItemAsObject(1));
  floor->GetProperty()->SetColor(0.0, 0.0, 0.0);
  wall->GetProperty()->SetColor(1.0, 0.5, 0.25);
  wall->GetProperty()->SetDiffuse(0.8);
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->PositionalOff();
  light->SetPosition(-1.0, 0.0, 0.5);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->AddLight(light);
  vtkFXReferenceAO reference;
  std::string error;
  FX_CHECK(reference.Build(renderer, error), error);
  const int rays = 1024;
  const auto bleeding = reference.TraceBleeding(renderer, w, h, R, rays);
  auto inverse = InversePixelProjection(renderer, w, h);
  const double rho[3] = { 0.8, 0.4, 0.2 };
  const double D = 1.0 / std::sqrt(1.25);
  double worst = 0.0;
  int checked = 0, open = 0;
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const double distance = FloorDistance(inverse, x, y, w, h);
      if (distance < 0.0)
      {
        continue;
      }
      const double share = distance > R ? 0.0 : 1.0 - vtkFXTest::CreaseOcclusionBinary(distance, R);
      for (int c = 0; c < 3; ++c)
      {
        const double expected = rho[c] * D * share;
        const double traced = bleeding[3 * (static_cast<size_t>(y) * w + x) + c];
        const double tolerance = 4.0 * rho[c] * D / 2.0 / std::sqrt(double(rays)) + 2e-3;
        worst = std::max(worst, std::fabs(traced - expected));
        FX_CHECK(std::fabs(traced - expected) <= (distance > R ? 0.0 : tolerance),
          "bleeding at pixel (" << x << "," << y << "), h = " << distance << ", channel " << c
                                << ": traced " << traced << ", closed form " << expected);
      }
      distance > R ? ++open : ++checked;
    }
  }
  std::cout << "bleeding: " << checked << " floor pixels within R of the wall (worst difference "
            << worst << "), " << open << " beyond it, exactly 0" << std::endl;
  FX_CHECK(checked > 50 && open > 50, "both regions in view");
  return EXIT_SUCCESS;
}

int TestReferenceAO(int, char*[])
{
  const double R = 1.0;
  vtkNew<vtkRenderer> renderer;
  // Floor z = 0 for x < 0; wall x = 0 rising along z; both far larger than R.
  auto floor = Plane(-20, -20, 0, 0, -20, 0, -20, 20, 0);
  renderer->AddActor(floor);
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
  FX_CHECK(CheckShadingNormals(renderer, reference, w, h, R) == EXIT_SUCCESS,
    "directional occlusion's reference");
  FX_CHECK(CheckBleeding(renderer, w, h, R) == EXIT_SUCCESS, "bleeding's reference");
  FX_CHECK(CheckPointNormals(renderer, floor, w, h, R) == EXIT_SUCCESS,
    "the lobe around the normal the mesh is shaded with");
  return EXIT_SUCCESS;
}
