// vtkFXAVSMPass against transmittances known in closed form. A large
// opaque ground (z = 0) seen from above in parallel projection, one
// directional light straight down, and translucent slabs covering the half
// x < 0 of the ground at some heights. The pass's "visibility" output (the
// light's transmittance at each receiver) is read back:
// - one slab of opacity a: 1 - a under it, 1 elsewhere (within 1e-3), for
//   the AVSM curves (point and bilinear look-ups) and the exact lists;
// - two slabs: the product (also through the opacity shadow map of the
//   comparison); four slabs: AVSM-16 (room for 8 surfaces) equals the
//   exact mode;
// - opacity exactly 0 casts nothing and exactly 1 blocks all;
// - 1000 stacked layers of opacity 0.9999: finite, >= 0 (and 0), and the
//   resolved curves' optical depth never decreases along the ray;
// - a list buffer far too small: the capture counts what it dropped, warns
//   once, the frame stays finite and in range, the buffer grows, and the
//   next frame is right; a second overflow grows it again without a second
//   warning;
// - the same under a perspective camera;
// - a spot light (perspective map) gives the same shadow, and from
//   between two slabs only the slab below it casts;
// - a point light (no cone: six views, the faces of a cube) over the slab,
//   and between two slabs: the same shadow, from every face that sees the
//   ground; one 1000 units away over a slab 0.5 above the ground too;
// - two casting lights, the second tilted and with ShadowAttenuation 0.5:
//   each light's visibility in its channel (0.7, and 1 - 0.5 x 0.3), and
//   the composite darkens each light by its own;
// - a translucent receiver under a translucent caster: its lit colour
//   loses the caster's share (from 8-bit images, within 0.04);
// - point-gaussian splats are uniform-density spheres: under one, the
//   ground gets exp(-tau_c sqrt(1 - rho^2 / R^2)) at distance rho from its
//   axis, and a ground through its centre half of that optical depth;
//   under a spot light (one perspective view) and a point light (six) the
//   same with rho the light ray's distance from the centre (asserted 1e-3,
//   measured 2e-5: the chord had been taken at the offset on the splat's
//   triangle, off by up to 0.01 for a splat 7 units from the light);
// - splats shadow each other: of two in a row along the light, the far
//   one is darker by the near one's centre transmittance; four whose
//   chords overlap: AVSM-16 equals the exact mode;
// - coincident slabs give the product, a slab lying on the ground does not
//   shadow it (the bias), for AVSM-4, -8 and exact;
// - the same casters arriving in the opposite order give bit-identical
//   curves and visibility (AVSM-4, -8, -16; lists longer than one round of
//   the resolve's selection, with identical segments);
// - nothing translucent: the pass is left out, with its buffers.
#include "vtkFXAVSMPass.h"
#include "vtkFXCompositePass.h"
#include "vtkFXPipelinePass.h"
#include "vtkFXRenderUtilities.h"
#include "vtkFXScenes.h"
#include "vtkFXTestUtilities.h"

#include "vtkActorCollection.h"
#include "vtkAppendPolyData.h"
#include "vtkCallbackCommand.h"
#if VTKFX_HAS_RENDERING_LOD
#include "vtkLODActor.h"
#endif
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkPlaneSource.h"
#include "vtkCellArray.h"
#include "vtkActor2D.h"
#include "vtkAssembly.h"
#include "vtkPropAssembly.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkTexture.h"
#include "vtkImageShiftScale.h"
#include "vtkPiecewiseFunction.h"
#include "vtkFloatArray.h"
#include "vtkPointGaussianMapper.h"
#include "vtkGlyph3DMapper.h"
#include "vtkTransform.h"
#include "vtkSphereSource.h"
#include "vtkPoints.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRendererCollection.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"
#include "vtkPointData.h"
#include "vtkCellData.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkFXOpenGL.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <sstream>

namespace
{
const int Width = 200, Height = 150;

// The rectangle x0..x1 by -10..10 at height z (up to date).
vtkSmartPointer<vtkPlaneSource> QuadSource(double x0, double x1, double z)
{
  auto plane = vtkSmartPointer<vtkPlaneSource>::New();
  plane->SetOrigin(x0, -10.0, z);
  plane->SetPoint1(x1, -10.0, z);
  plane->SetPoint2(x0, 10.0, z);
  plane->Update();
  return plane;
}

// Its actor of opacity `opacity`, drawn from the source (which tests may
// change).
vtkSmartPointer<vtkActor> Quad(double x0, double x1, double z, double opacity)
{
  auto actor = vtkFXTest::SurfaceActor(QuadSource(x0, x1, z));
  actor->GetProperty()->SetOpacity(opacity);
  return actor;
}

// An actor drawing `source`'s output in its RGBA point colours (opacity
// from their alpha).
vtkSmartPointer<vtkActor> DirectColourActor(vtkAlgorithm* source)
{
  auto actor = vtkFXTest::SurfaceActor(source);
  auto* mapper = vtkPolyDataMapper::SafeDownCast(actor->GetMapper());
  mapper->SetColorModeToDirectScalars();
  mapper->SetScalarModeToUsePointData();
  return actor;
}

// Layers of opacity `opacity` at heights `heights`, as one prop.
vtkSmartPointer<vtkActor> Layers(const std::vector<double>& heights, double opacity)
{
  vtkNew<vtkAppendPolyData> append;
  for (double z : heights)
  {
    append->AddInputData(QuadSource(-10.0, 0.0, z)->GetOutput());
  }
  auto actor = vtkFXTest::SurfaceActor(append);
  actor->GetProperty()->SetOpacity(opacity);
  return actor;
}

// An actor of opacity `opacity` drawing `blocks` through a composite
// mapper, the first block at opacity `blockOpacity` (returned through
// `mapper`).
vtkSmartPointer<vtkActor> BlockSlab(vtkMultiBlockDataSet* blocks, double opacity,
  double blockOpacity, vtkCompositePolyDataMapper2** mapper = nullptr)
{
  vtkNew<vtkCompositePolyDataMapper2> blockMapper;
  blockMapper->SetInputDataObject(blocks);
  vtkNew<vtkCompositeDataDisplayAttributes> attributes;
  blockMapper->SetCompositeDataDisplayAttributes(attributes);
  blockMapper->SetBlockOpacity(1, blockOpacity); // (flat index 1: block 0)
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(blockMapper);
  actor->GetProperty()->SetOpacity(opacity);
  if (mapper)
  {
    *mapper = blockMapper;
  }
  return actor;
}

// A renderer alone in `window`, lit by one directional light straight
// down, with the opaque ground (returned through `ground`) and a camera
// looking down at it from z = 20.
vtkRenderer* GroundScene(vtkRenderWindow* window, bool parallel, vtkActor** ground = nullptr)
{
  window->GetRenderers()->RemoveAllItems();
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  renderer->AutomaticLightCreationOff();
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->PositionalOff();
  light->SetPosition(0.0, 0.0, 1.0);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->AddLight(light);
  auto floor = Quad(-10.0, 10.0, 0.0, 1.0);
  renderer->AddActor(floor);
  if (ground)
  {
    *ground = floor;
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 0.0, 20.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetParallelProjection(parallel);
  camera->SetParallelScale(4.0);
  camera->SetViewAngle(22.0);
  camera->SetClippingRange(5.0, 40.0);
  return renderer;
}

// The ground, the light and `casters` in a pipeline with `avsm`; renders
// `frames` frames and returns the visibility per pixel (rows bottom-up).
// `placeCamera`, when given, moves the viewer's camera.
// With spotHeight > 0 the light is a spot light that high over the origin,
// pointing at (spotAimX, 0, 0), with a cone of spotCone degrees (90 or
// more: a positional light shining every way, six views). A view angle
// above 54 degrees shows background around the ground.
std::vector<float> Visibility(vtkRenderWindow* window, vtkFXAVSMPass* avsm,
  const std::vector<vtkSmartPointer<vtkActor>>& casters, bool parallel, int frames = 1,
  double spotHeight = 0.0, double spotCone = 60.0, double spotAimX = 0.0, double viewAngle = 22.0,
  const std::function<void(vtkCamera*)>& placeCamera = nullptr)
{
  vtkRenderer* renderer = GroundScene(window, parallel);
  renderer->GetActiveCamera()->SetViewAngle(viewAngle);
  if (placeCamera)
  {
    placeCamera(renderer->GetActiveCamera());
  }
  if (spotHeight > 0.0)
  {
    renderer->RemoveAllLights();
    vtkNew<vtkLight> spot;
    spot->SetLightTypeToSceneLight();
    spot->PositionalOn();
    spot->SetPosition(0.0, 0.0, spotHeight);
    spot->SetFocalPoint(spotAimX, 0.0, 0.0);
    spot->SetConeAngle(spotCone);
    renderer->AddLight(spot);
  }
  for (const auto& caster : casters)
  {
    if (caster)
    {
      renderer->AddActor(caster);
    }
  }
  vtkNew<vtkFXPipelinePass> pipeline;
  pipeline->AddEffect("avsm", avsm);
  renderer->SetPass(pipeline);
  for (int f = 0; f < frames; ++f)
  {
    window->Render();
  }
  return vtkFXTest::Download(avsm->GetOutputTexture("visibility"), 1);
}

// Checks the left third of the image (under the casters) against `under`
// and the right third against 1, within `tolerance`; everything finite and
// in [0, 1].
int CheckHalves(const char* name, const std::vector<float>& v, double under, double tolerance)
{
  FX_CHECK(v.size() == static_cast<size_t>(Width) * Height, name << ": no visibility");
  double worstUnder = 0.0, worstOpen = 0.0;
  for (int y = 10; y < Height - 10; ++y)
  {
    for (int x = 0; x < Width; ++x)
    {
      const float t = v[static_cast<size_t>(y) * Width + x];
      FX_CHECK(std::isfinite(t) && t >= 0.0f && t <= 1.0f, name << ": " << t << " at " << x << "," << y);
      if (x < Width / 3)
      {
        worstUnder = std::max(worstUnder, std::fabs(t - under));
      }
      else if (x > 2 * Width / 3)
      {
        worstOpen = std::max(worstOpen, std::fabs(t - 1.0));
      }
    }
  }
  std::cout << name << " [left " << v[static_cast<size_t>(Height / 2) * Width + 10] << ", right " << v[static_cast<size_t>(Height / 2) * Width + Width - 10] << "]: under the casters off by " << worstUnder << ", in the open by "
            << worstOpen << std::endl;
  FX_CHECK(worstUnder <= tolerance && worstOpen <= tolerance,
    name << ": expected " << under << " and 1 within " << tolerance);
  return EXIT_SUCCESS;
}

// Whether two read-back textures hold the same bytes (and any at all).
bool SameBytes(const std::vector<float>& a, const std::vector<float>& b)
{
  return a.size() == b.size() && !a.empty() &&
    std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

vtkSmartPointer<vtkFXAVSMPass> MakeAVSM(int nodes, bool exact, bool bilinear)
{
  auto avsm = vtkSmartPointer<vtkFXAVSMPass>::New();
  avsm->SetNumberOfNodes(nodes);
  avsm->SetExact(exact);
  avsm->SetBilinear(bilinear);
  return avsm;
}

// Point-gaussian splats at `centers`, of scale `scale` and opacity
// `opacity` (white, unlit as VTK draws them); with `composite`, the cloud
// is the second block of a multi-block data set (the first one empty).
vtkSmartPointer<vtkActor> Splats(const std::vector<std::array<double, 3>>& centers, double scale,
  double opacity, bool composite = false)
{
  vtkNew<vtkPoints> points;
  for (const auto& c : centers)
  {
    points->InsertNextPoint(c.data());
  }
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(points);
  vtkNew<vtkPointGaussianMapper> mapper;
  if (composite)
  {
    vtkNew<vtkMultiBlockDataSet> blocks;
    blocks->SetNumberOfBlocks(2);
    blocks->SetBlock(0, vtkNew<vtkPolyData>());
    blocks->SetBlock(1, cloud);
    mapper->SetInputDataObject(blocks);
  }
  else
  {
    mapper->SetInputData(cloud);
  }
  mapper->SetScaleFactor(scale);
  mapper->EmissiveOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetOpacity(opacity);
  return actor;
}

// One splat of scale 1 and opacity 0.5 (centre optical depth ln 2) over
// the ground, seen through a 2048^2 map: the ground's transmittance at
// distance rho from the splat's axis is exp(-ln 2 sqrt(1 - rho^2 / R^2))
// for the sphere of radius R = SplatRadius (sqrt 3). With the ground
// through the splat's centre, the ground lies half-way along each chord:
// half the optical depth (less the bias's share, 0.028 units of the
// chord's 2 x 1.73: 0.6% of it, 0.004 in transmittance; 0.01 allowed).
// Checked off the rim (rho < 0.8 R or > 1.2 R), where the curve's slope is
// at most 0.23 per unit and the bilinear look-up's error, a quarter texel
// squared times the curvature, stays below 1e-4: 1e-3 allowed below the
// splat.
// With spotHeight > 0 the light is a spot (cone 60 degrees: one perspective
// view) or a point light (cone 90: six views) that high over the origin,
// and the chord is along the ray from the light: its distance d from the
// splat's centre takes rho's place (the axial factor of perspective views).
int CheckSplatSphere(vtkRenderWindow* window, bool exact, double height,
  double spotHeight = 0.0, double cone = 60.0, int mapSize = 2048, double splatX = 0.0)
{
  auto avsm = MakeAVSM(8, exact, true);
  avsm->SetShadowMapSize(mapSize);
  const double R = avsm->GetSplatRadius();
  const auto v = Visibility(
    window, avsm, { Splats({ { splatX, 0.0, height } }, 1.0, 0.5) }, true, 1, spotHeight, cone);
  FX_CHECK(v.size() == static_cast<size_t>(Width) * Height, "no visibility");
  const double fraction = height > 0.0 ? 1.0 : 0.5;
  const double unitsPerPixel = 8.0 / Height; // parallel scale 4
  double worst = 0.0, centre = -1.0;
  double worstX = 0, worstY = 0, worstGot = 0, worstWant = 0, worstRho = 0;
  for (int y = 0; y < Height; ++y)
  {
    for (int x = 0; x < Width; ++x)
    {
      const double px = (x + 0.5 - 0.5 * Width) * unitsPerPixel;
      const double py = (y + 0.5 - 0.5 * Height) * unitsPerPixel;
      double rho = std::sqrt(px * px + py * py);
      if (spotHeight > 0.0)
      {
        // Distance from the centre (splatX, 0, height) to the ray from the
        // light (0, 0, spotHeight) to the ground point (px, py, 0).
        double u[3] = { px, py, -spotHeight };
        vtkMath::Normalize(u);
        const double w[3] = { splatX, 0.0, height - spotHeight };
        const double along = vtkMath::Dot(w, u);
        rho = std::sqrt(std::max(0.0, vtkMath::Dot(w, w) - along * along));
      }
      const float t = v[static_cast<size_t>(y) * Width + x];
      FX_CHECK(std::isfinite(t) && t >= 0.0f && t <= 1.0f, "splat: " << t << " at " << x << "," << y);
      if (rho < 0.8 * R || rho > 1.2 * R)
      {
        const double chord = std::sqrt(std::max(0.0, 1.0 - rho * rho / (R * R)));
        const double expected = std::exp(-std::log(2.0) * chord * fraction);
        if (std::fabs(t - expected) > worst) { worstX = px; worstY = py; worstGot = t; worstWant = expected; worstRho = rho; }
        worst = std::max(worst, std::fabs(t - expected));
      }
      if (x == Width / 2 && y == Height / 2)
      {
        centre = t;
      }

    }
  }
  std::cout << "splat sphere (" << (exact ? "exact" : "AVSM-8") << ", ground "
            << (height > 0.0 ? "below" : "through the centre")
            << (spotHeight <= 0.0 ? "" : cone < 90.0 ? ", spot light" : ", point light")
            << (splatX != 0.0 ? ", off the light's axis" : "")
            << "): centre " << centre << ", largest error " << worst << " at (" << worstX << ", " << worstY << ") d/R " << worstRho / R << ": " << worstGot << " against " << worstWant << std::endl;
  FX_CHECK(worst < (height > 0.0 ? 1e-3 : 0.01), "splat sphere's shadow off by " << worst);
  return EXIT_SUCCESS;
}

// One splat of scale 1 and opacity 0.5 (sphere radius R = SplatRadius) at
// `height` over the origin, above the ground (scaled by `groundScale` in
// x and y), lit from straight above: the ground under it gets the whole
// chord, exp(-ln 2 sqrt(1 - rho^2 / R^2)), within 0.01 (checked within
// 0.8 of the axis, away from the ground's edge). The cases:
// - a splat whose sphere reaches out of the visible props' bounds (which
//   hold its centre only) and past the light view's near plane: height
//   1.8 over a ground 2 units wide (the view's near plane at 2.58, the
//   sphere's top at 3.53). The chord comes from the splat's centre depth,
//   so none of it is cut;
// - a splat of composite data, for which VTK 9.1's point-gaussian mapper
//   reports no bounds, at height 16, out of the bounding sphere of the
//   20-unit ground (radius 14.1): the light views must fit it too.
int CheckSplatShadowBelow(
  vtkRenderWindow* window, const char* name, double height, double groundScale, bool composite)
{
  auto avsm = MakeAVSM(8, false, true);
  avsm->SetShadowMapSize(2048);
  const double R = avsm->GetSplatRadius();
  const auto scaleGround = [window, groundScale](vtkCamera*) {
    vtkActor* ground = window->GetRenderers()->GetFirstRenderer()->GetActors()->GetLastActor();
    ground->SetScale(groundScale, groundScale, 1.0);
  };
  const auto v = Visibility(window, avsm, { Splats({ { 0.0, 0.0, height } }, 1.0, 0.5, composite) },
    true, 1, 0.0, 60.0, 0.0, 22.0, scaleGround);
  FX_CHECK(v.size() == static_cast<size_t>(Width) * Height, "no visibility");
  const double unitsPerPixel = 8.0 / Height; // parallel scale 4
  double worst = 0.0, centre = -1.0;
  for (int y = 0; y < Height; ++y)
  {
    for (int x = 0; x < Width; ++x)
    {
      const double px = (x + 0.5 - 0.5 * Width) * unitsPerPixel;
      const double py = (y + 0.5 - 0.5 * Height) * unitsPerPixel;
      if (std::max(std::fabs(px), std::fabs(py)) < 0.8)
      {
        const double rho = std::sqrt(px * px + py * py);
        const double expected = std::exp(-std::log(2.0) * std::sqrt(1.0 - rho * rho / (R * R)));
        worst = std::max(worst, std::fabs(v[static_cast<size_t>(y) * Width + x] - expected));
      }
    }
  }
  centre = v[static_cast<size_t>(Height / 2) * Width + Width / 2];
  std::cout << name << ": centre " << centre << " (expected 0.5), largest error " << worst
            << std::endl;
  FX_CHECK(worst < 0.01, name << ": shadow off by " << worst);
  return EXIT_SUCCESS;
}

// vtkFXRenderUtilities::GetDrawnBounds on splats, which VTK bounds by
// their cells (9.1: none for composite data without vertex cells) but
// draws at every point: the points' bounds through the actor's matrix,
// through the assembly path's for an assembly's part and the part's own
// in a vtkPropAssembly; blocks whose vertices hold only some points;
// invisible parts, empty clouds and 2D props draw nothing; a 3D prop
// without bounds draws anywhere; ComputeVisiblePropBounds takes the
// splats with the other props. Exact up to rounding (1e-12).
int CheckDrawnBounds()
{
  using RU = vtkFXRenderUtilities;
  const auto near = [](const double* a, const std::array<double, 6>& b) {
    for (int i = 0; i < 6; ++i)
    {
      if (!(std::fabs(a[i] - b[i]) <= 1e-12 * (1.0 + std::fabs(b[i]))))
      {
        return false;
      }
    }
    return true;
  };
  const auto text = [](const double* b) {
    std::ostringstream os;
    os << b[0] << " " << b[1] << " " << b[2] << " " << b[3] << " " << b[4] << " " << b[5];
    return os.str();
  };
  const auto cloud = [] { return Splats({ { -1.0, 0.0, 2.0 }, { 1.0, 0.5, 3.0 } }, 1.0, 0.5, true); };
  double b[6];
  // moved 5 along x, scaled 2 about its origin
  auto actor = cloud();
  actor->SetPosition(5.0, 0.0, 0.0);
  actor->SetScale(2.0);
  FX_CHECK(RU::GetDrawnBounds(actor, b) == RU::DrawsWithin && near(b, { 3, 7, 0, 1, 4, 6 }),
    "composite splats: bounds " << text(b));
  // a part of an assembly moved 10 along y (the part's own matrix, then
  // the assembly's), and of a vtkPropAssembly (its own only)
  vtkNew<vtkAssembly> assembly;
  assembly->AddPart(actor);
  assembly->SetPosition(0.0, 10.0, 0.0);
  FX_CHECK(RU::GetDrawnBounds(assembly, b) == RU::DrawsWithin && near(b, { 3, 7, 10, 11, 4, 6 }),
    "composite splats in an assembly: bounds " << text(b));
  auto inPropAssembly = cloud();
  inPropAssembly->SetPosition(5.0, 0.0, 0.0);
  vtkNew<vtkPropAssembly> props;
  props->AddPart(inPropAssembly);
  FX_CHECK(RU::GetDrawnBounds(props, b) == RU::DrawsWithin && near(b, { 4, 6, 0, 0.5, 2, 3 }),
    "composite splats in a vtkPropAssembly: bounds " << text(b));
  actor->UseBoundsOff();
  FX_CHECK(RU::GetDrawnBounds(assembly, b) == RU::DrawsNothing,
    "a part with UseBounds off counted in its assembly's bounds");
  actor->UseBoundsOn();
  actor->VisibilityOff();
  FX_CHECK(RU::GetDrawnBounds(assembly, b) == RU::DrawsNothing,
    "an invisible part counted in its assembly's bounds");
  actor->VisibilityOn();
  auto empty = Splats({}, 1.0, 0.5, true);
  FX_CHECK(RU::GetDrawnBounds(empty, b) == RU::DrawsNothing, "an empty cloud has bounds");
  vtkNew<vtkActor2D> flat;
  FX_CHECK(RU::GetDrawnBounds(flat, b) == RU::DrawsNothing, "a 2D prop has bounds");
  // Vertex cells on the first point only (VTK's bounds: that point), in
  // polydata and in the composite cloud's block.
  for (bool composite : { false, true })
  {
    auto partial = Splats({ { -1.0, 0.0, 2.0 }, { 1.0, 0.5, 3.0 } }, 1.0, 0.5, composite);
    auto* mapper = vtkPointGaussianMapper::SafeDownCast(partial->GetMapper());
    vtkDataObject* input = mapper->GetInputDataObject(0, 0);
    auto* blocks = vtkMultiBlockDataSet::SafeDownCast(input);
    auto* data = vtkPolyData::SafeDownCast(blocks ? blocks->GetBlock(1) : input);
    vtkNew<vtkCellArray> verts;
    verts->InsertNextCell({ 0 });
    data->SetVerts(verts);
    FX_CHECK(RU::GetDrawnBounds(partial, b) == RU::DrawsWithin && near(b, { -1, 1, 0, 0.5, 2, 3 }),
      (composite ? "composite " : "") << "splats with vertices at some points: bounds " << text(b));
  }
  // with a plain prop, in a renderer
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(Quad(-10.0, 10.0, 0.0, 1.0));
  renderer->AddActor(cloud());
  renderer->AddActor(empty);
  RU::ComputeVisiblePropBounds(renderer, b);
  FX_CHECK(near(b, { -10, 10, -10, 10, 0, 3 }), "visible props' bounds " << text(b));
  std::cout << "drawn bounds of splats: as expected" << std::endl;
  return EXIT_SUCCESS;
}

// Two white splats (scale 0.3, opacity 0.5) side by side at x = -1 and
// x = 1, z = 2, lit along -x only, over GroundScene's ground (which the
// light grazes: black), in a pipeline with `avsm`. The ground is returned
// (kept alive) so that callers can take it out and put it back.
vtkSmartPointer<vtkActor> SplatRow(vtkRenderWindow* window, vtkFXPipelinePass* pipeline,
  vtkFXAVSMPass* avsm, vtkRenderer** renderer)
{
  vtkActor* floor = nullptr;
  *renderer = GroundScene(window, true, &floor);
  vtkSmartPointer<vtkActor> ground = floor;
  (*renderer)->SetBackground(0.0, 0.0, 0.0);
  vtkLight* light = vtkLight::SafeDownCast((*renderer)->GetLights()->GetItemAsObject(0));
  light->SetPosition(1.0, 0.0, 0.0);
  (*renderer)->AddActor(Splats({ { -1.0, 0.0, 2.0 }, { 1.0, 0.0, 2.0 } }, 0.3, 0.5));
  pipeline->AddEffect("avsm", avsm);
  (*renderer)->SetPass(pipeline);
  return ground;
}

// Renders SplatRow's scene and checks the splats' centre pixels: each is
// the splat's alpha times its colour times the transmittance at its
// centre plane; the one at x = +1 sees half its own sphere, the one at
// x = -1 that and the whole other one, so their ratio is the near one's
// centre transmittance, 0.5; from 8-bit pixels of about 90 and 45,
// within 0.03.
int CheckSplatRow(vtkRenderWindow* window, const std::string& name)
{
  window->Render();
  const auto image = vtkFXScenes::Capture(window);
  const auto green = [&](double worldX) {
    const int x = static_cast<int>(0.5 * Width + worldX * Height / 8.0);
    return double(image[3 * (static_cast<size_t>(Height / 2) * Width + x) + 1]);
  };
  const double far = green(-1.0), near = green(1.0);
  std::cout << "splats in a row along the light, " << name << ": far " << far << ", near " << near
            << ", ratio " << far / std::max(near, 1.0) << " (expected 0.5)" << std::endl;
  FX_CHECK(near > 60.0 && std::fabs(far / near - 0.5) < 0.03,
    "splats do not shadow each other (" << name << ")");
  return EXIT_SUCCESS;
}

// Self-shadowing: SplatRow's splats, with the ground, and without it (no
// opaque prop: the pass runs before the G-buffer, which is left out, and
// looks nothing up for opaque receivers) the same.
int CheckSplatsShadowEachOther(vtkRenderWindow* window, bool withGround)
{
  vtkNew<vtkFXPipelinePass> pipeline;
  vtkNew<vtkFXAVSMPass> avsm;
  vtkRenderer* renderer = nullptr;
  auto ground = SplatRow(window, pipeline, avsm, &renderer);
  if (!withGround)
  {
    renderer->RemoveActor(ground);
  }
  FX_CHECK(CheckSplatRow(window, withGround ? "over the ground" : "no opaque prop") == EXIT_SUCCESS,
    "");
  // The passes that ran: no G-buffer or composite without the ground, the
  // shadows before the G-buffer then, after it otherwise.
  std::string ran;
  for (int i = 0; i < pipeline->GetNumberOfPassesThatRan(); ++i)
  {
    ran += std::string(pipeline->GetPassThatRan(i)) + ",";
  }
  const bool expected = withGround
    ? ran.find("gbuffer,avsm,") != std::string::npos
    : ran.find("avsm,") != std::string::npos && ran.find("gbuffer") == std::string::npos &&
      ran.find("composite") == std::string::npos;
  FX_CHECK(expected, "passes that ran: " << ran);
  if (!withGround)
  {
    // Capture and resolve only: no look-up output.
    FX_CHECK(avsm->GetStage() == vtkFXEffectPass::LightSpace && !avsm->GetOutputTexture("visibility"),
      "the pass ran as if an opaque prop received");
  }
  return EXIT_SUCCESS;
}

// One pipeline through frames with the ground, without it, with it again
// and without: the pass moves between the stages (after the G-buffer,
// before it), the splats shadow each other the same in every frame, and
// the look-up's output is there exactly while the ground is.
int CheckStageSwitching(vtkRenderWindow* window)
{
  vtkNew<vtkFXPipelinePass> pipeline;
  vtkNew<vtkFXAVSMPass> avsm;
  vtkRenderer* renderer = nullptr;
  auto ground = SplatRow(window, pipeline, avsm, &renderer);
  for (bool withGround : { true, false, true, false })
  {
    if (withGround)
    {
      renderer->AddActor(ground);
    }
    else
    {
      renderer->RemoveActor(ground);
    }
    FX_CHECK(CheckSplatRow(window, std::string("one pipeline, ") +
                 (withGround ? "with the ground" : "without it")) == EXIT_SUCCESS,
      "");
    FX_CHECK(avsm->GetStage() ==
        (withGround ? vtkFXEffectPass::AfterGBuffer : vtkFXEffectPass::LightSpace),
      "stage");
    FX_CHECK((avsm->GetOutputTexture("visibility") != nullptr) == withGround,
      "the look-up's output follows the opaque props");
  }
  return EXIT_SUCCESS;
}

// Deterministic output: the same casters captured in the opposite order
// (props and splats reversed, so every texel's list arrives reversed) give
// bit-identical curves and visibility for AVSM-4, -8 and -16; so does the
// resolve at every texel (CullResolveTiles off) against the one at the
// flagged tiles (where the context can flag them). The casters:
// 40 overlapping splats, one of them twice, and two identical slabs, so
// lists are longer than one round of the resolve's selection takes (4
// segments) and hold identical segments.
int CheckArrivalOrder(vtkRenderWindow* window)
{
  std::vector<std::array<double, 3>> centers;
  unsigned int state = 12345u;
  const auto next = [&state]() {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) / double(1u << 24);
  };
  for (int i = 0; i < 40; ++i)
  {
    centers.push_back({ -1.5 + 2.0 * next(), -1.0 + 2.0 * next(), 1.0 + 4.0 * next() });
  }
  centers.push_back(centers[7]);
  for (int nodes : { 4, 8, 16 })
  {
    // 0: in order, 1: reversed, 2: in order, every texel resolved
    std::vector<std::vector<float>> results[3];
    bool culled[3] = { false, false, false };
    for (int order = 0; order < 3; ++order)
    {
      auto points = centers;
      std::vector<vtkSmartPointer<vtkActor>> casters = { Splats(points, 0.5, 0.3),
        Quad(-10, 0, 0.6, 0.4), Quad(-10, 0, 0.6, 0.4) };
      if (order == 1)
      {
        std::reverse(points.begin(), points.end());
        casters = { Quad(-10, 0, 0.6, 0.4), Quad(-10, 0, 0.6, 0.4), Splats(points, 0.5, 0.3) };
      }
      auto avsm = MakeAVSM(nodes, false, true);
      avsm->SetCullResolveTiles(order != 2);
      results[order].push_back(Visibility(window, avsm, casters, true));
      culled[order] = avsm->GetResolveTilesCulled();
      for (int k = 0; k < avsm->GetNumberOfCurveTextures(); ++k)
      {
        results[order].push_back(vtkFXTest::Download(avsm->GetCurveTexture(k), 4));
      }
      // GetTexelCurve (vtkfx-bench's ray plot) reads the same curve as the
      // textures hold, at the texel with the longest list.
      int x = 0, y = 0;
      std::vector<double> depths, tau;
      FX_CHECK(avsm->GetLongestListTexel(x, y) && avsm->GetTexelCurve(x, y, depths, tau) &&
          static_cast<int>(depths.size()) == nodes && static_cast<int>(tau.size()) == nodes,
        "AVSM-" << nodes << ": no curve at the longest list's texel");
      // The frame's longest list, which fragments raise without reading it
      // atomically (the exact look-up walks that far), is that texel's.
      std::vector<double> entries, opticalDepths;
      FX_CHECK(avsm->GetTexelFragments(x, y, entries, opticalDepths) &&
          avsm->GetLongestList() == static_cast<vtkIdType>(entries.size()) && entries.size() > 4,
        "AVSM-" << nodes << ": longest list " << avsm->GetLongestList() << ", the longest texel's "
                << entries.size());
      const size_t texel = static_cast<size_t>(y) * avsm->GetCurveTexture(0)->GetWidth() + x;
      for (int i = 0; i < nodes; ++i)
      {
        const auto& depthTexture = results[order][1 + i / 4];
        const auto& tauTexture = results[order][1 + nodes / 4 + i / 4];
        FX_CHECK(depths[i] == depthTexture[4 * texel + i % 4] && tau[i] == tauTexture[4 * texel + i % 4],
          "AVSM-" << nodes << ": GetTexelCurve node " << i << " differs from the texture");
      }
    }
    // Texels whose curve uses every node (at least nodes / 2 segments).
    const std::vector<float>& lastDepths = results[0][results[0].size() / 2];
    int full = 0;
    for (size_t texel = 0; texel < lastDepths.size() / 4; ++texel)
    {
      full += lastDepths[4 * texel + 3] < 1e30f ? 1 : 0;
    }
    size_t differ[3] = { 0, 0, 0 };
    for (int other : { 1, 2 })
    {
      for (size_t r = 0; r < results[0].size(); ++r)
      {
        FX_CHECK(results[0][r].size() == results[other][r].size() && !results[0][r].empty(),
          "AVSM-" << nodes << ": missing output " << r);
        differ[other] += SameBytes(results[0][r], results[other][r]) ? 0 : 1;
      }
    }
    std::cout << "AVSM-" << nodes << ", casters in reverse order: " << differ[1] << " of "
              << results[0].size() << " outputs differ; every texel resolved against "
              << (culled[0] ? "flagged tiles only: " : "every texel (no tile flags here): ")
              << differ[2] << " differ; " << full << " texels use all " << nodes << " nodes"
              << std::endl;
    FX_CHECK(full > 100, "AVSM-" << nodes << ": only " << full << " texels with full curves");
    FX_CHECK(differ[1] == 0, "AVSM-" << nodes << " depends on the order fragments arrive in");
    FX_CHECK(differ[2] == 0, "AVSM-" << nodes << ": the resolve over flagged tiles differs");
    FX_CHECK(culled[0] == culled[1] && !culled[2] &&
        culled[0] == vtkFXRenderUtilities::CanFlagTiles(8),
      "AVSM-" << nodes << ": tiles culled " << culled[0] << culled[1] << culled[2]);
  }
  return EXIT_SUCCESS;
}

}

// The resolve over flagged tiles against the resolve at every texel where
// tiles cross views and the atlas's edge: a point light's six views of
// 100 texels (not a multiple of the 8-texel tile), splats and a slab over
// part of the ground. Visibility and every curve texture byte for byte.
// The culled pass first draws a frame of casters elsewhere, whose tiles
// its next resolve must empty (it empties the last frame's tiles rather
// than clearing every texel).
int CheckTilesAcrossViews(vtkRenderWindow* window)
{
  std::vector<std::array<double, 3>> centers;
  for (int i = 0; i < 12; ++i)
  {
    centers.push_back({ -1.5 + 0.25 * i, 0.3 * std::sin(i), 1.0 + 0.1 * i });
  }
  std::vector<std::vector<float>> results[2];
  bool culled[2] = { false, false };
  std::vector<float> flags;
  int atlasWidth = 0;
  for (int cull = 0; cull < 2; ++cull)
  {
    auto avsm = MakeAVSM(8, false, true);
    avsm->SetShadowMapSize(100);
    avsm->SetCullResolveTiles(cull == 1);
    if (cull == 1)
    {
      std::vector<std::array<double, 3>> elsewhere;
      for (const auto& c : centers)
      {
        elsewhere.push_back({ c[0] + 1.2, c[1] - 1.0, c[2] + 0.3 });
      }
      Visibility(window, avsm, { Splats(elsewhere, 0.5, 0.7), Quad(0, 10, 0.8, 0.4) }, false, 1,
        4.0, 90.0);
    }
    results[cull].push_back(Visibility(window, avsm,
      { Splats(centers, 0.4, 0.5), Quad(-10, 0, 0.5, 0.3) }, false, 1, 4.0, 90.0));
    culled[cull] = avsm->GetResolveTilesCulled();
    if (culled[cull])
    {
      flags = vtkFXTest::Download(avsm->GetResolveTileMask(), 1);
      atlasWidth = static_cast<int>(avsm->GetCurveTexture(0)->GetWidth());
    }
    for (int k = 0; k < avsm->GetNumberOfCurveTextures(); ++k)
    {
      results[cull].push_back(vtkFXTest::Download(avsm->GetCurveTexture(k), 4));
    }
  }
  size_t differ = 0;
  for (size_t r = 0; r < results[0].size(); ++r)
  {
    FX_CHECK(r < results[1].size() && results[0][r].size() == results[1][r].size() &&
        !results[0][r].empty(), "tiles across views: missing output " << r);
    differ += SameBytes(results[0][r], results[1][r]) ? 0 : 1;
  }
  // (texels with a curve: results[0][1] holds the first four node depths)
  size_t withCurve = 0;
  for (size_t texel = 0; texel < results[0][1].size() / 4; ++texel)
  {
    withCurve += results[0][1][4 * texel] < 1e30f ? 1 : 0;
  }
  std::cout << "point light, six views of 100 texels: flagged tiles only ("
            << (culled[1] ? "culled" : "not culled here") << ") against every texel: " << differ
            << " of " << results[0].size() << " outputs differ; " << withCurve
            << " texels with a curve" << std::endl;
  FX_CHECK(withCurve > 500, "tiles across views: only " << withCurve << " texels with a curve");
  // Every tile holding a curve is flagged, and some tiles are not (a mask
  // flagging every tile would give the same curves, only slower).
  if (culled[1])
  {
    const int tilesWide = (atlasWidth + 7) / 8;
    size_t flagged = 0, missed = 0;
    for (float f : flags)
    {
      flagged += f > 0.0f ? 1 : 0;
    }
    for (size_t texel = 0; texel < results[0][1].size() / 4; ++texel)
    {
      const size_t x = texel % atlasWidth, y = texel / atlasWidth;
      const size_t tile = (y / 8) * tilesWide + x / 8;
      missed += results[0][1][4 * texel] < 1e30f && !(tile < flags.size() && flags[tile] > 0.0f);
    }
    std::cout << "tiles across views: " << flagged << " of " << flags.size() << " tiles flagged, "
              << missed << " texels with a curve in an unflagged tile" << std::endl;
    FX_CHECK(missed == 0 && flagged > 0 && flagged < flags.size() / 2,
      "tiles across views: " << flagged << " of " << flags.size() << " tiles flagged, " << missed
                             << " texels with a curve unflagged");
  }
  FX_CHECK(differ == 0, "the resolve over flagged tiles differs across views");
  FX_CHECK(!culled[0] && culled[1] == vtkFXRenderUtilities::CanFlagTiles(8),
    "tiles across views: culled " << culled[0] << culled[1]);

  // Adaptive nodes, then regular slices in the same curve textures (the
  // same size and count, another empty curve: 0 where adaptive depths are
  // 3e38): every curve texel as a pass that only ever made slices.
  std::vector<std::vector<float>> slices[2];
  for (int fresh = 0; fresh < 2; ++fresh)
  {
    auto avsm = MakeAVSM(8, false, true);
    avsm->SetShadowMapSize(100);
    const std::vector<vtkSmartPointer<vtkActor>> casters = { Splats(centers, 0.4, 0.5),
      Quad(-10, 0, 0.5, 0.3) };
    if (!fresh)
    {
      Visibility(window, avsm, casters, false, 1, 4.0, 90.0);
    }
    avsm->SetRepresentation(vtkFXAVSMPass::RegularSlices);
    slices[fresh].push_back(Visibility(window, avsm, casters, false, 1, 4.0, 90.0));
    for (int k = 0; k < avsm->GetNumberOfCurveTextures(); ++k)
    {
      slices[fresh].push_back(vtkFXTest::Download(avsm->GetCurveTexture(k), 4));
    }
  }
  size_t slicesDiffer = 0;
  for (size_t r = 0; r < slices[0].size(); ++r)
  {
    slicesDiffer += r < slices[1].size() && SameBytes(slices[0][r], slices[1][r]) ? 0 : 1;
  }
  std::cout << "adaptive nodes then slices: " << slicesDiffer << " of " << slices[0].size()
            << " outputs differ from slices alone" << std::endl;
  FX_CHECK(slices[0].size() > 1 && slicesDiffer == 0,
    "slices after adaptive nodes differ from slices alone");
  return EXIT_SUCCESS;
}

// The look-up over the pixels the casters can shadow (CullLookUp) against
// the look-up at every pixel, byte for byte: splats and a slab over part
// of the ground under a directional light (parallel and perspective
// viewers), a spot light, a point light (six views) and a viewer near the
// ground looking along it, under the casters, where the shadowed ground
// reaches behind it (nothing is left out then); splats sized by an array
// in a scaled assembly; splats of composite data (whose bounds come from
// their blocks), alone and in a scaled assembly; and a ground whose lines
// would be 3 pixels wide (a receiver drawn past its bounds: nothing left
// out).
int CheckLookUpCulling(vtkRenderWindow* window)
{
  std::vector<std::array<double, 3>> centers;
  for (int i = 0; i < 10; ++i)
  {
    centers.push_back({ -2.0 + 0.15 * i, 0.4 * std::sin(i), 1.0 + 0.2 * i });
  }
  const auto lookAlongGround = [](vtkCamera* camera) {
    camera->SetPosition(-1.0, 0.0, 0.3);
    camera->SetFocalPoint(-8.0, 0.0, 0.2);
    camera->SetViewUp(0.0, 0.0, 1.0);
    camera->SetClippingRange(0.05, 30.0);
  };
  // Splats whose sizes come from an array (0.5 and 2, times the scale
  // factor), in an assembly that scales them by 1.5 about the origin:
  // VTK's bounds hold their centres only.
  const auto sizedSplats = [&centers]() {
    auto splats = Splats(centers, 0.2, 0.5);
    auto* mapper = vtkPointGaussianMapper::SafeDownCast(splats->GetMapper());
    vtkNew<vtkFloatArray> sizes;
    sizes->SetName("sizes");
    for (size_t i = 0; i < centers.size(); ++i)
    {
      sizes->InsertNextValue(i % 2 ? 2.0f : 0.5f);
    }
    vtkPolyData::SafeDownCast(mapper->GetInput())->GetPointData()->AddArray(sizes);
    mapper->SetScaleArray("sizes");
    vtkNew<vtkAssembly> assembly;
    assembly->AddPart(splats);
    assembly->SetScale(1.5);
    return vtkSmartPointer<vtkProp>(assembly);
  };
  // Splats from composite data: an empty block, then one whose sizes are
  // 3-vectors of length 2 (0.3 x 1.155 a component) read through an
  // out-of-range component (VTK then takes the vector's length), times
  // 0.2.
  const auto compositeSplats = [&centers]() {
    vtkNew<vtkPoints> points;
    vtkNew<vtkFloatArray> sizes;
    sizes->SetName("sizes");
    sizes->SetNumberOfComponents(3);
    for (const auto& c : centers)
    {
      points->InsertNextPoint(c.data());
      sizes->InsertNextTuple3(1.1547, 1.1547, 1.1547);
    }
    vtkNew<vtkPolyData> cloud;
    cloud->SetPoints(points);
    cloud->GetPointData()->AddArray(sizes);
    vtkNew<vtkMultiBlockDataSet> blocks;
    blocks->SetNumberOfBlocks(2);
    blocks->SetBlock(0, vtkNew<vtkPolyData>());
    blocks->SetBlock(1, cloud);
    vtkNew<vtkPointGaussianMapper> mapper;
    mapper->SetInputDataObject(blocks);
    mapper->SetScaleFactor(0.2);
    mapper->SetScaleArray("sizes");
    mapper->SetScaleArrayComponent(7);
    mapper->EmissiveOff();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetOpacity(0.5);
    return vtkSmartPointer<vtkProp>(actor);
  };
  // The same in an assembly that scales them by 1.5 about the origin and
  // moves them 3 units along x, out of where their blocks' bounds are
  // (VTK 9.1 reports no bounds for the part, and leaves it out of the
  // assembly's).
  const auto compositeSplatsInAssembly = [&compositeSplats]() {
    vtkNew<vtkAssembly> assembly;
    assembly->AddPart(vtkProp3D::SafeDownCast(compositeSplats()));
    assembly->SetScale(1.5);
    assembly->SetPosition(3.0, 0.0, 0.0);
    return vtkSmartPointer<vtkProp>(assembly);
  };
  const auto wideGroundLines = [window](vtkCamera*) {
    vtkActor* ground = window->GetRenderers()->GetFirstRenderer()->GetActors()->GetLastActor();
    ground->GetProperty()->SetLineWidth(3.0f);
  };
  struct Case
  {
    const char* Name;
    bool Parallel;
    double SpotHeight, SpotCone;
    std::function<void(vtkCamera*)> Place;
    int Culled; // 1: some pixels left out, 0: none, -1: either
    std::function<vtkSmartPointer<vtkProp>()> MakeSplats = nullptr; // else Splats(0.4, 0.5)
  };
  const Case cases[] = { { "directional light, parallel viewer", true, 0.0, 60.0, nullptr, 1 },
    { "directional light, perspective viewer", false, 0.0, 60.0, nullptr, 1 },
    { "spot light", false, 8.0, 40.0, nullptr, 1 }, { "point light", false, 4.0, 90.0, nullptr, -1 },
    { "viewer under the casters", false, 0.0, 60.0, lookAlongGround, 0 },
    { "splats sized by an array, in a scaled assembly", false, 0.0, 60.0, nullptr, 1, sizedSplats },
    { "splats of composite data sized by vector lengths (bounds from the blocks)", false, 0.0,
      60.0, nullptr, 1, compositeSplats },
    { "splats of composite data in a scaled assembly", false, 0.0, 60.0, nullptr, 1,
      compositeSplatsInAssembly },
    { "the ground with lines 3 pixels wide (anywhere)", false, 0.0, 60.0, wideGroundLines, 0 } };
  for (const Case& c : cases)
  {
    std::vector<float> v[2];
    int pixels[2] = { 0, 0 };
    for (int cull = 0; cull < 2; ++cull)
    {
      auto avsm = MakeAVSM(8, false, true);
      avsm->SetCullLookUp(cull == 1);
      vtkSmartPointer<vtkProp> splats =
        c.MakeSplats ? c.MakeSplats() : vtkSmartPointer<vtkProp>(Splats(centers, 0.4, 0.5));
      v[cull] = Visibility(window, avsm, { Quad(-10, -1.5, 0.5, 0.3) }, c.Parallel, 1,
        c.SpotHeight, c.SpotCone, 0.0, 22.0, [&](vtkCamera* camera) {
          if (c.Place)
          {
            c.Place(camera);
          }
          window->GetRenderers()->GetFirstRenderer()->AddViewProp(splats);
        });
      const int* r = avsm->GetLookUpPixels();
      pixels[cull] = std::max(0, r[2] - r[0]) * std::max(0, r[3] - r[1]);
    }
    size_t shadowed = 0;
    for (float t : v[0])
    {
      shadowed += t < 0.999f ? 1 : 0;
    }
    const bool same = SameBytes(v[0], v[1]);
    std::cout << "look-up culling, " << c.Name << ": " << pixels[1] << " of " << pixels[0]
              << " pixels looked up, " << shadowed << " shadowed, "
              << (same ? "identical" : "DIFFERENT") << std::endl;
    FX_CHECK(pixels[0] == Width * Height, c.Name << ": CullLookUp off left pixels out");
    FX_CHECK(shadowed > 500, c.Name << ": only " << shadowed << " shadowed pixels");
    FX_CHECK(same, c.Name << ": the culled look-up differs");
    FX_CHECK(c.Culled < 0 || (pixels[1] < pixels[0]) == (c.Culled == 1),
      c.Name << ": " << pixels[1] << " of " << pixels[0] << " pixels looked up");
  }
  // A small slab of opacity 0.6 whose shadow the screen holds on all four
  // sides, with the background looked up too (SkipBackground off) and
  // under a spot light whose cone's edge crosses the shadow: identical,
  // and the rectangle within 5 pixels of the shadow (the two texels' margin
  // is about 1 pixel here, the pad and the rounding 1 each).
  for (bool spot : { false, true })
  {
    std::vector<float> v[2];
    const int* r = nullptr;
    vtkSmartPointer<vtkFXAVSMPass> kept;
    for (int cull = 0; cull < 2; ++cull)
    {
      auto avsm = MakeAVSM(8, false, true);
      avsm->SetCullLookUp(cull == 1);
      avsm->SetSkipBackground(false);
      auto slab = Quad(-1.0, 1.0, 0.5, 0.6);
      slab->SetScale(1.0, 0.1, 1.0);
      slab->SetPosition(0.8, 0.5, 0.0);
      v[cull] = Visibility(window, avsm, { slab }, false, 1, spot ? 8.0 : 0.0, 7.0, 1.8);
      r = avsm->GetLookUpPixels();
      kept = avsm;
    }
    int lo[2] = { Width, Height }, hi[2] = { -1, -1 };
    for (int y = 0; y < Height; ++y)
    {
      for (int x = 0; x < Width; ++x)
      {
        if (v[0][static_cast<size_t>(y) * Width + x] < 0.999f)
        {
          lo[0] = std::min(lo[0], x);
          lo[1] = std::min(lo[1], y);
          hi[0] = std::max(hi[0], x);
          hi[1] = std::max(hi[1], y);
        }
      }
    }
    const bool same = SameBytes(v[0], v[1]);
    const char* name = spot ? "small slab, spot light's cone edge across it" : "small slab";
    std::cout << "look-up culling, " << name << ": shadow in pixels " << lo[0] << "-" << hi[0]
              << " x " << lo[1] << "-" << hi[1] << ", looked up " << r[0] << "-" << r[2] - 1
              << " x " << r[1] << "-" << r[3] - 1 << ", " << (same ? "identical" : "DIFFERENT")
              << std::endl;
    FX_CHECK(same, name << ": the culled look-up differs");
    FX_CHECK(lo[0] > 5 && lo[1] > 5 && hi[0] < Width - 6 && hi[1] < Height - 6,
      name << ": the shadow is not inside the screen");
    FX_CHECK(r[0] <= lo[0] && r[1] <= lo[1] && r[2] > hi[0] && r[3] > hi[1] &&
        lo[0] - r[0] <= 5 && lo[1] - r[1] <= 5 && r[2] - 1 - hi[0] <= 5 && r[3] - 1 - hi[1] <= 5,
      name << ": the rectangle is not within 5 pixels of the shadow");
  }
  return EXIT_SUCCESS;
}

// Two directional lights over the ground and a slab of opacity 0.3 at
// z = 1 over x < 0: A straight down (intensity 0.5), B from 45 degrees
// towards -x (intensity 0.4, ShadowAttenuation 0.5), both casting. The
// visibility's channel 0 is A's (the brighter): 0.7 under the slab;
// channel 1 B's: its shadow is the slab moved 1 unit towards -x, so the
// left third (x < -1.8) gets 1 - 0.5 x 0.3 = 0.85 and the right third 1.
// In the lit image the slab (0.3 of its own colour, which it does not
// shadow) lies over 0.7 of the ground, so against the image without
// shadows the left third changes by 0.7 (A (0.7 - 1) + B (0.85 - 1)),
// where A and B are the ground's light from each (the right third of the
// images without shadows, both lights and B alone), within 8-bit rounding:
// the two compared pixels 1 level, the ground under the slab rounded before
// the slab blends over it 0.7 x 0.5, the change from rounded pixels
// 0.7 x (0.3 x 1 + 0.15 x 0.5): 1.6, so 2 levels.
int CheckTwoLights(vtkRenderWindow* window)
{
  const auto render = [window](bool shadows, bool withA, vtkFXAVSMPass* avsm) {
    vtkRenderer* renderer = GroundScene(window, true);
    renderer->RemoveAllLights();
    vtkNew<vtkLight> a, b;
    for (vtkLight* light : { a.GetPointer(), b.GetPointer() })
    {
      light->SetLightTypeToSceneLight();
      light->PositionalOff();
      light->SetFocalPoint(0.0, 0.0, 0.0);
    }
    a->SetPosition(0.0, 0.0, 1.0);
    a->SetIntensity(0.5);
    a->SetSwitch(withA);
    b->SetPosition(1.0, 0.0, 1.0);
    b->SetIntensity(0.4);
    b->SetShadowAttenuation(0.5f);
    renderer->AddLight(a);
    renderer->AddLight(b);
    renderer->AddActor(Quad(-10.0, 0.0, 1.0, 0.3));
    vtkNew<vtkFXPipelinePass> pipeline;
    if (shadows)
    {
      pipeline->AddEffect("avsm", avsm);
    }
    renderer->SetPass(pipeline);
    window->Render();
    return vtkFXScenes::Capture(window);
  };
  vtkNew<vtkFXAVSMPass> avsm;
  avsm->SetMaximumNumberOfLights(2);
  const auto shadowed = render(true, true, avsm);
  FX_CHECK(avsm->GetNumberOfCastingLights() == 2 && avsm->GetCastingLightIndex(0) == 0 &&
      avsm->GetCastingLightIndex(1) == 1,
    "two casting lights expected, brightest first");
  // One channel per casting light: two lights, two channels (RG32F).
  vtkTextureObject* visibility = avsm->GetOutputTexture("visibility");
  FX_CHECK(visibility && visibility->GetComponents() == 2,
    "two casting lights: a two-channel visibility");
  const auto v = vtkFXTest::Download(visibility, 2);
  std::vector<float> channel[2];
  for (size_t i = 0; i + 1 < v.size(); i += 2)
  {
    channel[0].push_back(v[i]);
    channel[1].push_back(v[i + 1]);
  }
  FX_CHECK(CheckHalves("two lights, the brighter's channel", channel[0], 0.7, 1e-3) == EXIT_SUCCESS, "");
  FX_CHECK(CheckHalves("two lights, the tilted one's channel (attenuation 0.5)", channel[1], 0.85,
             1e-3) == EXIT_SUCCESS, "");
  const auto both = render(false, true, nullptr);
  const auto onlyB = render(false, false, nullptr);
  const auto green = [](const std::vector<unsigned char>& image, int x, int y) {
    return double(image[3 * (static_cast<size_t>(y) * Width + x) + 1]);
  };
  const double lightB = green(onlyB, Width - 20, Height / 2);
  const double lightA = green(both, Width - 20, Height / 2) - lightB;
  const double change = 0.7 * (lightA * (0.7 - 1.0) + lightB * (0.85 - 1.0));
  double worst = 0.0;
  for (int y = 10; y < Height - 10; ++y)
  {
    for (int x = 5; x < Width / 3; ++x)
    {
      worst = std::max(worst, std::fabs(green(shadowed, x, y) - green(both, x, y) - change));
    }
  }
  std::cout << "two lights, composite: ground lit " << lightA << " by A, " << lightB
            << " by B; under the slab " << green(both, 20, Height / 2) << " without shadows, "
            << green(shadowed, 20, Height / 2) << " with (" << change
            << " expected); largest error " << worst << " levels" << std::endl;
  FX_CHECK(lightA > 100 && lightB > 50 && worst <= 2.0,
    "the composite does not darken each light by its own visibility");
  return EXIT_SUCCESS;
}

// GroundScene's ground made black on a black background, with `props`
// added in order, through a pipeline without or with AVSM: the image.
std::vector<unsigned char> RenderOnBlackGround(vtkRenderWindow* window,
  const std::vector<vtkSmartPointer<vtkActor>>& props, bool shadows, bool withGround = true)
{
  vtkActor* ground = nullptr;
  vtkRenderer* renderer = GroundScene(window, true, &ground);
  renderer->SetBackground(0.0, 0.0, 0.0);
  ground->GetProperty()->SetColor(0.0, 0.0, 0.0);
  if (!withGround)
  {
    renderer->RemoveActor(ground);
  }
  for (const auto& prop : props)
  {
    renderer->AddActor(prop);
  }
  vtkNew<vtkFXPipelinePass> pipeline;
  if (shadows)
  {
    vtkNew<vtkFXAVSMPass> avsm;
    pipeline->AddEffect("avsm", avsm);
  }
  renderer->SetPass(pipeline);
  window->Render();
  return vtkFXScenes::Capture(window);
}

// Translucent receivers: a nearly opaque white slab (opacity 0.99) at
// z = 1 lit from straight above, under a slab of opacity 0.3 at z = 2 over
// x < 0, on a black ground. Drawn in that order, the upper slab blends over
// the lower one, so with AVSM (B) and without (C) the images differ only
// by the lower slab's shadowed light: B - C = 0.7 x 0.99 x L x (T - 1),
// where 0.99 L is the lower slab alone (A). So T = 1 + (B - C) / (0.7 A),
// expected 0.7 under the upper slab and 1 beside it, within what 8-bit
// images resolve: each of the three is rounded (half a level), against a
// difference of 0.7 x 202 x 0.3 = 42 levels: 1.5 / 42 = 0.036, so 0.04.
// Without the ground (nothing opaque) the same.
int CheckTranslucentReceiver(vtkRenderWindow* window, bool withGround)
{
  auto lower = Quad(-10.0, 10.0, 1.0, 0.99);
  lower->GetProperty()->SetDiffuse(0.8);
  lower->GetProperty()->SetAmbient(0.0);
  lower->GetProperty()->SetSpecular(0.0);
  auto top = Quad(-10.0, 0.0, 2.0, 0.3);
  top->GetProperty()->SetAmbient(0.0);
  top->GetProperty()->SetSpecular(0.0);
  using Actors = std::vector<vtkSmartPointer<vtkActor>>;
  const auto render = [&](bool upper, bool shadows) {
    return RenderOnBlackGround(
      window, upper ? Actors{ lower, top } : Actors{ lower }, shadows, withGround);
  };
  const auto alone = render(false, false);
  const auto shadowed = render(true, true);
  const auto unshadowed = render(true, false);
  double worstUnder = 0.0, worstOpen = 0.0;
  for (int y = 10; y < Height - 10; ++y)
  {
    for (int x : { 10, 30, 50, Width - 50, Width - 30, Width - 10 })
    {
      const size_t i = 3 * (static_cast<size_t>(y) * Width + x) + 1; // green
      const double t = 1.0 + (double(shadowed[i]) - double(unshadowed[i])) / (0.7 * alone[i]);
      if (x < Width / 2)
      {
        worstUnder = std::max(worstUnder, std::fabs(t - 0.7));
      }
      else
      {
        worstOpen = std::max(worstOpen, std::fabs(t - 1.0));
      }
    }
  }
  std::cout << "translucent receiver" << (withGround ? "" : ", no opaque prop")
            << ": lower slab lit " << int(alone[3 * (75 * Width + 10) + 1])
            << "/255; transmittance off by " << worstUnder << " under the upper slab, "
            << worstOpen << " beside it" << std::endl;
  FX_CHECK(alone[3 * (75 * Width + 10) + 1] > 150, "the lower slab is not lit");
  FX_CHECK(worstUnder < 0.04 && worstOpen < 0.04, "translucent receiver shadowed wrongly");
  return EXIT_SUCCESS;
}

// A nearly opaque white slab tilted 56 degrees to the light (z = 5 + 1.5 x)
// over a black ground: it casts into the curves and receives from them,
// and must not shadow itself. Its depth changes by 1.5 texels' widths
// across a texel of the light's view, so a look-up at its own depth reads
// its own surface in front of it in part of every texel (stripes, "acne");
// moved along its normal by 1.5 texels it does not. Lit the same with and
// without AVSM, within 2 levels (8-bit images; measured 0).
int CheckTiltedTranslucentReceiver(vtkRenderWindow* window)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-2.0, -3.0, 2.0);
  plane->SetPoint1(2.0, -3.0, 8.0);
  plane->SetPoint2(-2.0, 3.0, 2.0);
  auto slab = vtkFXTest::SurfaceActor(plane);
  slab->GetProperty()->SetOpacity(0.99);
  slab->GetProperty()->SetAmbient(0.0);
  slab->GetProperty()->SetSpecular(0.0);
  const std::vector<unsigned char> images[2] = { RenderOnBlackGround(window, { slab }, false),
    RenderOnBlackGround(window, { slab }, true) };
  int lit = 0, worst = 0;
  for (size_t i = 1; i < images[0].size(); i += 3)
  {
    if (images[0][i] > 40)
    {
      ++lit;
      worst = std::max(worst, std::abs(int(images[0][i]) - int(images[1][i])));
    }
  }
  std::cout << "tilted translucent receiver: " << lit << " pixels of the slab, lit at most " << worst
            << " levels differently with AVSM" << std::endl;
  FX_CHECK(lit > 2000, "the slab is not seen lit");
  FX_CHECK(worst <= 2, "the tilted slab shadows itself: " << worst << " levels");
  return EXIT_SUCCESS;
}

// What a frame shows of the shadows: the opaque receivers' visibility
// (when there are opaque props) and the image (the translucent receivers).
struct ShadowFrame
{
  std::vector<float> Visibility;
  std::vector<unsigned char> Image;
  bool operator==(const ShadowFrame& other) const
  {
    return this->Visibility == other.Visibility && this->Image == other.Image;
  }
  bool operator!=(const ShadowFrame& other) const { return !(*this == other); }
};

ShadowFrame RenderShadowFrame(vtkRenderWindow* window, vtkFXAVSMPass* avsm)
{
  window->Render();
  vtkTextureObject* visibility = avsm->GetOutputTexture("visibility");
  return { visibility ? vtkFXTest::Download(visibility, 1) : std::vector<float>(),
    vtkFXScenes::Capture(window) };
}

// A caster left out of the renderer's bounds (UseBounds off: a large
// surface an application keeps out of ResetCamera) high above the props:
// the light's view reaches it, and it shadows the ground by its opacity.
// (Fitted to the other props' bounding sphere, the view's near plane cut
// it off: no shadow at all.)
int CheckCasterOutsideBounds(vtkRenderWindow* window)
{
  vtkNew<vtkFXPipelinePass> pipeline;
  vtkNew<vtkFXAVSMPass> avsm;
  vtkRenderer* renderer = GroundScene(window, false);
  auto slab = Quad(-10, 0, 40, 0.3);
  slab->UseBoundsOff();
  renderer->AddActor(slab);
  pipeline->AddEffect("avsm", avsm);
  renderer->SetPass(pipeline);
  const ShadowFrame frame = RenderShadowFrame(window, avsm);
  return CheckHalves("a caster with UseBounds off, 40 units up", frame.Visibility, 0.7, 1e-3);
}

// Shadow maps kept between frames (ReuseShadowMaps): after each change
// below, a frame either reuses the last maps or makes new ones, as
// expected, and what it shows (visibility and image) equals the same frame
// made afresh (the pass Modified()) byte for byte; a change that must
// remake them also changes the shadows, so stale maps would fail.
int CheckShadowMapReuse(vtkRenderWindow* window)
{
  vtkNew<vtkFXPipelinePass> pipeline;
  vtkNew<vtkFXAVSMPass> avsm;
  vtkActor* ground = nullptr;
  vtkRenderer* renderer = GroundScene(window, false, &ground);
  vtkSmartPointer<vtkActor> keptGround = ground;
  vtkLight* light = vtkLight::SafeDownCast(renderer->GetLights()->GetItemAsObject(0));
  auto slab = Quad(-10, 0, 1, 0.3);
  renderer->AddActor(slab);
  pipeline->AddEffect("avsm", avsm);
  renderer->SetPass(pipeline);
  ShadowFrame last = RenderShadowFrame(window, avsm);
  FX_CHECK(!avsm->GetReusedShadowMaps(), "the first frame reused shadow maps");
  FX_CHECK(CheckHalves("kept shadow maps, first frame", last.Visibility, 0.7, 1e-3) == EXIT_SUCCESS, "");

  // A slab of composite data (a block's opacity, then the block itself).
  auto smallerPlane = QuadSource(-10.0, -5.0, 2.0);
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, QuadSource(-10.0, 0.0, 2.0)->GetOutput());
  vtkCompositePolyDataMapper2* blockMapper = nullptr;
  auto blockSlab = BlockSlab(blocks, 0.999, 0.5, &blockMapper);

  // Splats whose opacity goes through a transfer function.
  auto splats = Splats({ { 3.0, 0.0, 2.0 }, { 5.0, 2.0, 2.5 } }, 1.5, 0.5);
  auto* splatMapper = vtkPointGaussianMapper::SafeDownCast(splats->GetMapper());
  vtkPolyData* cloud = vtkPolyData::SafeDownCast(splatMapper->GetInputDataObject(0, 0));
  vtkNew<vtkFloatArray> splatOpacity;
  splatOpacity->SetName("opacity");
  splatOpacity->InsertNextValue(1.0f);
  splatOpacity->InsertNextValue(1.0f);
  cloud->GetPointData()->AddArray(splatOpacity);
  vtkNew<vtkPiecewiseFunction> opacityFunction;
  opacityFunction->AddPoint(0.0, 0.0);
  opacityFunction->AddPoint(1.0, 0.5);
  splatMapper->SetOpacityArray("opacity");
  splatMapper->SetScalarOpacityFunction(opacityFunction);

  // A texture whose alpha comes from a pipeline (scaled by 0.5, then 1).
  vtkNew<vtkImageData> white;
  white->SetDimensions(2, 2, 1);
  white->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
  std::fill_n(static_cast<unsigned char*>(white->GetScalarPointer()), 16, 255);
  vtkNew<vtkImageShiftScale> alpha;
  alpha->SetInputData(white);
  alpha->SetScale(0.5);
  alpha->SetOutputScalarTypeToUnsignedChar();
  vtkNew<vtkTexture> texture;
  texture->SetInputConnection(alpha->GetOutputPort());

  // An assembly of two slabs.
  vtkNew<vtkAssembly> assembly;
  auto assemblyPart = Quad(-10, -4, 4, 0.4);
  assembly->AddPart(assemblyPart);
  assembly->AddPart(Quad(-3, 0, 4.5, 0.4));

  // A level-of-detail actor: it picks the mapper it draws as it renders,
  // which no key can know before the capture. (Without VTK's RenderingLOD,
  // as in ParaView's VTK, a plain actor stands in, and the steps below
  // expect what a plain actor gets.)
#if VTKFX_HAS_RENDERING_LOD
  vtkNew<vtkLODActor> lod;
  const bool lodSwitches = true;
#else
  vtkNew<vtkActor> lod;
  const bool lodSwitches = false;
#endif
  vtkNew<vtkPolyDataMapper> lodMapper;
  lodMapper->SetInputConnection(QuadSource(2.0, 8.0, 3.0)->GetOutputPort());
  lod->SetMapper(lodMapper);
  lod->GetProperty()->SetOpacity(0.5);

  // Glyphs: a sphere of radius 1 at each of two points, on the mapper's
  // second input port (the source), which the first port's pipeline leaves
  // out; at a resolution of 4 it is an octahedron, of the same bounds.
  vtkNew<vtkPoints> glyphPoints;
  glyphPoints->InsertNextPoint(4.0, -4.0, 2.0);
  glyphPoints->InsertNextPoint(6.0, -2.0, 2.5);
  vtkNew<vtkPolyData> glyphCentres;
  glyphCentres->SetPoints(glyphPoints);
  vtkNew<vtkSphereSource> glyphShape;
  glyphShape->SetRadius(1.0);
  glyphShape->SetThetaResolution(32);
  glyphShape->SetPhiResolution(16);
  vtkNew<vtkGlyph3DMapper> glyphMapper;
  glyphMapper->SetInputData(glyphCentres);
  glyphMapper->SetSourceConnection(glyphShape->GetOutputPort());
  glyphMapper->ScalingOff();
  vtkNew<vtkActor> glyphs;
  glyphs->SetMapper(glyphMapper);
  glyphs->GetProperty()->SetOpacity(0.5);

  vtkPlaneSource* source = vtkPlaneSource::SafeDownCast(slab->GetMapper()->GetInputAlgorithm());
  vtkCamera* camera = renderer->GetActiveCamera();
  const struct
  {
    const char* What;
    std::function<void()> Change;
    bool Reused;
    bool Changes; // the shadows (a stale map would show), not only the view
  } steps[] = {
    { "nothing changed", [] {}, true, false },
    { "the camera dollied", [&] { camera->Dolly(1.2); }, true, false },
    { "the camera turned", [&] { camera->Roll(30.0); }, true, false },
    { "the slab's opacity", [&] { slab->GetProperty()->SetOpacity(0.6); }, false, true },
    { "the slab moved", [&] { slab->SetPosition(3.0, 0.0, 0.0); }, false, true },
    { "the slab's data", [&] { source->SetPoint1(-5.0, -10.0, 1.0); }, false, true },
    { "a texture on the slab", [&] { slab->SetTexture(texture); }, false, true },
    { "the texture's image upstream", [&] { alpha->SetScale(1.0); }, false, true },
    { "the light turned", [&] { light->SetPosition(0.3, 0.0, 1.0); }, false, true },
    { "a caster added", [&] { renderer->AddActor(blockSlab); }, false, true },
    { "unchanged again", [] {}, true, false },
    { "a block's opacity", [&] { blockMapper->SetBlockOpacity(1, 0.8); }, false, true },
    { "a block replaced",
      [&] {
        blocks->SetBlock(0, smallerPlane->GetOutput());
        blocks->Modified();
      },
      false, true },
    { "splats added", [&] { renderer->AddActor(splats); }, false, true },
    // (the splats drawn here look the same either way, in VTK's image too:
    // this checks only that the function's change remakes the maps)
    { "the splats' opacity function", [&] { opacityFunction->AddPoint(1.0, 0.9); }, false, false },
    { "glyphs added", [&] { renderer->AddActor(glyphs); }, false, true },
    { "glyphs, nothing changed", [] {}, true, false },
    { "the glyphs' shape, its bounds the same",
      [&] {
        glyphShape->SetThetaResolution(4);
        glyphShape->SetPhiResolution(4);
      },
      false, true },
    { "an assembly added", [&] { renderer->AddActor(assembly); }, false, true },
    // (its parts' matrices are poked every frame: their values are keyed)
    { "an assembly, the camera turned", [&] { camera->Roll(10.0); }, true, false },
    { "an assembly's part moved", [&] { assemblyPart->SetPosition(-1.0, 1.0, 0.0); }, false, true },
    // (two surfaces per texel, which 4 nodes keep exactly as 8 do)
    { "the nodes", [&] { avsm->SetNumberOfNodes(4); }, false, false },
    { "exact lists", [&] { avsm->SetExact(true); }, false, false },
    { "exact lists, unchanged", [] {}, true, false },
    { "the ground removed (light-space stage)", [&] { renderer->RemoveActor(keptGround); },
      false, true },
    { "no ground, the camera turned", [&] { camera->Roll(20.0); }, true, false },
    { "the ground back", [&] { renderer->AddActor(keptGround); }, false, true },
    { "the window resized", [&] { window->SetSize(Width + 37, Height + 21); }, true, false },
    { "the window's size back", [&] { window->SetSize(Width, Height); }, true, false },
    { "a camera light, the camera still",
      [&] {
        light->SetLightTypeToCameraLight();
        light->SetPosition(0.2, 0.0, 1.0);
        light->SetFocalPoint(0.0, 0.0, 0.0);
      },
      false, true },
    { "a camera light, the camera turned", [&] { camera->Elevation(10.0); }, false, true },
    { "a level-of-detail actor added", [&] { renderer->AddActor(lod); }, false, true },
    { "a level-of-detail actor, nothing changed", [] {}, !lodSwitches, false },
    { "the level-of-detail actor removed", [&] { renderer->RemoveActor(lod); }, false, true },
    { "reuse off", [&] { avsm->ReuseShadowMapsOff(); }, false, false },
    { "reuse off, nothing changed", [] {}, false, false },
  };
  for (const auto& step : steps)
  {
    step.Change();
    renderer->ResetCameraClippingRange();
    const ShadowFrame frame = RenderShadowFrame(window, avsm);
    const bool reused = avsm->GetReusedShadowMaps();
    // The same frame again with the maps made afresh, and (the view
    // unchanged) shadows unchanged against the frame before the change.
    avsm->Modified();
    const ShadowFrame remade = RenderShadowFrame(window, avsm);
    const bool changed = frame != last;
    std::cout << "kept shadow maps, " << step.What << ": " << (reused ? "reused" : "made again")
              << ", " << (frame == remade ? "same as made afresh" : "DIFFERS from made afresh")
              << (changed ? ", shadows or view changed" : "") << std::endl;
    FX_CHECK(!avsm->GetReusedShadowMaps(), step.What << ": a Modified() pass reused its maps");
    FX_CHECK(reused == step.Reused,
      step.What << ": expected the maps " << (step.Reused ? "reused" : "made again"));
    FX_CHECK(!frame.Image.empty() && frame == remade,
      step.What << ": the frame differs from the maps made afresh");
    FX_CHECK(!step.Changes || changed, step.What << ": the change did not change the shadows (the test has no teeth)");
    last = frame;
  }

  // Lists that dropped fragments (a buffer of one fragment per texel under
  // six slabs over half the map) are not kept: the next frame, with the
  // grown buffer, makes them again, and the one after reuses them.
  vtkNew<vtkFXPipelinePass> small;
  vtkNew<vtkFXAVSMPass> overflowing;
  overflowing->SetInitialNodesPerTexel(1);
  renderer = GroundScene(window, false);
  for (double z : { 1.0, 1.5, 2.0, 2.5, 3.0, 3.5 })
  {
    renderer->AddActor(Quad(-10, 0, z, 0.3));
  }
  small->AddEffect("avsm", overflowing);
  renderer->SetPass(small);
  bool reusedFrames[3];
  const vtkIdType capacity = vtkIdType(overflowing->GetShadowMapSize()) * overflowing->GetShadowMapSize();
  vtkIdType captured = 0;
  for (bool& frameReused : reusedFrames)
  {
    window->Render();
    frameReused = overflowing->GetReusedShadowMaps();
    captured = captured ? captured : overflowing->GetCapturedFragments();
  }
  std::cout << "kept shadow maps after an overflow (" << captured << " fragments, capacity "
            << capacity << "): frames " << reusedFrames[0] << reusedFrames[1] << reusedFrames[2]
            << " reused" << std::endl;
  FX_CHECK(captured > capacity && !reusedFrames[0] && !reusedFrames[1] && reusedFrames[2],
    "lists that dropped fragments were kept, or whole ones were not");
  return EXIT_SUCCESS;
}

// A light with a NaN intensity ahead of the sun in the renderer's list:
// it casts nothing and lights nothing in vtkFX's deferred lighting, and the
// sun's shadow still darkens the sun's own light, on VTK's uniforms and on the light texture (whose
// rows keep each light's place among the lights that are on): the image
// is the one without that light.
int CheckShadowsBesideNonFiniteLight(vtkRenderWindow* window)
{
  for (bool texture : { false, true })
  {
    std::vector<unsigned char> images[2];
    for (int withBad : { 0, 1 })
    {
      vtkNew<vtkFXPipelinePass> pipeline;
      vtkNew<vtkFXAVSMPass> avsm;
      vtkRenderer* renderer = GroundScene(window, true);
      // (unlit: VTK draws the translucent slab with its own light uniforms,
      // which a NaN light turns into NaN, as in VTK without vtkFX)
      auto slab = Quad(-10, 0, 1, 0.3);
      slab->GetProperty()->LightingOff();
      renderer->AddActor(slab);
      if (withBad)
      {
        vtkNew<vtkLight> bad;
        bad->SetLightTypeToSceneLight();
        bad->PositionalOff();
        bad->SetIntensity(std::numeric_limits<double>::quiet_NaN());
        vtkLight* sun = vtkLight::SafeDownCast(renderer->GetLights()->GetItemAsObject(0));
        vtkSmartPointer<vtkLight> keep = sun;
        renderer->RemoveAllLights();
        renderer->AddLight(bad);
        renderer->AddLight(keep);
      }
      if (texture)
      {
        pipeline->GetCompositePass()->SetMaximumUniformLights(0);
      }
      pipeline->AddEffect("avsm", avsm);
      renderer->SetPass(pipeline);
      window->Render();
      images[withBad] = vtkFXScenes::Capture(window);
      FX_CHECK(avsm->GetCastingLightIndex(0) == withBad,
        "the sun casts as light " << avsm->GetCastingLightIndex(0));
    }
    const int largest = vtkFXScenes::MaxDifference(images[0], images[1]);
    const auto green = [&](int x) { return int(images[1][3 * (size_t(Height / 2) * Width + x) + 1]); };
    std::cout << "a NaN light ahead of the casting sun" << (texture ? " (light texture)" : "")
              << ": " << largest << " levels off the image without it; under the slab "
              << green(10) << ", in the open " << green(Width - 10) << std::endl;
    FX_CHECK(largest <= 1 && green(10) < green(Width - 10) - 20,
      "a NaN light moved the sun's shadow onto another light");
  }
  return EXIT_SUCCESS;
}

// Two shadow frames of GroundScene with the translucent slab over its
// left half, in a fresh pipeline each: `arrange(renderer, moved)` sets up
// the first (moved false) and the second; each visibility is the opaque
// receivers'. `worst` receives the largest visibility difference (1 when
// the sizes differ), `levels` the images' largest difference.
void RenderFramePair(vtkRenderWindow* window, bool parallel,
  const std::function<void(vtkRenderer*, bool)>& arrange, ShadowFrame frames[2], double& worst,
  int& levels)
{
  for (int moved = 0; moved < 2; ++moved)
  {
    vtkNew<vtkFXPipelinePass> pipeline;
    vtkNew<vtkFXAVSMPass> avsm;
    vtkRenderer* renderer = GroundScene(window, parallel);
    renderer->AddActor(Quad(-10, 0, 1, 0.3));
    arrange(renderer, moved != 0);
    pipeline->AddEffect("avsm", avsm);
    renderer->SetPass(pipeline);
    frames[moved] = RenderShadowFrame(window, avsm);
    renderer->SetPass(nullptr);
  }
  worst = frames[0].Visibility.size() == frames[1].Visibility.size() ? 0.0 : 1.0;
  for (size_t i = 0; worst < 1.0 && i < frames[0].Visibility.size(); ++i)
  {
    worst = std::max(worst, std::fabs(double(frames[0].Visibility[i]) - frames[1].Visibility[i]));
  }
  levels = vtkFXScenes::MaxDifference(frames[0].Image, frames[1].Image);
}

// A camera with a model transform (vtkCamera::SetModelTransformMatrix, as
// VR cameras have): VTK's view coordinates are the model-view transform's,
// and a camera at (0, 0, 20) whose model transform moves the world by
// (2, 0, 0) draws what a camera at (-2, 0, 20) draws; so must the shadows
// (visibility within float rounding, images within a level). (VTK 9.1's
// GetViewTransformMatrix is the model-view transform, which the look-up
// takes back to the world: measured equal.)
int CheckCameraModelTransform(vtkRenderWindow* window)
{
  ShadowFrame frames[2];
  double worst = 1.0;
  int levels = 255;
  RenderFramePair(
    window, false,
    [](vtkRenderer* renderer, bool moved) {
      auto receiver = Quad(-10.0, 10.0, 0.5, 0.5);
      receiver->SetPosition(0.0, 6.0, 0.0); // (a translucent receiver over the upper part)
      renderer->AddActor(receiver);
      vtkCamera* camera = renderer->GetActiveCamera();
      if (moved)
      {
        vtkNew<vtkTransform> shift;
        shift->Translate(2.0, 0.0, 0.0);
        camera->SetModelTransformMatrix(shift->GetMatrix());
      }
      else
      {
        camera->SetPosition(-2.0, 0.0, 20.0);
        camera->SetFocalPoint(-2.0, 0.0, 0.0);
      }
    },
    frames, worst, levels);
  std::cout << "camera with a model transform: visibility off by " << worst << ", image by "
            << levels << " levels" << std::endl;
  FX_CHECK(!frames[0].Visibility.empty() && worst < 1e-3 && levels <= 1,
    "shadows under a camera's model transform");
  return EXIT_SUCCESS;
}

// A camera light under the renderer's user light transform (VTK moves such
// lights by it in view coordinates; VR renderers set it) casts its shadows
// from where VTK shades it: the same frame as a scene light placed there.
// Here the transform turns the light, which shines along the view (straight
// down), by 30 degrees about the view's y axis. (Fitted to the unmoved
// light, the shadow's edge lay 0.58 units off, under the slab's edge.)
int CheckUserLightTransform(vtkRenderWindow* window)
{
  ShadowFrame frames[2];
  double worst = 1.0;
  int levels = 255;
  RenderFramePair(
    window, true,
    [](vtkRenderer* renderer, bool moved) {
      renderer->RemoveAllLights();
      vtkNew<vtkLight> light;
      light->PositionalOff();
      if (moved)
      {
        light->SetLightTypeToCameraLight();
        light->SetPosition(0.0, 0.0, 1.0);
        light->SetFocalPoint(0.0, 0.0, 0.0);
        vtkNew<vtkTransform> turn;
        turn->RotateY(30.0);
        vtkOpenGLRenderer::SafeDownCast(renderer)->SetUserLightTransform(turn);
      }
      else
      {
        // (the view's axes are the world's, shifted along z)
        light->SetLightTypeToSceneLight();
        light->SetPosition(0.5, 0.0, std::sqrt(0.75));
        light->SetFocalPoint(0.0, 0.0, 0.0);
      }
      renderer->AddLight(light);
    },
    frames, worst, levels);
  const int shadowed = static_cast<int>(std::count_if(frames[0].Visibility.begin(),
    frames[0].Visibility.end(), [](float v) { return v < 0.9f; }));
  std::cout << "camera light under a user light transform: visibility off by " << worst
            << ", image by " << levels << " levels (" << shadowed << " pixels shadowed)"
            << std::endl;
  FX_CHECK(shadowed > 1000 && worst < 1e-3 && levels <= 1,
    "shadows of a light under the user light transform");
  return EXIT_SUCCESS;
}

// A point light standing in for the sun, 1e9 units above props of about
// 14 units: its rays are parallel there to within 1e-8 rad, and a
// perspective view from it cannot tell the props' depths apart in float
// (distance +- 14 is one float at 1e9: near = far). The shadow is the
// directional light's, finite: under a slab of 0.3, 0.7, and 1 beside it.
// Also a spot light, and a point light 500 radii away (its perspective
// view kept).
// (A spot light of 30 degrees from 7e3 or 200 units, outside the props'
// bounding sphere, gets the view fitted to the sphere: its cone's view
// spread the map over 8000 units at 7e3, the 20-unit ground under two
// texels, and the shadow's edge lost.)
int CheckFarLight(vtkRenderWindow* window)
{
  for (double height : { 1e9, 7e3, 200.0 })
  {
    for (double cone : { 30.0, 90.0 })
    {
      vtkNew<vtkFXAVSMPass> avsm;
      const auto v = Visibility(window, avsm, { Quad(-10, 0, 1, 0.3) }, true, 1, height, cone);
      std::ostringstream name;
      name << (cone < 90.0 ? "a spot light " : "a point light ") << height << " units above";
      FX_CHECK(CheckHalves(name.str().c_str(), v, 0.7, 2e-3) == EXIT_SUCCESS, name.str());
    }
  }
  return EXIT_SUCCESS;
}

int TestAVSM(int, char*[])
{
  auto window = vtkFXTest::MakeWindow(Width, Height);
  // A caster outside the camera's frustum (above and behind it; VTK's
  // culler leaves it out of the frame's props) still shadows the ground
  // the camera sees.
  {
    vtkNew<vtkFXAVSMPass> avsm;
    const auto v = Visibility(window, avsm, { Quad(-10.0, 0.0, 30.0, 0.4) }, true);
    FX_CHECK(CheckHalves("a caster behind the camera", v, 0.6, 1e-3) == EXIT_SUCCESS, "");
  }
  const struct
  {
    const char* Name;
    int Nodes;
    bool Exact, Bilinear;
  } modes[] = { { "exact bilinear", 8, true, true }, { "AVSM-8 bilinear", 8, false, true },
    { "AVSM-4 point", 4, false, false } };
  for (const auto& m : modes)
  {
    auto avsm = MakeAVSM(m.Nodes, m.Exact, m.Bilinear);
    const std::string one = std::string(m.Name) + ", one slab of 0.3";
    FX_CHECK(CheckHalves(one.c_str(), Visibility(window, avsm, { Quad(-10, 0, 1, 0.3) }, true),
               0.7, 1e-3) == EXIT_SUCCESS, one);
    const std::string two = std::string(m.Name) + ", slabs of 0.3 and 0.5";
    FX_CHECK(CheckHalves(two.c_str(),
               Visibility(window, avsm, { Quad(-10, 0, 1, 0.3), Quad(-10, 0, 2, 0.5) }, true),
               0.35, 1e-3) == EXIT_SUCCESS, two);
  }

  // The opacity shadow map of the comparison: receivers past the casters'
  // depth range get the whole sum, exactly.
  {
    auto osm = MakeAVSM(8, false, true);
    osm->SetRepresentation(vtkFXAVSMPass::RegularSlices);
    FX_CHECK(CheckHalves("opacity shadow map, slabs of 0.3 and 0.5",
               Visibility(window, osm, { Quad(-10, 0, 1, 0.3), Quad(-10, 0, 2, 0.5) }, true), 0.35,
               1e-3) == EXIT_SUCCESS, "");
  }

  // Four surfaces: 8 nodes, which AVSM-16 keeps exactly.
  const std::vector<vtkSmartPointer<vtkActor>> four = { Quad(-10, 0, 1, 0.2), Quad(-10, 0, 1.5, 0.4),
    Quad(-10, 0, 2, 0.6), Quad(-10, 0, 2.5, 0.1) };
  const auto exact = Visibility(window, MakeAVSM(8, true, true), four, true);
  const auto avsm16 = Visibility(window, MakeAVSM(16, false, true), four, true);
  double largest = 0.0;
  for (size_t i = 0; i < exact.size() && i < avsm16.size(); ++i)
  {
    largest = std::max(largest, static_cast<double>(std::fabs(exact[i] - avsm16[i])));
  }
  std::cout << "four slabs: AVSM-16 against exact, largest difference " << largest << std::endl;
  FX_CHECK(!exact.empty() && largest < 1e-5, "AVSM-16 differs from exact by " << largest);
  FX_CHECK(CheckHalves("four slabs, exact", exact, 0.8 * 0.6 * 0.4 * 0.9, 1e-3) == EXIT_SUCCESS, "");

  // 1000 layers of opacity 0.9999: optical depth 9210, transmittance 0.
  std::vector<double> heights;
  for (int i = 0; i < 1000; ++i)
  {
    heights.push_back(1.0 + i * 1e-3);
  }
  for (bool exactMode : { false, true })
  {
    auto avsm = MakeAVSM(8, exactMode, false);
    avsm->SetShadowMapSize(32);
    // Each layer shadowing the ones below, in exact mode, is 1000 x 1000
    // list steps per pixel: the receivers here are the ground.
    avsm->TranslucentReceiversOff();
    const auto v = Visibility(window, avsm, { Layers(heights, 0.9999) }, true, 2);
    FX_CHECK(CheckHalves(exactMode ? "1000 layers, exact" : "1000 layers, AVSM-8", v, 0.0, 1e-6) ==
        EXIT_SUCCESS, "");
    if (exactMode)
    {
      // The deep shadow map itself: along the ray with the most fragments,
      // 1000 segments, each of finite non-negative optical depth
      // (-ln 0.0001 = 9.21), so the transmittance in front of any depth
      // never increases along the ray.
      int x = 0, y = 0;
      std::vector<double> depths, tau;
      FX_CHECK(avsm->GetLongestListTexel(x, y) && avsm->GetTexelFragments(x, y, depths, tau),
        "no list to read back");
      double total = 0.0;
      for (double t : tau)
      {
        FX_CHECK(std::isfinite(t) && t >= 0.0, "a segment's optical depth " << t);
        total += t;
      }
      std::cout << "1000 layers, exact: " << tau.size() << " segments on the longest ray, optical "
                << "depth " << total << std::endl;
      FX_CHECK(tau.size() == 1000 && std::fabs(total - 1000 * -std::log(1e-4)) < 1.0,
        tau.size() << " segments of optical depth " << total);
    }
    else
    {
      // Along every light ray the curve's nodes go deeper and the optical
      // depth never decreases (transmittance never increases), finite.
      const int quarter = avsm->GetNumberOfCurveTextures() / 2;
      FX_CHECK(quarter == 2, "8 nodes make 2 + 2 curve textures, not " << 2 * quarter);
      std::vector<std::vector<float>> curves;
      for (int k = 0; k < 2 * quarter; ++k)
      {
        curves.push_back(vtkFXTest::Download(avsm->GetCurveTexture(k), 4));
      }
      int rays = 0;
      for (size_t texel = 0; texel < curves[0].size() / 4; ++texel)
      {
        float previousZ = -1.0f, previousTau = 0.0f;
        for (int node = 0; node < 8; ++node)
        {
          const float z = curves[node / 4][4 * texel + node % 4];
          const float tau = curves[quarter + node / 4][4 * texel + node % 4];
          FX_CHECK(std::isfinite(tau) && tau >= previousTau && z >= previousZ,
            "texel " << texel << " node " << node << ": depth " << z << ", optical depth " << tau);
          previousZ = z;
          previousTau = tau;
        }
        rays += previousTau > 1000.0f ? 1 : 0;
      }
      std::cout << "1000 layers: " << rays << " light rays through the layers, every curve monotone"
                << std::endl;
      FX_CHECK(rays > 100, "only " << rays << " rays through the layers");
    }
  }

  // More fragments than one storage block can address (llvmpipe: 128 MiB,
  // 8 Mi fragments of 16 bytes): 24 slabs over a 1024^2 map, each on
  // some 465 000 of its texels (11 Mi fragments), with a list buffer asked
  // for 64 per texel. The buffer stops
  // at what a block addresses (a larger one would be written only in
  // part, its lists pointing at nodes never stored); the fragments beyond
  // are left out with one warning, and the visibility stays finite, in
  // [0, 1], and no darker than the slabs make it (0.9^24).
  {
    auto avsm = MakeAVSM(8, false, true);
    avsm->SetShadowMapSize(1024);
    avsm->SetInitialNodesPerTexel(64);
    vtkFXTest::EventCounter warned(avsm, vtkCommand::WarningEvent);
    const int& warnings = warned.Count;
    std::vector<vtkSmartPointer<vtkActor>> slabs;
    const int layers = 24;
    for (int z = 1; z <= layers; ++z)
    {
      slabs.push_back(Quad(-10, 10, 0.5 * z, 0.1));
    }
    const auto v = Visibility(window, avsm, slabs, true, 2);
    GLint64 blockBytes = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &blockBytes);
    std::cout << layers << " slabs over 1024^2: " << avsm->GetCapturedFragments() << " fragments, capacity "
              << avsm->GetCapacity() << " (limit " << avsm->GetCapacityLimit() << ", storage block "
              << blockBytes << " bytes), " << warnings << " warning(s)" << std::endl;
    FX_CHECK(avsm->GetCapacityLimit() > 0 && avsm->GetCapacity() <= avsm->GetCapacityLimit() &&
        avsm->GetCapacity() * 16 <= blockBytes,
      "a list buffer of " << avsm->GetCapacity() << " fragments for a storage block of "
                          << blockBytes << " bytes");
    if (avsm->GetUsedSlots() > avsm->GetCapacityLimit())
    {
      FX_CHECK(warnings == 1, warnings << " warnings for fragments beyond the limit, not 1");
    }
    const float darkest = static_cast<float>(std::pow(0.9, layers));
    FX_CHECK(v.size() == static_cast<size_t>(Width) * Height, "no visibility beyond the limit");
    for (float t : v)
    {
      FX_CHECK(std::isfinite(t) && t >= darkest - 1e-3f && t <= 1.0f,
        "beyond the limit, visibility " << t);
    }
  }

  // List heads beyond one storage block: a positional light's six views
  // of 4096^2 texels need 384 MiB of heads (4 bytes per texel), above
  // llvmpipe's 128 MiB block. The pass says so once, however many frames,
  // allocates nothing for them, and the frame is the one the pipeline
  // draws with the pass disabled: no shadows of translucent props.
  {
    GLint64 blockBytes = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &blockBytes);
    const long long heads = 6LL * 4096 * 4096 * 4;
    // (the atlas, 3 x 2 views, must fit a texture, or the pass refuses it first)
    const int largest = vtkTextureObject::GetMaximumTextureSize(
      vtkOpenGLRenderWindow::SafeDownCast(window.GetPointer()));
    if (heads <= blockBytes || largest < 3 * 4096)
    {
      std::cout << "list heads over a storage block: not tried, this OpenGL's block holds "
                << blockBytes << " bytes, its textures " << largest << " texels" << std::endl;
    }
    else
    {
      auto avsm = MakeAVSM(8, false, true);
      avsm->SetShadowMapSize(4096);
      vtkFXTest::ErrorCounter failed(avsm);
      const auto v =
        Visibility(window, avsm, { Quad(-10, 0, 1, 0.3) }, true, 3, 6.0, 120.0);
      std::cout << "list heads over a storage block: " << failed.Count << " error(s): "
                << failed.Last << std::endl;
      FX_CHECK(avsm->GetNumberOfViews() == 0 && v.empty(),
        "a visibility texture (" << v.size() << " values) without lists");
      FX_CHECK(failed.Count == 1 && failed.Last.find("list heads") != std::string::npos,
        failed.Count << " errors for list heads over a storage block, not 1");
      const auto unshadowed = vtkFXScenes::Capture(window);
      avsm->EnabledOff();
      window->Render();
      const auto disabled = vtkFXScenes::Capture(window);
      FX_CHECK(!unshadowed.empty() && unshadowed == disabled,
        "the frame without lists differs from the frame without the pass");
      FX_CHECK(glGetError() == GL_NO_ERROR, "an OpenGL error after the refused lists");
    }
  }

  // A list buffer of 1 fragment per texel for up to 3 surfaces per texel:
  // the first frame drops fragments (and says so), the second is right.
  {
    auto avsm = MakeAVSM(8, false, true);
    avsm->SetInitialNodesPerTexel(1);
    avsm->SetShadowMapSize(64);
    vtkFXTest::EventCounter warned(avsm, vtkCommand::WarningEvent);
    const int& warnings = warned.Count;
    const std::vector<vtkSmartPointer<vtkActor>> slabs = { Quad(-10, 10, 1, 0.3),
      Quad(-10, 10, 2, 0.5), Quad(-10, 0, 3, 0.2) };
    const auto dropped = Visibility(window, avsm, slabs, true, 1);
    const vtkIdType firstCapacity = 64 * 64;
    std::cout << "overflow: " << avsm->GetCapturedFragments() << " fragments, capacity now "
              << avsm->GetCapacity() << ", " << warnings << " warning(s)" << std::endl;
    FX_CHECK(avsm->GetCapturedFragments() > firstCapacity && avsm->GetCapacity() > firstCapacity,
      "no overflow detected");
    FX_CHECK(warnings == 1, warnings << " warnings for the overflow, not 1");
    // The frame that dropped fragments is lighter, not broken.
    FX_CHECK(dropped.size() == static_cast<size_t>(Width) * Height, "no visibility after overflow");
    for (float t : dropped)
    {
      FX_CHECK(std::isfinite(t) && t >= 0.0f && t <= 1.0f, "after overflow, visibility " << t);
    }
    const auto v = Visibility(window, avsm, slabs, true, 1);
    FX_CHECK(avsm->GetUsedSlots() <= avsm->GetCapacity(), "still overflowing");
    // (the slots span at most about twice the fragments: see the crowded
    // case below)
    std::cout << "after overflow: " << avsm->GetCapturedFragments() << " fragments in "
              << avsm->GetUsedSlots() << " list slots" << std::endl;
    FX_CHECK(avsm->GetUsedSlots() <= 2 * avsm->GetCapturedFragments() + 64,
      avsm->GetUsedSlots() << " list slots for " << avsm->GetCapturedFragments() << " fragments");
    // Left: all three slabs; right: the two wide ones.
    double worst = 0.0;
    for (int y = 10; y < Height - 10; ++y)
    {
      worst = std::max(worst, std::fabs(v[static_cast<size_t>(y) * Width + 10] - 0.28));
      worst = std::max(worst, std::fabs(v[static_cast<size_t>(y) * Width + Width - 10] - 0.35));
    }
    FX_CHECK(worst < 1e-3, "after growing, off by " << worst);
    // More casters overflow the grown buffer again: it grows again, and the
    // warning is not repeated.
    const vtkIdType grown = avsm->GetCapacity();
    auto more = slabs;
    for (int i = 0; i < 6; ++i)
    {
      more.push_back(Quad(-10, 10, 4 + 0.5 * i, 0.1));
    }
    Visibility(window, avsm, more, true, 2);
    std::cout << "second overflow: capacity " << grown << " -> " << avsm->GetCapacity() << ", "
              << warnings << " warning(s) in all" << std::endl;
    FX_CHECK(avsm->GetCapacity() > grown && warnings == 1,
      "second overflow: capacity " << avsm->GetCapacity() << ", " << warnings << " warnings");
  }

  // Fragments crowded into one tile of the shadow map (layers transparent
  // but for a corner) crowd into one of the capture's node counters, and
  // their list slots span several times their number; the next capture
  // goes back to one counter (vtkFXAVSMPass::ChooseNodeCounters), the
  // slots are the fragments again, and the shadow is the same.
  {
    auto avsm = MakeAVSM(8, false, false);
    avsm->ReuseShadowMapsOff();
    vtkNew<vtkAppendPolyData> append;
    for (double z : { 1.0, 1.5, 2.0, 2.5, 3.0 })
    {
      auto plane = QuadSource(-10.0, 10.0, z);
      plane->SetXResolution(40);
      plane->SetYResolution(40);
      plane->Update();
      vtkPolyData* layer = plane->GetOutput();
      vtkNew<vtkUnsignedCharArray> rgba;
      rgba->SetNumberOfComponents(4);
      for (vtkIdType i = 0; i < layer->GetNumberOfPoints(); ++i)
      {
        double x[3];
        layer->GetPoint(i, x);
        const bool corner = x[0] < -9.4 && x[1] < -9.4;
        const unsigned char c[4] = { 200, 200, 200, static_cast<unsigned char>(corner ? 128 : 0) };
        rgba->InsertNextTypedTuple(c);
      }
      layer->GetPointData()->SetScalars(rgba);
      append->AddInputData(layer);
    }
    auto actor = DirectColourActor(append);
    const auto first = Visibility(window, avsm, { actor }, true);
    const vtkIdType crowdedSlots = avsm->GetUsedSlots();
    const vtkIdType crowdedFragments = avsm->GetCapturedFragments();
    const auto second = Visibility(window, avsm, { actor }, true);
    std::cout << "crowded fragments: " << crowdedFragments << " in " << crowdedSlots
              << " list slots, then " << avsm->GetCapturedFragments() << " in "
              << avsm->GetUsedSlots() << std::endl;
    FX_CHECK(crowdedFragments > 1000 && crowdedSlots > 2 * crowdedFragments + 64,
      "the corner's " << crowdedFragments << " fragments took " << crowdedSlots
                      << " slots: not crowded, the case shows nothing");
    FX_CHECK(avsm->GetUsedSlots() == avsm->GetCapturedFragments(),
      "after crowding, " << avsm->GetUsedSlots() << " slots for " << avsm->GetCapturedFragments()
                         << " fragments");
    FX_CHECK(!first.empty() && first == second, "the shadow changed with the counters");
    // 64 captures with one counter later, eight are tried again: crowded
    // again, and one counter the capture after (the shadow the same).
    Visibility(window, avsm, { actor }, true, 63);
    const vtkIdType oneCounter = avsm->GetUsedSlots();
    Visibility(window, avsm, { actor }, true);
    const vtkIdType retried = avsm->GetUsedSlots();
    const auto afterRetry = Visibility(window, avsm, { actor }, true);
    std::cout << "crowded fragments, captures 65 to 67: " << oneCounter << ", " << retried << ", "
              << avsm->GetUsedSlots() << " list slots" << std::endl;
    FX_CHECK(oneCounter == crowdedFragments && retried == crowdedSlots &&
        avsm->GetUsedSlots() == crowdedFragments && afterRetry == first,
      "eight counters not tried again after 64 captures, or not given up again");
  }

  // Opacity exactly 0 casts nothing, exactly 1 blocks all: RGBA colours
  // on two quads (left: alpha 255, right: alpha 0) of one translucent prop.
  {
    vtkNew<vtkAppendPolyData> append;
    for (int side = 0; side < 2; ++side)
    {
      vtkNew<vtkPlaneSource> plane;
      plane->SetOrigin(side ? 0.0 : -10.0, -10.0, 1.0);
      plane->SetPoint1(side ? 10.0 : 0.0, -10.0, 1.0);
      plane->SetPoint2(side ? 0.0 : -10.0, 10.0, 1.0);
      plane->Update();
      vtkNew<vtkUnsignedCharArray> rgba;
      rgba->SetNumberOfComponents(4);
      rgba->SetName("rgba");
      for (vtkIdType p = 0; p < plane->GetOutput()->GetNumberOfPoints(); ++p)
      {
        const unsigned char c[4] = { 200, 200, 200, static_cast<unsigned char>(side ? 0 : 255) };
        rgba->InsertNextTypedTuple(c);
      }
      plane->GetOutput()->GetPointData()->SetScalars(rgba);
      append->AddInputData(plane->GetOutput());
    }
    auto actor = DirectColourActor(append);
    const auto v = Visibility(window, MakeAVSM(8, false, false), { actor }, true);
    FX_CHECK(CheckHalves("opacity 1 and 0", v, 0.0, 1e-3) == EXIT_SUCCESS, "");
  }

  // Casters with NaN and infinite points and degenerate triangles, and a
  // splat at NaN of NaN scale, beside the slab: every pixel finite, in
  // [0, 1], and the slab's shadow as without them.
  for (bool exactMode : { false, true })
  {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    const double coordinates[][3] = { { 2, 1, 2 }, { 4, 1, 2 }, { nan, 2, 2 }, { 3, 3, 2 },
      { 3, 3, 2 }, { 3, 3, 2 }, { inf, 1, 2 }, { 5, -inf, 2 }, { 6, 1, nan },
      // one good triangle, around (3.75, -2)
      { 2.0, -3.5, 2 }, { 5.5, -3.5, 2 }, { 3.75, -0.5, 2 } };
    for (const auto& c : coordinates)
    {
      points->InsertNextPoint(c);
    }
    vtkNew<vtkCellArray> triangles;
    const vtkIdType cells[][3] = { { 0, 1, 2 }, { 3, 4, 5 }, { 0, 6, 7 }, { 1, 8, 3 }, { 0, 0, 1 },
      { 9, 10, 11 } };
    for (const auto& cell : cells)
    {
      triangles->InsertNextCell(3, cell);
    }
    vtkNew<vtkPolyData> bad;
    bad->SetPoints(points);
    bad->SetPolys(triangles);
    vtkNew<vtkPolyDataMapper> badMapper;
    badMapper->SetInputData(bad);
    auto badActor = vtkSmartPointer<vtkActor>::New();
    badActor->SetMapper(badMapper);
    badActor->GetProperty()->SetOpacity(0.5);
    // (and one good splat at (3.75, 2))
    auto badSplats = Splats({ { nan, 0.0, 2.0 }, { 2.0, inf, 2.0 }, { 3.75, 2.0, 2.0 } }, 0.5, 0.5);
    const auto v = Visibility(window, MakeAVSM(8, exactMode, true),
      { Quad(-10, 0, 1, 0.3), badActor, badSplats }, true);
    FX_CHECK(v.size() == static_cast<size_t>(Width) * Height, "no visibility");
    size_t bad01 = 0;
    double under = 0.0;
    for (int y = 10; y < Height - 10; ++y)
    {
      for (int x = 0; x < Width / 3; ++x)
      {
        under = std::max(under, std::fabs(v[static_cast<size_t>(y) * Width + x] - 0.7));
      }
    }
    for (float t : v)
    {
      bad01 += (std::isfinite(t) && t >= 0.0f && t <= 1.0f) ? 0 : 1;
    }
    // The good triangle's and splat's shadows (world (3.75, -2) and
    // (3.75, 2): the parallel view shows 4 units from the centre to the top).
    const auto at = [&v](double x, double y) {
      const int px = static_cast<int>(0.5 * Width + x * 0.5 * Height / 4.0);
      const int py = static_cast<int>(0.5 * Height + y * 0.5 * Height / 4.0);
      return v[static_cast<size_t>(py) * Width + px];
    };
    std::cout << (exactMode ? "exact" : "AVSM-8") << ", NaN and infinite casters beside a slab: "
              << bad01 << " pixels not finite in [0, 1], the slab's shadow off by " << under
              << "; under their good triangle " << at(3.75, -2.0) << ", their good splat "
              << at(3.75, 2.0) << std::endl;
    FX_CHECK(bad01 == 0 && under <= 1e-3, "NaN or infinite casters broke the shadows");
    // (the mesh's good triangle casts nothing: its infinite points collapse
    // its bounds, and VTK draws nothing of it either, with or without vtkFX)
    FX_CHECK(at(3.75, 2.0) < 0.9, "the finite splat beside the bad ones casts nothing");
  }

  // Coincident surfaces: two identical slabs at one height are two
  // segments of zero thickness at the same depth (the resolve merges them
  // into one of twice the optical depth): the product, 0.49. A slab lying
  // on the ground is at the receiver's own depth: the bias keeps it from
  // shadowing what it lies on (1), and nothing is NaN.
  for (int nodes : { 4, 8, 0 }) // 0: exact
  {
    const std::string name = nodes ? "AVSM-" + std::to_string(nodes) : std::string("exact");
    FX_CHECK(CheckHalves((name + ", two coincident slabs of 0.3").c_str(),
               Visibility(window, MakeAVSM(nodes ? nodes : 8, nodes == 0, true),
                 { Quad(-10, 0, 1, 0.3), Quad(-10, 0, 1, 0.3) }, true),
               0.49, 1e-3) == EXIT_SUCCESS, "");
    FX_CHECK(CheckHalves((name + ", a slab of 0.3 on the ground").c_str(),
               Visibility(window, MakeAVSM(nodes ? nodes : 8, nodes == 0, true),
                 { Quad(-10, 0, 0, 0.3) }, true),
               1.0, 1e-3) == EXIT_SUCCESS, "");
    // Without the bias the receiver lies at the slab's nodes up to
    // rounding (the receiver's light depth is computed, the slab's
    // rasterised): each pixel is either lit or behind the slab, finite.
    auto unbiased = MakeAVSM(nodes ? nodes : 8, nodes == 0, true);
    unbiased->SetBias(0.0);
    const auto v = Visibility(window, unbiased, { Quad(-10, 0, 0, 0.3) }, true);
    FX_CHECK(v.size() == static_cast<size_t>(Width) * Height, name << ", no bias: no visibility");
    // (between the two, only along the slab's edge, where the bilinear
    // look-up blends)
    size_t shadowed = 0, other = 0;
    for (size_t i = 0; i < v.size(); ++i)
    {
      const float t = v[i];
      const int x = static_cast<int>(i % Width);
      const bool blend = x > Width / 3 && x < 2 * Width / 3;
      shadowed += std::fabs(t - 0.7f) < 1e-3f ? 1 : 0;
      const bool defined = std::isfinite(t) &&
        (blend ? t > 0.699f && t < 1.001f
               : std::fabs(t - 0.7f) < 1e-3f || std::fabs(t - 1.0f) < 1e-3f);
      other += defined ? 0 : 1;
    }
    std::cout << name << ", no bias, a slab of 0.3 on the ground: " << shadowed
              << " pixels behind it, " << other << " neither lit nor behind it" << std::endl;
    FX_CHECK(other == 0, name << ", no bias: " << other << " pixels neither 1 nor 0.7");
  }

  // Eight surfaces (16 nodes, what AVSM-16 holds exactly), four over the
  // ground and four under it, so that the receiver lies inside the curve:
  // AVSM-16 equals the exact lists and both give the product of the four
  // above.
  {
    std::vector<vtkSmartPointer<vtkActor>> eight;
    double product = 1.0;
    for (int i = 0; i < 8; ++i)
    {
      const double opacity = 0.05 + 0.1 * i;
      const double height = -1.4 + 0.4 * i;
      eight.push_back(Quad(-10, 0, height, opacity));
      product *= height > 0.0 ? 1.0 - opacity : 1.0;
    }
    const auto exactEight = Visibility(window, MakeAVSM(8, true, true), eight, true);
    const auto avsmEight = Visibility(window, MakeAVSM(16, false, true), eight, true);
    double largest = 0.0;
    for (size_t i = 0; i < exactEight.size() && i < avsmEight.size(); ++i)
    {
      largest = std::max(largest, static_cast<double>(std::fabs(exactEight[i] - avsmEight[i])));
    }
    // (AVSM-8 cannot hold them: it must differ, or the scene tests nothing)
    const auto avsm8Eight = Visibility(window, MakeAVSM(8, false, true), eight, true);
    double largest8 = 0.0;
    for (size_t i = 0; i < exactEight.size() && i < avsm8Eight.size(); ++i)
    {
      largest8 = std::max(largest8, static_cast<double>(std::fabs(exactEight[i] - avsm8Eight[i])));
    }
    std::cout << "eight slabs: AVSM-16 against exact, largest difference " << largest
              << " (AVSM-8: " << largest8 << ")" << std::endl;
    FX_CHECK(!exactEight.empty() && exactEight.size() == avsmEight.size() && largest < 1e-5,
      "eight slabs: AVSM-16 differs from exact by " << largest);
    FX_CHECK(largest8 > 1e-3, "eight slabs fit in AVSM-8 too (" << largest8 << ")");
    FX_CHECK(CheckHalves("eight slabs, AVSM-16", avsmEight, product, 1e-3) == EXIT_SUCCESS, "");
  }

  // No light that can cast (only a headlight, or a casting light switched
  // off or with ShadowAttenuation 0): the pass is left out, with its
  // buffers, although a prop is translucent.
  for (int variant = 0; variant < 3; ++variant)
  {
    auto idle = MakeAVSM(8, false, true);
    vtkRenderer* renderer = GroundScene(window, true);
    vtkLight* light = vtkLight::SafeDownCast(renderer->GetLights()->GetItemAsObject(0));
    if (variant == 0)
    {
      light->SetLightTypeToHeadlight();
    }
    else if (variant == 1)
    {
      light->SwitchOff();
    }
    else
    {
      light->SetShadowAttenuation(0.0);
    }
    renderer->AddActor(Quad(-10, 0, 1, 0.3));
    vtkNew<vtkFXPipelinePass> pipeline;
    pipeline->AddEffect("avsm", idle);
    renderer->SetPass(pipeline);
    window->Render();
    const char* names[] = { "a headlight", "a light switched off", "ShadowAttenuation 0" };
    std::cout << "translucent slab, " << names[variant] << ": " << idle->GetCapacity()
              << " nodes allocated" << std::endl;
    FX_CHECK(idle->GetCapacity() == 0 && !idle->GetOutputTexture("visibility"),
      "with " << names[variant] << " the AVSM holds " << idle->GetCapacity() << " nodes");
  }

  FX_CHECK(CheckTranslucentReceiver(window, true) == EXIT_SUCCESS, "translucent receiver");
  FX_CHECK(CheckTranslucentReceiver(window, false) == EXIT_SUCCESS,
    "translucent receiver without an opaque prop");
  FX_CHECK(CheckTiltedTranslucentReceiver(window) == EXIT_SUCCESS, "tilted translucent receiver");

  // A spot light: the perspective map gives the same shadow; from between
  // two slabs (the light inside the "cloud") only the one below casts (a
  // cone of 85 degrees, so that the whole view is in it).
  FX_CHECK(CheckHalves("spot light, one slab",
             Visibility(window, MakeAVSM(8, false, true), { Quad(-10, 0, 1, 0.3) }, true, 1, 6.0),
             0.7, 1e-3) == EXIT_SUCCESS, "");
  FX_CHECK(CheckHalves("spot light aimed off the data's centre",
             Visibility(window, MakeAVSM(8, false, true), { Quad(-10, 0, 1, 0.3) }, true, 1, 6.0,
               80.0, -8.0),
             0.7, 1e-3) == EXIT_SUCCESS, "");
  FX_CHECK(CheckHalves("spot light between two slabs",
             Visibility(window, MakeAVSM(8, false, true),
               { Quad(-10, 0, 1, 0.3), Quad(-10, 0, 2, 0.5) }, true, 1, 1.5, 85.0),
             0.7, 1e-3) == EXIT_SUCCESS, "");

  for (bool exactSplat : { true, false })
  {
    FX_CHECK(CheckSplatSphere(window, exactSplat, 3.0) == EXIT_SUCCESS, "splat over the ground");
    FX_CHECK(CheckSplatSphere(window, exactSplat, 0.0) == EXIT_SUCCESS, "splat in the ground");
  }
  // (the compressed curves only: the chord is the capture's, shared by both
  // modes; the point light's six views at 1024^2, whose four times larger
  // bilinear error, from 6e-6 at 2048^2, stays far below 1e-3)
  {
    FX_CHECK(CheckSplatSphere(window, false, 3.0, 10.0, 60.0) == EXIT_SUCCESS,
      "splat under a spot light");
    FX_CHECK(CheckSplatSphere(window, false, 3.0, 10.0, 90.0, 1024) == EXIT_SUCCESS,
      "splat under a point light");
    // 27 degrees off the spot's axis: the splat's triangle faces the light,
    // not the view's axis, so a fragment's offset is across the ray from
    // the light (its shadow is the same circle's, stretched on the ground).
    FX_CHECK(CheckSplatSphere(window, false, 4.0, 8.0, 60.0, 2048, 2.0) == EXIT_SUCCESS,
      "splat off a spot light's axis");
  }
  FX_CHECK(CheckSplatsShadowEachOther(window, true) == EXIT_SUCCESS, "splat self-shadowing");
  FX_CHECK(CheckSplatsShadowEachOther(window, false) == EXIT_SUCCESS,
    "splat self-shadowing without an opaque prop");
  FX_CHECK(CheckStageSwitching(window) == EXIT_SUCCESS, "frames with and without opaque props");
  FX_CHECK(CheckArrivalOrder(window) == EXIT_SUCCESS, "order independence");
  FX_CHECK(CheckLookUpCulling(window) == EXIT_SUCCESS, "look-up culling");
  FX_CHECK(CheckCameraModelTransform(window) == EXIT_SUCCESS, "camera model transform");
  FX_CHECK(CheckUserLightTransform(window) == EXIT_SUCCESS, "user light transform");
  FX_CHECK(CheckSplatShadowBelow(window, "splat reaching out of the props' bounds towards the light",
             1.8, 0.1, false) == EXIT_SUCCESS,
    "splat reaching out of the bounds");
  FX_CHECK(CheckDrawnBounds() == EXIT_SUCCESS, "drawn bounds");
  FX_CHECK(CheckSplatShadowBelow(window, "splat of composite data out of the other props' bounds",
             16.0, 1.0, true) == EXIT_SUCCESS,
    "composite splats out of the bounds");
  FX_CHECK(CheckTilesAcrossViews(window) == EXIT_SUCCESS, "flagged tiles across views");
  // Four splats whose chords overlap along the light (scale 0.6, centres
  // 0.5 apart, spheres 2.1 across): 8 entries and exits, which AVSM-16
  // keeps exactly.
  {
    const std::vector<vtkSmartPointer<vtkActor>> column = { Splats(
      { { 0.0, 0.0, 2.0 }, { 0.3, 0.0, 2.5 }, { -0.2, 0.1, 3.0 }, { 0.1, -0.3, 3.5 } }, 0.6, 0.4) };
    const auto exactColumn = Visibility(window, MakeAVSM(8, true, true), column, true);
    const auto avsmColumn = Visibility(window, MakeAVSM(16, false, true), column, true);
    double worst = 0.0, darkest = 1.0;
    for (size_t i = 0; i < exactColumn.size() && i < avsmColumn.size(); ++i)
    {
      worst = std::max(worst, static_cast<double>(std::fabs(exactColumn[i] - avsmColumn[i])));
      darkest = std::min(darkest, static_cast<double>(exactColumn[i]));
    }
    std::cout << "four overlapping splats: darkest " << darkest << ", AVSM-16 against exact "
              << worst << std::endl;
    FX_CHECK(!exactColumn.empty() && darkest < 0.3 && worst < 1e-5,
      "overlapping splats: AVSM-16 differs from exact by " << worst);
  }

  // A point light: six views; over the slab, and between two slabs.
  {
    auto omni = MakeAVSM(8, false, true);
    FX_CHECK(CheckHalves("point light, one slab",
               Visibility(window, omni, { Quad(-10, 0, 1, 0.3) }, true, 1, 6.0, 180.0), 0.7,
               1e-3) == EXIT_SUCCESS, "");
    FX_CHECK(omni->GetNumberOfViews() == 6, "a point light has " << omni->GetNumberOfViews() << " views");
    FX_CHECK(CheckHalves("point light between two slabs",
               Visibility(window, MakeAVSM(8, true, true),
                 { Quad(-10, 0, 1, 0.3), Quad(-10, 0, 2, 0.5) }, true, 1, 1.5, 180.0),
               0.7, 1e-3) == EXIT_SUCCESS, "");
    // A lamp 1000 units up, 70 times the props' radius: one perspective
    // view aimed at the props, not a cube whose face held them in about 4
    // of its texels and whose bias, a fraction of its depth range, came to
    // about 1 unit (the slab 0.5 above the ground cast nothing). Bias is
    // now a fraction of the props' diameter for every view.
    FX_CHECK(CheckHalves("far point light, slab 0.5 over the ground",
               Visibility(window, omni, { Quad(-10, 0, 0.5, 0.3) }, true, 1, 1000.0, 180.0),
               0.7, 1e-3) == EXIT_SUCCESS, "");
    FX_CHECK(omni->GetNumberOfViews() == 1, "a far point light has " << omni->GetNumberOfViews() << " views");
  }
  FX_CHECK(CheckTwoLights(window) == EXIT_SUCCESS, "two casting lights");
  FX_CHECK(CheckShadowMapReuse(window) == EXIT_SUCCESS, "shadow maps kept between frames");
  FX_CHECK(CheckCasterOutsideBounds(window) == EXIT_SUCCESS, "a caster outside the bounds");
  FX_CHECK(CheckShadowsBesideNonFiniteLight(window) == EXIT_SUCCESS, "a NaN light and shadows");
  FX_CHECK(CheckFarLight(window) == EXIT_SUCCESS, "a light far from the props");

  // Nothing translucent, or translucent props of opacity 0 only (they
  // cast nothing): the pass is left out and allocates nothing.
  for (double opacity : { -1.0, 0.0 })
  {
    auto idle = MakeAVSM(8, false, true);
    std::vector<vtkSmartPointer<vtkActor>> props;
    if (opacity >= 0.0)
    {
      props.push_back(Quad(-10, 0, 1, opacity));
      props.push_back(Splats({ { 0.0, 0.0, 2.0 } }, 1.0, opacity));
    }
    Visibility(window, idle, props, true);
    std::cout << (props.empty() ? "nothing translucent" : "opacity 0 only") << ": "
              << idle->GetCapacity() << " nodes allocated" << std::endl;
    FX_CHECK(idle->GetCapacity() == 0 && !idle->GetOutputTexture("visibility"),
      "an AVSM without casters holds " << idle->GetCapacity() << " nodes");
  }
  // The look-up at surface pixels only (SkipBackground) or at every pixel:
  // the same visibility, compressed and exact, under the splats and a slab,
  // seen at 80 degrees so that background surrounds the ground.
  for (bool exact : { false, true })
  {
    std::vector<float> visibility[2];
    for (int skip : { 0, 1 })
    {
      auto avsm = MakeAVSM(8, exact, true);
      avsm->SetSkipBackground(skip != 0);
      visibility[skip] = Visibility(window, avsm,
        { Splats({ { 0.0, 0.0, 2.0 }, { 0.3, 0.0, 2.5 } }, 0.6, 0.5), Quad(-10, 0, 1, 0.3) }, false,
        1, 0.0, 60.0, 0.0, 80.0);
    }
    const size_t n = visibility[0].size();
    const bool backgroundCorner = n > 0 && visibility[0][0] == 1.0f && visibility[0][n - 1] == 1.0f;
    const auto shadowed =
      std::count_if(visibility[0].begin(), visibility[0].end(), [](float t) { return t < 0.9f; });
    std::cout << (exact ? "exact" : "AVSM-8") << " look-up with and without the background: "
              << (visibility[0] == visibility[1] ? "the same" : "different") << ", " << shadowed
              << " pixels shadowed" << std::endl;
    FX_CHECK(n > 0 && backgroundCorner && shadowed > 1000 && visibility[0] == visibility[1],
      "skipping the background changed the " << (exact ? "exact" : "AVSM-8") << " visibility");
  }
  // An actor of opacity 0 whose back faces have a property of their own
  // that is not transparent still casts.
  {
    auto avsm = MakeAVSM(8, false, true);
    auto slab = Quad(-10, 0, 1, 0.0);
    vtkNew<vtkProperty> back;
    back->SetOpacity(0.5);
    slab->SetBackfaceProperty(back);
    Visibility(window, avsm, { slab }, true);
    FX_CHECK(avsm->GetCapacity() > 0, "an actor of opacity 0 with a back-face property of "
                                      "opacity 0.5 was left out of the casters");
  }
  // So does one of opacity 0 that draws composite data, whose blocks may
  // have opacities of their own (here 0.5: its shadow is 0.5).
  {
    vtkNew<vtkMultiBlockDataSet> blocks;
    blocks->SetBlock(0, QuadSource(-10.0, 0.0, 1.0)->GetOutput());
    auto slab = BlockSlab(blocks, 0.0, 0.5);
    auto avsm = MakeAVSM(8, false, true);
    FX_CHECK(CheckHalves("opacity 0, composite data with a block of opacity 0.5",
               Visibility(window, avsm, { slab }, true), 0.5, 1e-3) == EXIT_SUCCESS,
      "composite data's block opacity left out of the casters");
  }

  auto avsm = MakeAVSM(8, false, true);
  FX_CHECK(CheckHalves("perspective camera, one slab",
             Visibility(window, avsm, { Quad(-10, 0, 1, 0.3) }, false), 0.7, 1e-3) == EXIT_SUCCESS,
    "");
  return EXIT_SUCCESS;
}
