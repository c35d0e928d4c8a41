// Helpers shared by the occlusion tests (TestSSAO, TestDirectionalOcclusion):
// a 320 x 240 pipeline with ambient occlusion, planes, and the G-buffer's
// world positions and occlusion per pixel read back. Header only.
#ifndef vtkFXOcclusionTestUtilities_h
#define vtkFXOcclusionTestUtilities_h

#include "vtkFXBilateralBlurPass.h"
#include "vtkFXGBufferPass.h"
#include "vtkFXPipelinePass.h"
#include "vtkFXRenderUtilities.h"
#include "vtkFXTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkRendererCollection.h"

#include <array>
#include <vector>

namespace vtkFXOcclusionTest
{
using GB = vtkFXGBufferPass;
const int Width = 320, Height = 240;

inline vtkSmartPointer<vtkActor> Plane(const double o[3], const double p1[3], const double p2[3])
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(o[0], o[1], o[2]);
  plane->SetPoint1(p1[0], p1[1], p1[2]);
  plane->SetPoint2(p2[0], p2[1], p2[2]);
  plane->SetResolution(8, 8);
  return vtkFXTest::SurfaceActor(plane);
}

// World positions of the G-buffer's pixels (w = 0 where there is no surface).
inline std::vector<std::array<double, 4>> WorldPositions(vtkRenderer* ren, vtkFXGBufferPass* gbuffer)
{
  const auto depth = vtkFXTest::Download(gbuffer->GetChannelTexture(GB::LinearDepth), 1);
  double origin[3][3], direction[3][3];
  vtkFXRenderUtilities::ComputeFrustumRay(ren, origin, direction);
  vtkNew<vtkMatrix4x4> toWorld;
  toWorld->DeepCopy(ren->GetActiveCamera()->GetViewTransformMatrix());
  toWorld->Invert();
  std::vector<std::array<double, 4>> world(depth.size());
  for (int y = 0; y < Height; ++y)
  {
    for (int x = 0; x < Width; ++x)
    {
      const size_t i = static_cast<size_t>(y) * Width + x;
      const double ndc[2] = { 2.0 * (x + 0.5) / Width - 1.0, 2.0 * (y + 0.5) / Height - 1.0 };
      double view[4] = { 0, 0, 0, 1 };
      for (int c = 0; c < 3; ++c)
      {
        view[c] = origin[0][c] + ndc[0] * origin[1][c] + ndc[1] * origin[2][c] +
          depth[i] * (direction[0][c] + ndc[0] * direction[1][c] + ndc[1] * direction[2][c]);
      }
      double w[4];
      toWorld->MultiplyPoint(view, w);
      world[i] = { w[0], w[1], w[2], depth[i] > 0.0f ? 1.0 : 0.0 };
    }
  }
  return world;
}


// The occlusion texture at full resolution: one component (R by default)
// of the texture, which is either full resolution or read at the G-buffer
// pixel's half-res texel.
inline std::vector<float> OcclusionAtPixels(vtkTextureObject* texture, int component = 0)
{
  const int comps = texture->GetComponents();
  const auto values = vtkFXTest::Download(texture, comps);
  const int w = static_cast<int>(texture->GetWidth());
  const int step = Width / w >= 2 ? 2 : 1;
  std::vector<float> out(static_cast<size_t>(Width) * Height);
  for (int y = 0; y < Height; ++y)
  {
    for (int x = 0; x < Width; ++x)
    {
      out[static_cast<size_t>(y) * Width + x] =
        values[comps * (static_cast<size_t>(y / step) * w + x / step) + component];
    }
  }
  return out;
}


inline int CheckRange(vtkTextureObject* texture, const char* what, float upper = 1.0f)
{
  // 8-bit normalised texels are in [0, 1] whatever the shader wrote: a
  // range check on them could not fail.
  FX_CHECK(texture && texture->GetVTKDataType() == VTK_FLOAT,
    what << ": a range check needs float texels");
  const int comps = texture->GetComponents();
  const auto values = vtkFXTest::Download(texture, comps);
  for (size_t i = 0; i < values.size(); i += comps)
  {
    FX_CHECK(std::isfinite(values[i]) && values[i] >= 0.0f && values[i] <= upper,
      what << ": occlusion " << values[i] << " at texel " << i / comps);
  }
  return EXIT_SUCCESS;
}

struct Setup
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkFXPipelinePass> Pipeline;
};

inline Setup MakeSetup(vtkRenderWindow* window)
{
  Setup s;
  s.Window = window;
  window->GetRenderers()->RemoveAllItems();
  s.Renderer = vtkSmartPointer<vtkRenderer>::New();
  window->AddRenderer(s.Renderer);
  s.Pipeline = vtkSmartPointer<vtkFXPipelinePass>::New();
  s.Pipeline->AmbientOcclusionOn();
  s.Pipeline->GetOcclusionBlurPass()->UpsampleOn();
  s.Renderer->SetPass(s.Pipeline);
  return s;
}

// A 40 x 40 plane y = 0 (the only prop), seen from `elevation` degrees
// above it, 6 units away.
inline void ViewPlane(Setup& s, double elevation)
{
  const double o[3] = { -20, 0, -20 }, p1[3] = { 20, 0, -20 }, p2[3] = { -20, 0, 20 };
  s.Renderer->AddActor(Plane(o, p1, p2));
  vtkCamera* camera = s.Renderer->GetActiveCamera();
  const double a = vtkMath::RadiansFromDegrees(elevation);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(0, 6 * std::sin(a), 6 * std::cos(a));
  camera->SetViewUp(0, 1, 0);
  s.Renderer->ResetCameraClippingRange();
}

// Lowest occlusion (values above 1 count as 1) over the pixels of that
// plane more than `margin` from its border; `inside` counts them.
inline float LowestOnPlane(const std::vector<float>& ao,
  const std::vector<std::array<double, 4>>& world, double margin, int& inside)
{
  float lowest = 1.0f;
  inside = 0;
  for (size_t i = 0; i < ao.size(); ++i)
  {
    const auto& p = world[i];
    if (p[3] > 0.0 && std::fabs(p[0]) < 20 - margin && std::fabs(p[2]) < 20 - margin)
    {
      lowest = std::min(lowest, ao[i]);
      ++inside;
    }
  }
  return lowest;
}


// The inner crease of a floor (y = 0, z in [0, 10]) and a wall (z = 0,
// y in [0, 10]), 20 units wide, seen from (0.5, 3, 4) towards (0, 0.5,
// 0.5). Returns the floor; the wall is the renderer's last actor.
inline vtkActor* AddCrease(Setup& s)
{
  // (both front faces towards the crease: a bump rises along them)
  const double fo[3] = { -10, 0, 0 }, f1[3] = { -10, 0, 10 }, f2[3] = { 10, 0, 0 };
  const double wo[3] = { -10, 0, 0 }, w1[3] = { 10, 0, 0 }, w2[3] = { -10, 10, 0 };
  auto floor = Plane(fo, f1, f2);
  s.Renderer->AddActor(floor);
  s.Renderer->AddActor(Plane(wo, w1, w2));
  vtkCamera* camera = s.Renderer->GetActiveCamera();
  camera->SetFocalPoint(0, 0.5, 0.5);
  camera->SetPosition(0.5, 3.0, 4.0);
  camera->SetViewUp(0, 1, 0);
  s.Renderer->ResetCameraClippingRange();
  return floor;
}
}

#endif
