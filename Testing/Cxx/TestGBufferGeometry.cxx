// Reads the G-buffer back and checks it against an analytic sphere (drawn by
// VTK's ray-cast sphere imposter, so the surface is exact):
// - linear depth equals -z_view of the ray/sphere hit within 1e-4 relative,
// - normals decode to unit vectors within 2e-3 rad of the analytic normal
//   (16-bit octahedral coding: ~5e-4 per component), and unlit surfaces
//   carry the unlit sentinel instead,
// - background pixels have hardware depth 1 and linear depth 0,
// under perspective and parallel projection, at scene scales 1e-6 and 1e6,
// with near/far ratios down to 1e-6, and (for a plane) 1e6 units from the
// origin.
// The expected values come from inverting the camera's composite projection
// in double precision, independently of vtkFXRenderUtilities.
#include "vtkFXGBufferPass.h"
#include "vtkFXTestUtilities.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkMatrix4x4.h"
#include "vtkOpenGLSphereMapper.h"
#include "vtkPlaneSource.h"
#include "vtkPoints.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkPolyData.h"
#include "vtkActor.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"

namespace
{
struct Case
{
  const char* Name;
  bool Parallel;
  double Scale;     // sphere radius and camera distance scale
  double Offset;    // translation of the whole scene
  double NearRatio; // near/far clipping ratio (0: VTK's automatic range)
  bool Plane;       // a plane z = const instead of the sphere
  bool Unlit;       // lighting off: no view-space position in VTK's shader
  bool Pbr = false; // VTK's PBR model: its colour kept, its normal flagged
};

// A pre-lit (PBR) code keeps 9 bits after the point in x: its encoding
// alone is off by up to 0.0025 rad (vtkFXNormalCoding.glsl), on top of
// what the others' 2e-3 allows (measured: the sphere 1.0e-3 without the
// flag, 5.0e-3 with it; the plane 1.4e-4 and 1.8e-3).
double NormalTolerance(const Case& c)
{
  return c.Pbr ? 6e-3 : 2e-3;
}

// Whether texel i's normal code carries the pre-lit flag (x moved up by 3).
bool IsFlaggedPrelit(const std::vector<float>& normal, size_t i)
{
  return normal[2 * i] > 1.5f && normal[2 * i + 1] <= 2.0f;
}

// Ray through the pixel centre in world coordinates (double precision).
void PixelRay(vtkMatrix4x4* inverse, double ndcX, double ndcY, double origin[3], double dir[3])
{
  double p0[4] = { ndcX, ndcY, -1.0, 1.0 }, p1[4] = { ndcX, ndcY, 1.0, 1.0 };
  double w0[4], w1[4];
  inverse->MultiplyPoint(p0, w0);
  inverse->MultiplyPoint(p1, w1);
  double l = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    origin[i] = w0[i] / w0[3];
    dir[i] = w1[i] / w1[3] - origin[i];
    l += dir[i] * dir[i];
  }
  l = std::sqrt(l);
  for (int i = 0; i < 3; ++i)
  {
    dir[i] /= l;
  }
}

int RunCase(vtkRenderWindow* window, const Case& c)
{
  const int width = 160, height = 120;
  const double radius = c.Scale;
  const double center[3] = { c.Offset, c.Offset, c.Offset };
  window->GetRenderers()->RemoveAllItems();
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->InsertNextPoint(center);
  vtkNew<vtkCellArray> verts;
  const vtkIdType id = 0;
  verts->InsertNextCell(1, &id);
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetVerts(verts);
  vtkNew<vtkActor> actor;
  if (c.Plane)
  {
    // VTK's polydata mapper keeps far-away meshes precise by shifting the
    // vertex buffer; its imposter spheres compute their centres in float and
    // lose ~1e6 * 6e-8 world units there, so the far case uses a plane.
    vtkNew<vtkPlaneSource> plane;
    plane->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
    plane->SetOrigin(center[0] - 50 * radius, center[1] - 50 * radius, center[2]);
    plane->SetPoint1(center[0] + 50 * radius, center[1] - 50 * radius, center[2]);
    plane->SetPoint2(center[0] - 50 * radius, center[1] + 50 * radius, center[2]);
    vtkNew<vtkPolyDataMapper> planeMapper;
    planeMapper->SetInputConnection(plane->GetOutputPort());
    actor->SetMapper(planeMapper);
    actor->GetProperty()->SetLighting(!c.Unlit);
  }
  else
  {
    vtkNew<vtkOpenGLSphereMapper> mapper;
    mapper->SetInputData(poly);
    mapper->SetRadius(radius);
    actor->SetMapper(mapper);
  }
  if (c.Pbr)
  {
    actor->GetProperty()->SetInterpolationToPBR();
  }
  renderer->AddActor(actor);

  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(center);
  camera->SetPosition(center[0] + 1.2 * radius, center[1] + 0.8 * radius, center[2] + 4.0 * radius);
  camera->SetViewUp(0, 1, 0);
  camera->SetParallelProjection(c.Parallel);
  camera->SetParallelScale(1.6 * radius);
  if (c.NearRatio > 0.0)
  {
    const double distance = camera->GetDistance();
    camera->SetClippingRange(distance * 1e-4, distance * 1e-4 / c.NearRatio);
  }
  else
  {
    renderer->ResetCameraClippingRange();
  }

  vtkFXGBufferPass* gbuffer = vtkFXTest::InstallGBufferAlone(renderer);
  window->Render();

  vtkTextureObject* depthTexture = gbuffer->GetChannelTexture(vtkFXGBufferPass::LinearDepth);
  vtkTextureObject* normalTexture = gbuffer->GetChannelTexture(vtkFXGBufferPass::Normal);
  FX_CHECK(depthTexture && normalTexture, "depth and normal channels allocated");
  FX_CHECK(static_cast<int>(depthTexture->GetWidth()) == width &&
      static_cast<int>(depthTexture->GetHeight()) == height,
    "textures have the viewport size");
  const std::vector<float> depth = vtkFXTest::Download(depthTexture, 1);
  const std::vector<float> normal = vtkFXTest::Download(normalTexture, 2);
  const std::vector<float> hardware = vtkFXTest::Download(gbuffer->GetDepthTexture(), 1);
  FX_CHECK(depth.size() == static_cast<size_t>(width * height), "depth read back");

  vtkNew<vtkMatrix4x4> inverse;
  inverse->DeepCopy(camera->GetCompositeProjectionTransformMatrix(
    renderer->GetTiledAspectRatio(), -1, 1));
  inverse->Invert();
  vtkMatrix4x4* view = camera->GetViewTransformMatrix();

  int checked = 0, background = 0;
  double worstDepth = 0.0, worstAngle = 0.0;
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const size_t i = static_cast<size_t>(y) * width + x;
      double o[3], d[3];
      PixelRay(inverse, 2.0 * (x + 0.5) / width - 1.0, 2.0 * (y + 0.5) / height - 1.0, o, d);
      if (c.Plane)
      {
        const double t = (center[2] - o[2]) / d[2];
        double hit[4] = { o[0] + t * d[0], o[1] + t * d[1], center[2], 1.0 }, hitVC[4];
        view->MultiplyPoint(hit, hitVC);
        const double relative = std::fabs(depth[i] + hitVC[2]) / -hitVC[2];
        worstDepth = std::max(worstDepth, relative);
        FX_CHECK(relative <= 1e-4, c.Name << ": plane depth at (" << x << "," << y << ") "
                                          << depth[i] << " expected " << -hitVC[2]);
        if (c.Unlit)
        {
          // Unlit fragments carry the sentinel, never a made-up normal.
          FX_CHECK(normal[2 * i] == 4.0f && normal[2 * i + 1] == 4.0f,
            c.Name << ": unlit normal sentinel at (" << x << "," << y << ")");
        }
        else
        {
          double n[3], up[4] = { 0, 0, 1, 0 }, upVC[4];
          vtkFXTest::DecodeNormal(normal[2 * i], normal[2 * i + 1], n);
          view->MultiplyPoint(up, upVC);
          const double angle = vtkFXTest::Angle(n, upVC);
          worstAngle = std::max(worstAngle, angle);
          FX_CHECK(angle <= NormalTolerance(c), c.Name << ": plane normal off by " << angle);
          FX_CHECK(IsFlaggedPrelit(normal, i) == c.Pbr,
            c.Name << ": the normal is flagged pre-lit exactly for PBR");
        }
        ++checked;
        continue;
      }
      double oc[3] = { o[0] - center[0], o[1] - center[1], o[2] - center[2] };
      const double b = oc[0] * d[0] + oc[1] * d[1] + oc[2] * d[2];
      const double cc = oc[0] * oc[0] + oc[1] * oc[1] + oc[2] * oc[2] - radius * radius;
      const double disc = b * b - cc;
      // Distance of the ray from the centre, relative to the radius.
      const double miss = std::sqrt(std::max(0.0, cc + radius * radius - b * b)) / radius;
      if (miss > 1.02)
      {
        FX_CHECK(hardware[i] == 1.0f && depth[i] == 0.0f,
          c.Name << ": background pixel (" << x << "," << y << ") depth " << depth[i]);
        ++background;
        continue;
      }
      if (miss > 0.95 || disc < 0.0)
      {
        continue; // silhouette: coverage is up to rasterisation
      }
      const double t = -b - std::sqrt(disc);
      double hit[4] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2], 1.0 };
      double hitVC[4];
      view->MultiplyPoint(hit, hitVC);
      const double expected = -hitVC[2];
      const double relative = std::fabs(depth[i] - expected) / expected;
      worstDepth = std::max(worstDepth, relative);
      FX_CHECK(relative <= 1e-4,
        c.Name << ": depth at (" << x << "," << y << ") " << depth[i] << " expected " << expected);

      double n[3];
      vtkFXTest::DecodeNormal(normal[2 * i], normal[2 * i + 1], n);
      double nWorld[4] = { (hit[0] - center[0]) / radius, (hit[1] - center[1]) / radius,
        (hit[2] - center[2]) / radius, 0.0 };
      double nVC[4];
      view->MultiplyPoint(nWorld, nVC);
      const double angle = vtkFXTest::Angle(n, nVC);
      worstAngle = std::max(worstAngle, angle);
      FX_CHECK(angle <= NormalTolerance(c),
        c.Name << ": normal at (" << x << "," << y << ") off by " << angle);
      FX_CHECK(IsFlaggedPrelit(normal, i) == c.Pbr,
        c.Name << ": the normal is flagged pre-lit exactly for PBR");
      ++checked;
    }
  }
  std::cout << c.Name << ": " << checked << " surface pixels, " << background
            << " background pixels; worst relative depth error " << worstDepth
            << ", worst normal error " << worstAngle << " rad" << std::endl;
  FX_CHECK(checked > 1000 && (c.Plane || background > 1000),
    c.Name << ": the surface fills part of the view");
  return EXIT_SUCCESS;
}
}

// Points drawn as spheres and lines drawn as tubes (VTK's impostors, whose
// depth VTK computes in window space): the linear depth under a near/far
// ratio of 1e-6 equals the one under VTK's automatic clipping range within
// 1e-5 relative over every covered pixel (measured: identical; inverting
// gl_FragDepth, as before, was up to 6.9e-4 off; under the automatic range
// the two ways agree within 1.6e-7).
int CheckImpostorDepth(vtkRenderWindow* window)
{
  for (bool tubes : { false, true })
  {
    std::vector<float> depth[2];
    for (int extreme = 0; extreme < 2; ++extreme)
    {
      window->GetRenderers()->RemoveAllItems();
      vtkNew<vtkRenderer> renderer;
      window->AddRenderer(renderer);
      vtkNew<vtkPoints> points;
      points->InsertNextPoint(-0.5, 0.0, 0.0);
      points->InsertNextPoint(0.5, 0.2, -0.3);
      vtkNew<vtkCellArray> cells;
      const vtkIdType ids[2] = { 0, 1 };
      if (tubes)
      {
        cells->InsertNextCell(2, ids);
      }
      else
      {
        cells->InsertNextCell(1, &ids[0]);
        cells->InsertNextCell(1, &ids[1]);
      }
      vtkNew<vtkPolyData> poly;
      poly->SetPoints(points);
      if (tubes)
      {
        poly->SetLines(cells);
      }
      else
      {
        poly->SetVerts(cells);
      }
      vtkNew<vtkPolyDataMapper> mapper;
      mapper->SetInputData(poly);
      vtkNew<vtkActor> actor;
      actor->SetMapper(mapper);
      actor->GetProperty()->SetRenderPointsAsSpheres(!tubes);
      actor->GetProperty()->SetRenderLinesAsTubes(tubes);
      actor->GetProperty()->SetPointSize(40.0);
      actor->GetProperty()->SetLineWidth(20.0);
      renderer->AddActor(actor);
      vtkCamera* camera = renderer->GetActiveCamera();
      camera->SetFocalPoint(0, 0, 0);
      camera->SetPosition(0.3, 0.4, 3.0);
      camera->SetViewUp(0, 1, 0);
      renderer->ResetCameraClippingRange();
      if (extreme)
      {
        const double distance = camera->GetDistance();
        camera->SetClippingRange(distance * 1e-4, distance * 1e-4 / 1e-6);
      }
      vtkFXGBufferPass* gbuffer = vtkFXTest::InstallGBufferAlone(renderer);
      window->Render();
      depth[extreme] =
        vtkFXTest::Download(gbuffer->GetChannelTexture(vtkFXGBufferPass::LinearDepth), 1);
    }
    double worst = 0.0;
    int covered = 0, mismatched = 0;
    for (size_t i = 0; i < depth[0].size() && i < depth[1].size(); ++i)
    {
      if (depth[0][i] > 0.0f && depth[1][i] > 0.0f)
      {
        worst = std::max(worst, std::fabs(double(depth[1][i]) / depth[0][i] - 1.0));
        ++covered;
      }
      else if ((depth[0][i] > 0.0f) != (depth[1][i] > 0.0f))
      {
        ++mismatched; // (an edge pixel the two clipping ranges round differently)
      }
    }
    std::cout << (tubes ? "lines as tubes" : "points as spheres") << ", near/far 1e-6: " << covered
              << " pixels, linear depth at most " << worst << " off (relative), " << mismatched
              << " coverage differences" << std::endl;
    FX_CHECK(covered > 300 && worst <= 1e-5, "impostor depth at near/far 1e-6");
    FX_CHECK(mismatched * 50 < covered, "the impostors cover other pixels at near/far 1e-6");
  }
  return EXIT_SUCCESS;
}

int TestGBufferGeometry(int, char*[])
{
  const Case cases[] = {
    { "perspective", false, 1.0, 0.0, 0.0, false, false },
    { "parallel", true, 1.0, 0.0, 0.0, false, false },
    { "tiny scale 1e-6", false, 1e-6, 0.0, 0.0, false, false },
    { "huge scale 1e6", false, 1e6, 0.0, 0.0, false, false },
    { "parallel 1e6", true, 1e6, 0.0, 0.0, false, false },
    { "near/far 1e-6", false, 1.0, 0.0, 1e-6, false, false },
    { "plane", false, 1.0, 0.0, 0.0, true, false },
    { "plane far from origin 1e6", false, 1.0, 1e6, 0.0, true, false },
    { "parallel plane far from origin 1e6", true, 1.0, 1e6, 0.0, true, false },
    // Unlit: no view-space position in VTK's shader; in perspective the
    // fragment's clip w (exact at any near/far: inverting the window depth
    // gave infinite or negative depths beyond about 1e-7), in parallel
    // projection the window depth inverted (linear).
    { "unlit plane", false, 1.0, 0.0, 0.0, true, true },
    { "unlit plane, near/far 1e-8", false, 1.0, 0.0, 1e-8, true, true },
    { "unlit parallel plane", true, 1.0, 0.0, 0.0, true, true },
    // PBR: VTK's colour is kept, and its normal stored for the effects
    // (before, the unlit sentinel: no occlusion, no feature lines from it).
    { "PBR plane", false, 1.0, 0.0, 0.0, true, false, true },
    { "PBR sphere", false, 1.0, 0.0, 0.0, false, false, true },
    { "PBR parallel plane far from origin 1e6", true, 1.0, 1e6, 0.0, true, false, true },
  };
  // One window for all cases: each window is an X connection.
  auto window = vtkFXTest::MakeWindow(160, 120);
  for (const Case& c : cases)
  {
    if (RunCase(window, c) != EXIT_SUCCESS)
    {
      return EXIT_FAILURE;
    }
  }
  return CheckImpostorDepth(window);
}
