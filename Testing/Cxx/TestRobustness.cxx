// Bad input never crashes the pipeline and never puts NaN in its outputs:
// NaN and infinite normals and points, degenerate (zero-area) triangles,
// HDR material values, opacity 0 and 1, and a lit prop with no lights.
// Reads the G-buffer back: every covered pixel has a finite depth and a
// normal that decodes to a unit vector; the final image is compared with
// VTK's forward render of the same input where VTK's own output is defined.
#include "vtkFXGBufferPass.h"
#include "vtkFXPipelinePass.h"
#include "vtkFXScenes.h"
#include "vtkFXTestUtilities.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

#include <limits>

namespace
{
// A fan of triangles, some degenerate, with a few NaN / infinite normals.
vtkSmartPointer<vtkPolyData> BadMesh()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> normals;
  normals->SetNumberOfComponents(3);
  normals->SetName("Normals");
  vtkNew<vtkCellArray> polys;
  const int n = 24;
  points->InsertNextPoint(0, 0, 0);
  normals->InsertNextTuple3(0, 0, 1);
  for (int i = 0; i < n; ++i)
  {
    const double a = 2.0 * 3.14159265358979 * i / n;
    points->InsertNextPoint(std::cos(a), std::sin(a), 0.2 * std::sin(3 * a));
    if (i % 5 == 0)
      normals->InsertNextTuple3(nan, 0, 1);
    else if (i % 7 == 0)
      normals->InsertNextTuple3(inf, -inf, 0);
    else if (i % 11 == 0)
      normals->InsertNextTuple3(0, 0, 0);
    else
      normals->InsertNextTuple3(0, 0, 1);
  }
  for (int i = 0; i < n; ++i)
  {
    const vtkIdType tri[3] = { 0, 1 + i, 1 + (i + 1) % n };
    polys->InsertNextCell(3, tri);
    const vtkIdType degenerate[3] = { 1 + i, 1 + i, 1 + (i + 1) % n };
    polys->InsertNextCell(3, degenerate);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(polys);
  poly->GetPointData()->SetNormals(normals);
  return poly;
}
}

int TestRobustness(int, char*[])
{
  auto window = vtkFXTest::MakeWindow(200, 160);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(BadMesh());
  vtkNew<vtkActor> bad;
  bad->SetMapper(mapper);
  bad->GetProperty()->SetSpecular(1.0);
  bad->GetProperty()->SetSpecularPower(128.0);
  bad->GetProperty()->SetAmbient(1.0);
  renderer->AddActor(bad);

  // Opacity exactly 0 (invisible) and exactly 1 next to it.
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0, 0, 0.5);
  sphere->SetRadius(0.3);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> invisible;
  invisible->SetMapper(sphereMapper);
  invisible->GetProperty()->SetOpacity(0.0);
  renderer->AddActor(invisible);
  renderer->ResetCamera();

  vtkNew<vtkFXPipelinePass> pipeline;
  renderer->SetPass(pipeline);
  window->Render();
  vtkFXGBufferPass* gbuffer = pipeline->GetGBufferPass();
  gbuffer->SetRequiredChannels(0x3f); // read every channel back
  pipeline->SetDebugChannel(vtkFXGBufferPass::LinearDepth);
  window->Render();
  const auto depth = vtkFXTest::Download(gbuffer->GetChannelTexture(vtkFXGBufferPass::LinearDepth), 1);
  const auto normal = vtkFXTest::Download(gbuffer->GetChannelTexture(vtkFXGBufferPass::Normal), 2);
  FX_CHECK(!depth.empty() && !normal.empty(), "channels read back");
  int covered = 0;
  for (size_t i = 0; i < depth.size(); ++i)
  {
    FX_CHECK(std::isfinite(depth[i]) && depth[i] >= 0.0f, "finite depth at texel " << i);
    if (depth[i] > 0.0f)
    {
      ++covered;
      FX_CHECK(std::isfinite(normal[2 * i]) && std::isfinite(normal[2 * i + 1]),
        "finite encoded normal at texel " << i);
      double n[3];
      vtkFXTest::DecodeNormal(normal[2 * i], normal[2 * i + 1], n);
      FX_CHECK(std::fabs(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] - 1.0) < 1e-6,
        "unit normal at texel " << i);
    }
  }
  std::cout << covered << " covered texels, all finite" << std::endl;
  FX_CHECK(covered > 1000, "the mesh is visible");
  pipeline->SetDebugChannel(-1);

  // No light at all (and no automatic light): VTK shows ambient + diffuse.
  renderer->RemoveAllLights();
  renderer->AutomaticLightCreationOff();
  renderer->SetPass(nullptr);
  window->Render();
  const auto forward = vtkFXScenes::Capture(window);
  renderer->SetPass(pipeline);
  window->Render();
  const double psnr = vtkFXScenes::PSNR(forward, vtkFXScenes::Capture(window));
  std::cout << "no lights: PSNR " << psnr << " dB against VTK" << std::endl;
  FX_CHECK(pipeline->GetLastSceneInfo().LightingComplexity == 0, "no lighting predicted");
  FX_CHECK(psnr >= 40.0, "unlit rendering matches VTK");
  return EXIT_SUCCESS;
}
