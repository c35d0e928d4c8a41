// vtkFXSSAOPass::OccluderThickness (the horizon estimator with occluders of
// finite thickness, Binary falloff) against the ray-traced reference and
// the closed forms, with the Medium preset's 16 fetches at half resolution,
// blurred:
// - a flat plane seen from 70 to 4 degrees reads open (0.999 or more)
//   raw, as the height field does: its own texels lie on its tangent line
//   and mark no sector; also under R = 1e25 and a thickness of 1e20 R;
// - three balls floating over a floor (atoms over a surface): the floor
//   within R of their feet against vtkFXReferenceAO (256 rays per pixel).
//   The height field takes each ball for a column down to the floor
//   (measured: RMSE 0.141, 0.067 too dark on average); 0.5 R of thickness
//   lets rays pass under them (RMSE 0.031, 0.011 too dark). Asserted: under
//   half the height field's RMSE, and below 0.06;
// - the crease of a floor and a wall (a wall is one surface, and rays that
//   reach it stop there whatever lies behind it) against its closed form:
//   the wall's samples, each hiding only 0.5 R behind it, still close it
//   (measured: mean |error| 0.033 from 0.03 R to R, asserted below 0.05;
//   TestSSAO bounds the height field's at 0.04);
// - every raw value is finite and in [0, 1].
#include "vtkFXOcclusionTestUtilities.h"
#include "vtkFXReferenceAO.h"
#include "vtkFXSSAOPass.h"
#include "vtkFXTestUtilities.h"

#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkSphereSource.h"

#include <cmath>

namespace
{
using namespace vtkFXOcclusionTest;

const double Radius = 0.5;

// Horizon, 16 fetches, half resolution, blurred (the Medium preset; read
// at each pixel's half-resolution texel), with occluders `thickness` R
// thick.
vtkFXSSAOPass* UseThickness(Setup& s, double thickness)
{
  vtkFXSSAOPass* ssao = s.Pipeline->GetSSAOPass();
  ssao->SetMethod(vtkFXSSAOPass::Horizon);
  ssao->SetFalloff(vtkFXSSAOPass::Binary);
  ssao->SetNumberOfSamples(16);
  ssao->SetRadius(Radius);
  ssao->SetOccluderThickness(thickness);
  return ssao;
}

// A 40 x 40 floor (y = 0) with three balls of radius 0.16 R floating
// with their centres 0.5 R above it, 0.8 R apart (atoms over a surface),
// seen from about 35 degrees.
const double BallRadius = 0.16 * Radius, BallHeight = 0.5 * Radius;
const double BallX[3] = { -0.8 * Radius, 0.0, 0.8 * Radius };
void AddFloatingBalls(Setup& s)
{
  const double fo[3] = { -20, 0, -20 }, f1[3] = { -20, 0, 20 }, f2[3] = { 20, 0, -20 };
  s.Renderer->AddActor(Plane(fo, f1, f2));
  for (double x : BallX)
  {
    vtkNew<vtkSphereSource> ball;
    ball->SetCenter(x, BallHeight, 0.0);
    ball->SetRadius(BallRadius);
    ball->SetThetaResolution(48);
    ball->SetPhiResolution(24);
    s.Renderer->AddActor(vtkFXTest::SurfaceActor(ball));
  }
  vtkCamera* camera = s.Renderer->GetActiveCamera();
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(0.2, 1.2, 1.8);
  camera->SetViewUp(0, 1, 0);
  s.Renderer->ResetCameraClippingRange();
}

// RMSE and mean signed error of `ao` against the reference over the floor
// pixels within R of a ball's foot.
void FloorErrors(const std::vector<float>& ao, const std::vector<float>& reference,
  const std::vector<std::array<double, 4>>& world, double& rmse, double& bias, int& pixels)
{
  double sum2 = 0.0, sum = 0.0;
  pixels = 0;
  for (size_t i = 0; i < ao.size(); ++i)
  {
    const auto& p = world[i];
    double d = VTK_DOUBLE_MAX;
    for (double x : BallX)
    {
      d = std::min(d, std::hypot(p[0] - x, p[2]));
    }
    if (p[3] > 0.0 && std::fabs(p[1]) < 1e-4 && d < Radius && reference[i] >= 0.0f)
    {
      const double e = ao[i] - reference[i];
      sum2 += e * e;
      sum += e;
      ++pixels;
    }
  }
  rmse = pixels ? std::sqrt(sum2 / pixels) : 0.0;
  bias = pixels ? sum / pixels : 0.0;
}
}

int TestSSAOThickness(int, char*[])
{
  auto window = vtkFXTest::MakeWindow(Width, Height);

  // 1. An open plane, raw, from 70 to 4 degrees; at 30 degrees also under
  // a radius far beyond what the image shows and a thickness far beyond
  // the radius (where the point behind a sample lies 1e20 units away).
  struct OpenCase
  {
    double Elevation, Radius, Thickness;
  };
  const OpenCase openCases[] = { { 70.0, Radius, 0.5 }, { 30.0, Radius, 0.5 },
    { 10.0, Radius, 0.5 }, { 4.0, Radius, 0.5 }, { 30.0, 1e25, 0.5 }, { 30.0, Radius, 1e20 } };
  for (const OpenCase& c : openCases)
  {
    const double elevation = c.Elevation;
    Setup s = MakeSetup(window);
    ViewPlane(s, elevation);
    vtkFXSSAOPass* ssao = UseThickness(s, c.Thickness);
    ssao->SetRadius(c.Radius);
    s.Pipeline->GetOcclusionBlurPass()->EnabledOff();
    window->Render();
    FX_CHECK(ssao->UsesThinOccluders(), "the thin-occluder estimator runs");
    if (CheckRange(ssao->GetOutputTexture(), "plane") != EXIT_SUCCESS)
    {
      return EXIT_FAILURE;
    }
    const auto ao = OcclusionAtPixels(ssao->GetOutputTexture());
    const auto world = WorldPositions(s.Renderer, s.Pipeline->GetGBufferPass());
    int inside = 0;
    const float lowest = LowestOnPlane(ao, world, Radius, inside);
    std::cout << "plane at " << elevation << " degrees, R " << c.Radius << ", thickness "
              << c.Thickness << " R: lowest raw occlusion " << lowest << " over " << inside
              << " pixels" << std::endl;
    // (one sector marked on one side of one slice would cost 1/128)
    FX_CHECK(inside > 1000 && lowest >= 0.999f, "a flat plane is unoccluded");
  }

  // 2. Balls floating over a floor, against the ray-traced reference.
  double rmse[2] = {}, bias[2] = {};
  std::vector<float> reference;
  for (int k = 0; k < 2; ++k)
  {
    const double thickness = k == 0 ? vtkFXSSAOPass::HeightField : 0.5;
    Setup s = MakeSetup(window);
    AddFloatingBalls(s);
    vtkFXSSAOPass* ssao = UseThickness(s, thickness);
    window->Render();
    FX_CHECK(ssao->UsesThinOccluders() == (k == 1), "the estimator follows the thickness");
    if (CheckRange(ssao->GetOutputTexture(), "balls, raw") != EXIT_SUCCESS)
    {
      return EXIT_FAILURE;
    }
    if (reference.empty())
    {
      vtkFXReferenceAO tracer;
      std::string error;
      FX_CHECK(tracer.Build(s.Renderer, error), "reference: " << error);
      const auto traced = tracer.Trace(s.Renderer, Width, Height, Radius, 256);
      FX_CHECK(traced.StandardErrorRMS < 0.02, "reference's standard error " << traced.StandardErrorRMS);
      reference = traced.Occlusion;
    }
    const auto ao = OcclusionAtPixels(s.Pipeline->GetOcclusionBlurPass()->GetOutputTexture());
    const auto world = WorldPositions(s.Renderer, s.Pipeline->GetGBufferPass());
    int pixels = 0;
    FloorErrors(ao, reference, world, rmse[k], bias[k], pixels);
    std::cout << (k == 0 ? "height field" : "thickness 0.5 R") << ": floor within R of the balls' feet, "
              << pixels << " pixels: RMSE " << rmse[k] << ", mean error " << bias[k] << std::endl;
    FX_CHECK(pixels > 2000, "the floor under the balls is seen");
  }
  FX_CHECK(rmse[1] < 0.5 * rmse[0] && rmse[1] < 0.06,
    "thin occluders: RMSE " << rmse[1] << " against the height field's " << rmse[0]);

  // 3. The crease of a floor and a wall against its closed form.
  {
    Setup s = MakeSetup(window);
    AddCrease(s);
    UseThickness(s, 0.5);
    window->Render();
    const auto ao = OcclusionAtPixels(s.Pipeline->GetOcclusionBlurPass()->GetOutputTexture());
    const auto world = WorldPositions(s.Renderer, s.Pipeline->GetGBufferPass());
    double sum = 0.0, signedSum = 0.0;
    int n = 0;
    for (size_t i = 0; i < ao.size(); ++i)
    {
      const auto& p = world[i];
      const bool onFloor = p[3] > 0.0 && std::fabs(p[1]) < 1e-4 && std::fabs(p[0]) < 1.2;
      if (onFloor && p[2] >= 0.06 * Radius && p[2] < Radius)
      {
        const double e = ao[i] - vtkFXTest::CreaseOcclusion(p[2], Radius, vtkFXSSAOPass::Binary);
        sum += std::fabs(e);
        signedSum += e;
        ++n;
      }
    }
    std::cout << "crease, thickness 0.5 R: mean |error| " << sum / std::max(n, 1)
              << ", mean error " << signedSum / std::max(n, 1) << " over " << n << " pixels"
              << std::endl;
    FX_CHECK(n > 1000 && sum / n < 0.05, "the crease with thin occluders");
  }
  return EXIT_SUCCESS;
}
