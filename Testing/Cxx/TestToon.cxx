// vtkFXToonPass:
// - bands: a white sphere under one directional light, seen in parallel
//   projection, so each pixel's normal and diffuse factor n.l are known in
//   closed form; every pixel away from a band threshold shows exactly the
//   band value the factor falls in (default and custom thresholds);
// - lines: on the sphere, lines lie on the silhouette only (none in the
//   smooth interior), go all the way round, and cover the width asked for;
//   at twice the resolution they are twice as wide in pixels (the same
//   drawing); on the fandisk (normals split at 30 degrees, as CAD parts are
//   shown) creases add lines inside the part;
// - lines drawn only over the tiles the edges pass flags give the same
//   image, byte for byte, as lines drawn over the whole image, and as
//   lines read texel by texel instead of by textureGather, at widths
//   that take each of the lines shader's forms and a size that is not a
//   multiple of the tile;
// - the same image at scene scales 1e-6 and 1e6, translated 1e6 from the
//   origin, with a near/far ratio of 1e-6, in both projections.
#include "vtkFXPipelinePass.h"
#include "vtkFXGBufferPass.h"
#include "vtkFXScenes.h"
#include "vtkFXTestUtilities.h"
#include "vtkFXToonPass.h"
#include "vtkImageData.h"
#include "vtkFloatArray.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkWindowToImageFilter.h"
#include "vtkPlaneSource.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkOBJReader.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRendererCollection.h"
#include "vtkSSAAPass.h"
#include "vtkSphereSource.h"

#include <algorithm>
#include <array>
#include <functional>
#include <map>
#include <numeric>

namespace
{
const double Pi = 3.14159265358979323846;
// Toward the light, in view (and world) coordinates: 60 degrees off the
// view direction, so the lit and dark sides both show.
const double LightDirection[3] = { 0.8660254037844386, 0.0, 0.5 };

// A scene in `window`: one renderer with the toon effect in a pipeline, a
// grey background and one directional light along LightDirection; the
// camera looks down -z at the origin.
vtkFXToonPass* MakeScene(vtkRenderWindow* window, vtkActor* actor, bool parallel)
{
  window->GetRenderers()->RemoveAllItems();
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  renderer->SetBackground(0.5, 0.5, 0.5);
  renderer->AutomaticLightCreationOff();
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->PositionalOff();
  light->SetPosition(LightDirection);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->AddLight(light);
  renderer->AddActor(actor);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 0.0, 5.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetParallelProjection(parallel);
  camera->SetParallelScale(1.0);
  camera->SetViewAngle(30.0);
  camera->SetClippingRange(1.0, 10.0);
  vtkNew<vtkFXPipelinePass> pipeline;
  vtkNew<vtkFXToonPass> toon;
  pipeline->AddEffect("toon", toon);
  renderer->SetPass(pipeline);
  return toon;
}

// A sphere of radius 0.8 at the origin: under the parallel camera above its
// disc has radius 0.4 x the window's height, at the window's centre.
vtkSmartPointer<vtkActor> Sphere(double ambient, double diffuse)
{
  vtkNew<vtkSphereSource> source;
  source->SetRadius(0.8);
  source->SetThetaResolution(128);
  source->SetPhiResolution(128);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(1.0, 1.0, 1.0);
  actor->GetProperty()->SetAmbient(ambient);
  actor->GetProperty()->SetDiffuse(diffuse);
  actor->GetProperty()->SetSpecular(0.0);
  return actor;
}

// A surface from `port`, lit with ambient 0.4 and diffuse 0.6 (its
// darkest side stays bright enough to measure lines on).
vtkSmartPointer<vtkActor> LitSurface(vtkAlgorithmOutput* port)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(port);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetAmbient(0.4);
  actor->GetProperty()->SetDiffuse(0.6);
  return actor;
}

// What the seed's rule makes of a diffuse factor under `thresholds`.
double Band(double df, const std::vector<double>& thresholds)
{
  double level = thresholds.empty() ? 1.0 : 0.0;
  for (size_t i = 0; i < thresholds.size(); ++i)
  {
    if (df >= thresholds[i])
    {
      level = i + 1 < thresholds.size() ? thresholds[i + 1] : 1.0;
    }
  }
  return df > 0.0 ? level : 0.0;
}

// Renders the lit sphere with bands only and checks every pixel at least
// 2 px inside the disc whose n.l is at least 0.02 from a threshold (the
// tessellation's normals are that close to the sphere's): its red value is
// the band's within 2 / 255. Each band value must show on 100+ pixels.
int CheckBands(vtkRenderWindow* window, const std::vector<double>& thresholds)
{
  const int width = 400, height = 300;
  window->SetSize(width, height);
  vtkFXToonPass* toon = MakeScene(window, Sphere(0.0, 1.0), true);
  toon->FeatureLinesOff();
  toon->RemoveAllBandThresholds();
  for (double t : thresholds)
  {
    toon->AddBandThreshold(t);
  }
  window->Render();
  const auto image = vtkFXScenes::Capture(window);
  const double r = 0.4 * height;
  std::map<int, int> seen; // band value (x 1000) -> pixels
  int checked = 0, wrong = 0;
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const double nx = (x + 0.5 - 0.5 * width) / r, ny = (y + 0.5 - 0.5 * height) / r;
      const double rho2 = nx * nx + ny * ny;
      if (std::sqrt(rho2) * r > r - 2.0)
      {
        continue;
      }
      const double n[3] = { nx, ny, std::sqrt(1.0 - rho2) };
      const double df = std::max(0.0, vtkMath::Dot(n, LightDirection));
      bool nearThreshold = false;
      for (double t : thresholds)
      {
        nearThreshold = nearThreshold || std::fabs(df - t) < 0.02;
      }
      if (nearThreshold)
      {
        continue;
      }
      const double expected = Band(df, thresholds);
      const int red = image[3 * (y * width + x)];
      ++checked;
      ++seen[static_cast<int>(std::lround(1000 * expected))];
      if (std::fabs(red - 255.0 * expected) > 2.0)
      {
        if (++wrong <= 5)
        {
          std::cerr << "pixel " << x << "," << y << ": n.l " << df << ", red " << red
                    << ", band " << expected << std::endl;
        }
      }
    }
  }
  std::cout << "bands (" << thresholds.size() << " thresholds): " << checked << " pixels, "
            << wrong << " off their band, " << seen.size() << " band values seen" << std::endl;
  FX_CHECK(checked > 20000 && wrong == 0, wrong << " of " << checked << " pixels off their band");
  FX_CHECK(seen.size() == thresholds.size() + 1, seen.size() << " band values seen");
  for (const auto& band : seen)
  {
    FX_CHECK(band.second >= 100, "band " << band.first / 1000.0 << " on " << band.second << " px");
  }
  return EXIT_SUCCESS;
}

// Per pixel, 1 - lined / plain in the green channel (0 where plain is 0).
std::vector<double> Coverage(
  const std::vector<unsigned char>& lined, const std::vector<unsigned char>& plain)
{
  std::vector<double> coverage(plain.size() / 3, 0.0);
  for (size_t i = 0; i < coverage.size(); ++i)
  {
    const double base = plain[3 * i + 1];
    coverage[i] = base > 0.0 ? std::max(0.0, 1.0 - lined[3 * i + 1] / base) : 0.0;
  }
  return coverage;
}

// Line coverage per pixel: 1 - (image with lines) / (image without), in the
// green channel (black lines over a grey background and a sphere whose
// ambient term keeps it above 0.4).
// `plain` receives the image without lines, `linedImage` the one with.
std::vector<double> LineCoverage(vtkRenderWindow* window, vtkFXToonPass* toon,
  std::vector<unsigned char>* plainImage = nullptr,
  std::vector<unsigned char>* linedImage = nullptr)
{
  toon->FeatureLinesOn();
  window->Render();
  const auto lined = vtkFXScenes::Capture(window);
  toon->FeatureLinesOff();
  window->Render();
  const auto plain = vtkFXScenes::Capture(window);
  toon->FeatureLinesOn();
  const std::vector<double> coverage = Coverage(lined, plain);
  if (plainImage)
  {
    *plainImage = plain;
  }
  if (linedImage)
  {
    *linedImage = lined;
  }
  return coverage;
}

// Lines on the sphere at height rows: none farther than w/2 + 1.5 px from
// the silhouette circle, some all the way round, and a total coverage of
// (2 pi r) x w within 12% (the contour through the pixel sides' midpoints
// follows the circle to a fraction of a pixel; measured: +3% at 0.83 px,
// +9% at 1.67 px). Returns the measured width.
int CheckSphereLines(vtkRenderWindow* window, int height, double& measuredWidth)
{
  const int width = height * 4 / 3;
  window->SetSize(width, height);
  vtkFXToonPass* toon = MakeScene(window, Sphere(0.4, 0.6), true);
  toon->BandsOff();
  const auto coverage = LineCoverage(window, toon);
  const double r = 0.4 * height;
  const double w = toon->GetEffectiveLineWidth(height);
  double total = 0.0;
  int stray = 0;
  std::vector<double> around(64, 0.0); // largest coverage near the circle, per angle
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const double dx = x + 0.5 - 0.5 * width, dy = y + 0.5 - 0.5 * height;
      const double offCircle = std::fabs(std::hypot(dx, dy) - r);
      const double c = coverage[y * width + x];
      total += c;
      if (offCircle > 0.5 * w + 1.5 && c > 0.04)
      {
        if (++stray <= 5)
        {
          std::cerr << "line pixel " << x << "," << y << " is " << offCircle
                    << " px off the silhouette (coverage " << c << ")" << std::endl;
        }
      }
      if (offCircle < 1.5)
      {
        const double angle = std::atan2(dy, dx) + Pi;
        const size_t sector = std::min<size_t>(63, static_cast<size_t>(angle / (2 * Pi) * 64));
        around[sector] = std::max(around[sector], c);
      }
    }
  }
  measuredWidth = total / (2 * Pi * r);
  const double weakest = *std::min_element(around.begin(), around.end());
  std::cout << "sphere lines at " << width << "x" << height << ": width " << w << " px asked, "
            << measuredWidth << " px measured, " << stray << " stray pixels, weakest sector "
            << weakest << std::endl;
  FX_CHECK(stray == 0, stray << " line pixels away from the silhouette");
  FX_CHECK(weakest > 0.25, "a gap in the silhouette line (coverage " << weakest << ")");
  FX_CHECK(std::fabs(measuredWidth - w) < 0.12 * w, "width " << measuredWidth << " for " << w);
  return EXIT_SUCCESS;
}

// Pixels within 2 px of a crease of what the G-buffer of `renderer`'s
// pipeline holds: two side-by-side covered pixels whose normals differ by
// more than 25 degrees (the toon pass's crease angle is 30; the normals
// are VTK's, split at 30 degrees, so a crease is a jump well above 25).
std::vector<char> NearCreases(vtkRenderer* renderer, int width, int height,
  const std::function<bool(int, int)>& background)
{
  auto* pipeline = vtkFXPipelinePass::SafeDownCast(renderer->GetPass());
  const auto encoded = vtkFXTest::Download(
    pipeline->GetGBufferPass()->GetChannelTexture(vtkFXGBufferPass::Normal), 2);
  std::vector<char> near(static_cast<size_t>(width) * height, 0);
  if (encoded.size() < near.size() * 2)
  {
    return near;
  }
  std::vector<std::array<double, 3>> normals(near.size());
  for (size_t i = 0; i < near.size(); ++i)
  {
    vtkFXTest::DecodeNormal(encoded[2 * i], encoded[2 * i + 1], normals[i].data());
  }
  const double cosine = std::cos(vtkMath::RadiansFromDegrees(25.0));
  for (int y = 0; y + 1 < height; ++y)
  {
    for (int x = 0; x + 1 < width; ++x)
    {
      const size_t i = static_cast<size_t>(y) * width + x;
      bool crease = false;
      for (const size_t j : { i + 1, i + width })
      {
        const int xj = static_cast<int>(j % width), yj = static_cast<int>(j / width);
        crease = crease ||
          (!background(x, y) && !background(xj, yj) &&
            vtkMath::Dot(normals[i].data(), normals[j].data()) < cosine);
      }
      for (int dy = -2; crease && dy <= 3; ++dy)
      {
        for (int dx = -2; dx <= 3; ++dx)
        {
          if (x + dx >= 0 && y + dy >= 0 && x + dx < width && y + dy < height)
          {
            near[static_cast<size_t>(y + dy) * width + x + dx] = 1;
          }
        }
      }
    }
  }
  return near;
}

// Fandisk pixels at least 3 px from the background with line coverage
// above 0.2 (lines are 0.83 px wide here), with creases on or off; with
// `lines`, which pixels those are, and with `nearCreases`, the pixels near
// the surface's creases (NearCreases). `pbr`: the fandisk in VTK's PBR
// model, whose colour the composite keeps.
int InteriorLinePixels(vtkRenderWindow* window, bool creases, bool pbr, int& interior,
  int& object, std::vector<char>* lines = nullptr, std::vector<char>* nearCreases = nullptr)
{
  const int width = 400, height = 300;
  window->SetSize(width, height);
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName((vtkFXScenes::DataDirectory() + "/fandisk.obj").c_str());
  vtkNew<vtkPolyDataNormals> normals; // splitting at 30 degrees, VTK's default
  normals->SetInputConnection(reader->GetOutputPort());
  auto actor = LitSurface(normals->GetOutputPort());
  if (pbr)
  {
    actor->GetProperty()->SetInterpolationToPBR();
  }
  vtkFXToonPass* toon = MakeScene(window, actor, false);
  vtkRenderer* renderer = window->GetRenderers()->GetFirstRenderer();
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Azimuth(40);
  renderer->GetActiveCamera()->Elevation(25);
  renderer->ResetCameraClippingRange();
  toon->BandsOff();
  toon->SetCreases(creases);
  std::vector<unsigned char> image;
  const auto coverage = LineCoverage(window, toon, &image);
  unsigned char bg[3];
  vtkFXScenes::BackgroundBytes(renderer, bg);
  const auto background = [&](int x, int y) {
    if (x < 0 || y < 0 || x >= width || y >= height)
    {
      return true;
    }
    const unsigned char* p = &image[3 * (y * width + x)];
    return p[0] == bg[0] && p[1] == bg[1] && p[2] == bg[2];
  };
  interior = object = 0;
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      bool inside = true;
      for (int dy = -3; dy <= 3 && inside; ++dy)
      {
        for (int dx = -3; dx <= 3 && inside; ++dx)
        {
          inside = !background(x + dx, y + dy);
        }
      }
      object += inside ? 1 : 0;
      const bool line = inside && coverage[y * width + x] > 0.2;
      interior += line ? 1 : 0;
      if (lines)
      {
        lines->resize(static_cast<size_t>(width) * height, 0);
        (*lines)[static_cast<size_t>(y) * width + x] = line ? 1 : 0;
      }
    }
  }
  if (nearCreases)
  {
    // (the normals of a frame with lines: without, a scene of PBR props
    // alone has no effect that reads them)
    window->Render();
    *nearCreases = NearCreases(renderer, width, height, background);
  }
  return EXIT_SUCCESS;
}

// Also in VTK's PBR model: its fragments carry their normals (before, the
// unlit sentinel: the creases added no line, and the silhouettes were
// found from depths alone).
int CheckFandiskCreases(vtkRenderWindow* window, bool pbr)
{
  int withCreases = 0, withoutCreases = 0, object = 0;
  std::vector<char> creaseLines, otherLines, nearCreases;
  InteriorLinePixels(window, true, pbr, withCreases, object, &creaseLines, &nearCreases);
  InteriorLinePixels(window, false, pbr, withoutCreases, object, &otherLines);
  // The lines creases add lie on the surface's creases.
  int added = 0, addedNearCreases = 0;
  const long nearArea = std::count(nearCreases.begin(), nearCreases.end(), 1);
  for (size_t i = 0; i < creaseLines.size() && i < otherLines.size() && i < nearCreases.size(); ++i)
  {
    const bool isAdded = creaseLines[i] && !otherLines[i];
    added += isAdded ? 1 : 0;
    addedNearCreases += isAdded && nearCreases[i] ? 1 : 0;
  }
  std::cout << "fandisk" << (pbr ? " (PBR)" : "") << ": " << object << " interior pixels, "
            << withCreases
            << " on lines with creases, " << withoutCreases << " without; of the " << added
            << " the creases add, " << addedNearCreases << " within 2.5 px of a crease (a zone of "
            << nearArea << " pixels, " << 100.0 * nearArea / std::max(object, 1)
            << "% of the interior's size)" << std::endl;
  FX_CHECK(nearArea < object / 2, "the crease zone covers " << nearArea << " pixels: no test");
  // (measured: all of them; the zone is every pixel whose centre lies
  // within 2.5 px of the side between the two pixels of a crease)
  FX_CHECK(added > 300 && addedNearCreases >= 0.99 * added,
    "crease lines off the creases: " << addedNearCreases << " of " << added << " near one");
  FX_CHECK(object > 10000, "the fandisk covers " << object << " interior pixels");
  FX_CHECK(withCreases > 300 && withCreases > 2 * withoutCreases + 100,
    "creases add too few lines: " << withCreases << " against " << withoutCreases);
  FX_CHECK(withCreases < object / 5, "lines everywhere: " << withCreases << " of " << object);
  return EXIT_SUCCESS;
}

// The bunny scene through `toon`, arranged by `arrange` (if any) first.
std::vector<unsigned char> RenderBunny(vtkRenderWindow* window, vtkFXToonPass* toon,
  const std::function<void(vtkRenderer*)>& arrange = nullptr)
{
  window->GetRenderers()->RemoveAllItems();
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  std::string error;
  if (!vtkFXScenes::Populate(renderer,
        vtkFXScenes::DataDirectory() + "/stanford-bunny.obj", vtkFXScenes::Options(), error))
  {
    std::cerr << error << std::endl;
    return {};
  }
  if (arrange)
  {
    arrange(renderer);
  }
  vtkNew<vtkFXPipelinePass> pipeline;
  pipeline->AddEffect("toon", toon);
  renderer->SetPass(pipeline);
  window->Render();
  return vtkFXScenes::Capture(window);
}

// The bunny scene with bands and lines, moved as TestSSAOScale moves it.
std::vector<unsigned char> RenderMoved(vtkRenderWindow* window, double scale, double offset,
  bool parallel, double nearRatio)
{
  vtkNew<vtkFXToonPass> toon;
  return RenderBunny(window, toon, [&](vtkRenderer* renderer) {
    vtkFXTest::MoveScene(renderer, scale, offset, parallel, nearRatio);
  });
}

// The bunny with lines of `width` pixels, drawn over flagged tiles only or
// over the whole image, at 403x301 (tiles of 8 px do not divide it); edges
// found where they can be only (skipBackground) or everywhere.
// `kinds`: 1 silhouettes, 2 creases (at 10 degrees, so the bunny has
// some), 3 both (creases at the default angle).
std::vector<unsigned char> RenderLines(vtkRenderWindow* window, double width, bool cull,
  bool lines, bool* culled = nullptr, bool gather = true, bool skipBackground = true,
  int kinds = 3)
{
  window->SetSize(403, 301);
  vtkNew<vtkFXToonPass> toon;
  toon->SetSilhouettes((kinds & 1) != 0);
  toon->SetCreases((kinds & 2) != 0);
  if (kinds == 2)
  {
    toon->SetCreaseAngle(10.0);
  }
  toon->SetLineReferenceHeight(301);
  toon->SetLineWidth(width);
  toon->SetCullLineTiles(cull);
  toon->SetUseTextureGather(gather);
  toon->SetSkipBackgroundEdges(skipBackground);
  toon->SetFeatureLines(lines);
  auto image = RenderBunny(window, toon);
  if (culled)
  {
    *culled = toon->GetLineTilesCulled();
  }
  return image;
}

int CheckTileCulling(vtkRenderWindow* window)
{
  window->MakeCurrent(); // CanFlagLineTiles asks the current context
  if (!vtkFXToonPass::CanFlagLineTiles())
  {
    std::cout << "no image stores here: lines are always drawn over the whole image, "
                 "tile culling is not compared" << std::endl;
    return EXIT_SUCCESS;
  }
  // 0.8 px: one block of marks; 2 and 4 px: 4 and 9 blocks in straight-line
  // code; 7 px: the loop over midpoints.
  for (double width : { 0.8, 2.0, 4.0, 7.0 })
  {
    bool tilesCulled = false;
    const auto culled = RenderLines(window, width, true, true, &tilesCulled);
    // Otherwise both images would come from the same whole-image draw.
    FX_CHECK(tilesCulled, "tile culling did not run at " << width << " px");
    const auto whole = RenderLines(window, width, false, true);
    const auto none = RenderLines(window, width, true, false);
    // (the texel-by-texel reads, where a context lacks textureGather)
    const auto fetched = RenderLines(window, width, true, true, nullptr, false);
    // (edges found at every pixel, background included)
    const auto everywhere = RenderLines(window, width, true, true, nullptr, true, false);
    FX_CHECK(!culled.empty() && culled.size() == whole.size() && none.size() == whole.size() &&
        fetched.size() == whole.size() && everywhere.size() == whole.size(),
      "the bunny did not render");
    size_t differing = 0, lined = 0, differingFetched = 0, differingEverywhere = 0;
    for (size_t i = 0; i < culled.size(); ++i)
    {
      differing += culled[i] != whole[i] ? 1 : 0;
      differingFetched += culled[i] != fetched[i] ? 1 : 0;
      differingEverywhere += culled[i] != everywhere[i] ? 1 : 0;
      lined += culled[i] != none[i] ? 1 : 0;
    }
    std::cout << "lines of " << width << " px: " << lined
              << " bytes changed by lines, culled (tiles culled: " << (tilesCulled ? "yes" : "no")
              << ") and whole images differ in " << differing << ", gathered and fetched in "
              << differingFetched << ", background skipped and not in " << differingEverywhere
              << std::endl;
    FX_CHECK(differingEverywhere == 0,
      differingEverywhere << " bytes differ with edges found on the background at " << width << " px");
    FX_CHECK(lined > 1000, "no lines drawn at " << width << " px");
    FX_CHECK(differing == 0, differing << " bytes differ with tile culling at " << width << " px");
    FX_CHECK(differingFetched == 0,
      differingFetched << " bytes differ without textureGather at " << width << " px");
  }
  // Each kind of line alone (a background pixel beside the bunny has a
  // mark only with silhouettes on).
  for (int kinds : { 1, 2 })
  {
    const auto culled = RenderLines(window, 2.0, true, true, nullptr, true, true, kinds);
    const auto whole = RenderLines(window, 2.0, false, true, nullptr, true, true, kinds);
    const auto none = RenderLines(window, 2.0, true, false, nullptr, true, true, kinds);
    size_t differing = 0, lined = 0;
    for (size_t i = 0; i < culled.size() && i < whole.size() && i < none.size(); ++i)
    {
      differing += culled[i] != whole[i] ? 1 : 0;
      lined += culled[i] != none[i] ? 1 : 0;
    }
    const char* kind = kinds == 1 ? "silhouettes" : "creases";
    std::cout << kind << " alone: " << lined << " bytes changed by lines, culled and whole "
              << "images differ in " << differing << std::endl;
    FX_CHECK(!culled.empty() && culled.size() == whole.size() && none.size() == whole.size(),
      "the bunny did not render");
    FX_CHECK(lined > 100, "no " << kind << " drawn");
    FX_CHECK(differing == 0, differing << " bytes differ with tile culling, " << kind << " alone");
  }
  // A multisampled window: its framebuffer gets the whole-image quad (a
  // point's square has no rule for samples on its sides), with the marks
  // stored as images or drawn as colour: the same bytes either way.
  {
    auto multisampled = vtkFXTest::MakeWindow(403, 301);
    multisampled->SetMultiSamples(4);
    std::vector<unsigned char> images[2];
    for (bool cull : { true, false })
    {
      vtkNew<vtkFXToonPass> toon;
      toon->SetLineReferenceHeight(301);
      toon->SetCullLineTiles(cull);
      images[cull ? 0 : 1] = RenderBunny(multisampled, toon);
    }
    FX_CHECK(!images[0].empty() && images[0] == images[1],
      "in a multisampled window, culled and whole-image lines differ by up to "
        << vtkFXScenes::MaxDifference(images[0], images[1]) << "/255");
  }
  // One pass switched from skipping the background to not and back (its
  // edges quad moves off the far plane and back): the same bytes.
  vtkNew<vtkFXToonPass> toon;
  toon->SetLineReferenceHeight(301);
  std::vector<unsigned char> switched[3];
  for (int i = 0; i < 3; ++i)
  {
    toon->SetSkipBackgroundEdges(i != 1);
    switched[i] = RenderBunny(window, toon);
  }
  FX_CHECK(!switched[0].empty() && switched[0] == switched[1] && switched[1] == switched[2],
    "switching SkipBackgroundEdges on one pass changed the lines");
  return EXIT_SUCCESS;
}

// A renderer whose viewport is the right half of a 402x301 window, or the
// upper half of a 201x602 one, draws the lines a 201x301 window draws: the
// same bytes in that half (the
// edges texture starts at the viewport's corner, gl_FragCoord at the
// window's; the flagged tiles' points are placed in the viewport).
int CheckOffsetViewport(vtkRenderWindow* window)
{
  // (both cameras framed for the viewport's aspect)
  vtkNew<vtkFXToonPass> alone;
  window->SetSize(201, 301);
  const auto small = RenderBunny(window, alone, [](vtkRenderer* renderer) { renderer->ResetCamera(); });
  vtkNew<vtkFXToonPass> offset;
  window->SetSize(402, 301);
  const auto wide = RenderBunny(window, offset, [](vtkRenderer* renderer) {
    renderer->SetViewport(0.5, 0.0, 1.0, 1.0);
    renderer->ResetCamera();
  });
  FX_CHECK(small.size() == 3u * 201 * 301 && wide.size() == 3u * 402 * 301, "no images");
  size_t differing = 0;
  for (int y = 0; y < 301; ++y)
  {
    for (int x = 0; x < 201; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        differing += small[3 * (static_cast<size_t>(y) * 201 + x) + c] !=
            wide[3 * (static_cast<size_t>(y) * 402 + 201 + x) + c]
          ? 1
          : 0;
      }
    }
  }
  std::cout << "lines in a viewport at x = 201: " << differing
            << " bytes differ from a window of the viewport's size" << std::endl;
  FX_CHECK(differing == 0, differing << " bytes differ in an offset viewport");
  // The same in the upper half of a 201x602 window (offset in y).
  vtkNew<vtkFXToonPass> raised;
  window->SetSize(201, 602);
  const auto tall = RenderBunny(window, raised, [](vtkRenderer* renderer) {
    renderer->SetViewport(0.0, 0.5, 1.0, 1.0);
    renderer->ResetCamera();
  });
  FX_CHECK(tall.size() == 3u * 201 * 602, "no image");
  // (rows bottom up: the viewport's are 301..601)
  const size_t upper = 3u * 201 * 301;
  const size_t differingUp = static_cast<size_t>(std::inner_product(small.begin(), small.end(),
    tall.begin() + upper, size_t(0), std::plus<size_t>(),
    [](unsigned char a, unsigned char b) { return a != b ? size_t(1) : size_t(0); }));
  std::cout << "lines in a viewport at y = 301: " << differingUp
            << " bytes differ from a window of the viewport's size" << std::endl;
  FX_CHECK(differingUp == 0, differingUp << " bytes differ in a viewport offset in y");
  window->SetSize(400, 300);
  return EXIT_SUCCESS;
}

int CheckScaleInvariance(vtkRenderWindow* window)
{
  window->SetSize(320, 240);
  struct Variant
  {
    const char* Name;
    double Scale, Offset, NearRatio;
  };
  const Variant variants[] = { { "scaled 1e-6", 1e-6, 0.0, 0.0 }, { "scaled 1e6", 1e6, 0.0, 0.0 },
    { "translated 1e6", 1.0, 1e6, 0.0 }, { "near/far 1e-6", 1.0, 0.0, 1e-6 } };
  int failures = 0;
  for (bool parallel : { false, true })
  {
    const auto base = RenderMoved(window, 1.0, 0.0, parallel, 0.0);
    FX_CHECK(!base.empty(), "the bunny did not render");
    for (const Variant& v : variants)
    {
      const auto image = RenderMoved(window, v.Scale, v.Offset, parallel, v.NearRatio);
      const double psnr = vtkFXScenes::PSNR(base, image);
      const int difference = vtkFXScenes::MaxDifference(base, image);
      int differingPixels = 0;
      for (size_t i = 0; i + 2 < base.size() && i + 2 < image.size(); i += 3)
      {
        differingPixels +=
          (base[i] != image[i] || base[i + 1] != image[i + 1] || base[i + 2] != image[i + 2]) ? 1 : 0;
      }
      std::cout << "toon bunny " << (parallel ? "parallel" : "perspective") << ", " << v.Name
                << ": PSNR " << psnr << " dB, largest difference " << difference << ", "
                << differingPixels << " pixels differ" << std::endl;
      // Scaled and translated: the same image up to a line pixel whose
      // crease or silhouette test lies within rounding of its threshold
      // (on VTK 9.1 the same bytes; on 9.2, whose mappers shift and scale
      // coordinates differently, 1 pixel of 76800 differs by 8 levels in
      // parallel projection at scale 1e6 with the bunny's normals split at
      // 30 degree features): at most 4 pixels; near/far 1e-6, the same
      // image up to rounding (52.9-54.8 dB in perspective).
      const bool rounding = v.NearRatio > 0.0;
      failures += (rounding ? psnr >= 50.0 : differingPixels <= 4) ? 0 : 1;
    }
  }
  FX_CHECK(failures == 0,
    failures << " variant(s) with more than 4 pixels changed (scale, translation) or below 50 dB (near/far)");

  // In parallel projection, the camera moved 1000 times as far back (its
  // parallel scale kept) shows the same image, lines included.
  const auto near = RenderMoved(window, 1.0, 0.0, true, 0.0);
  vtkNew<vtkFXToonPass> farToon;
  const auto far = RenderBunny(window, farToon, [&](vtkRenderer* renderer) {
    vtkFXTest::MoveScene(renderer, 1.0, 0.0, true, 0.0);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->Dolly(1e-3); // (VTK's dolly: the distance divided by the factor)
    renderer->ResetCameraClippingRange();
  });
  const double farPSNR = vtkFXScenes::PSNR(near, far);
  std::cout << "toon bunny parallel, camera 1000 times as far: PSNR " << farPSNR << " dB" << std::endl;
  FX_CHECK(farPSNR >= 50.0, "parallel lines depend on the camera's distance");

  // Nor does a parallel image depend on the camera's view angle, nor its
  // lines: the same image, byte for byte (when the silhouettes' depth
  // scale followed 1 / tan(angle / 2): 51.1 dB at 10 degrees, 56.6 at 60).
  for (const double angle : { 10.0, 60.0 })
  {
    vtkNew<vtkFXToonPass> angledToon;
    const auto angled = RenderBunny(window, angledToon, [&](vtkRenderer* renderer) {
      vtkFXTest::MoveScene(renderer, 1.0, 0.0, true, 0.0);
      renderer->GetActiveCamera()->SetViewAngle(angle);
    });
    const double anglePSNR = vtkFXScenes::PSNR(near, angled);
    std::cout << "toon bunny parallel, view angle " << angle << " degrees: PSNR " << anglePSNR
              << " dB" << std::endl;
    FX_CHECK(angled == near, "parallel lines depend on the camera's view angle");
  }

  // A view given as an explicit projection matrix, the camera's
  // ParallelProjection flag the other way (and, in parallel projection,
  // the camera 1000 times as far; in perspective, a parallel scale 1000
  // times as large, which the matrix ignores): the same image. The lines'
  // depth scale comes from the matrix VTK draws with, not the camera's flag.
  for (const bool parallel : { true, false })
  {
    const auto moveFar = [parallel](vtkRenderer* renderer) {
      vtkFXTest::MoveScene(renderer, 1.0, 0.0, parallel, 0.0);
      vtkCamera* camera = renderer->GetActiveCamera();
      if (parallel)
      {
        camera->Dolly(1e-3);
        renderer->ResetCameraClippingRange();
      }
      else
      {
        camera->SetParallelScale(1e3 * camera->GetParallelScale());
      }
    };
    vtkNew<vtkFXToonPass> flaggedToon;
    const auto flagged = RenderBunny(window, flaggedToon, moveFar);
    vtkNew<vtkFXToonPass> explicitToon;
    const auto given = RenderBunny(window, explicitToon, [&](vtkRenderer* renderer) {
      moveFar(renderer);
      vtkCamera* camera = renderer->GetActiveCamera();
      vtkNew<vtkMatrix4x4> projection;
      projection->DeepCopy(
        camera->GetProjectionTransformMatrix(renderer->GetTiledAspectRatio(), -1, 1));
      camera->SetExplicitProjectionTransformMatrix(projection);
      camera->UseExplicitProjectionTransformMatrixOn();
      camera->SetParallelProjection(!parallel);
    });
    int differingPixels = 0;
    for (size_t i = 0; i + 2 < flagged.size() && i + 2 < given.size(); i += 3)
    {
      differingPixels += (flagged[i] != given[i] || flagged[i + 1] != given[i + 1] ||
                           flagged[i + 2] != given[i + 2])
        ? 1
        : 0;
    }
    std::cout << "toon bunny " << (parallel ? "parallel" : "perspective")
              << " as an explicit matrix, the camera's flag the other way: " << differingPixels
              << " pixels differ" << std::endl;
    FX_CHECK(!flagged.empty() && flagged.size() == given.size() && differingPixels <= 4,
      "the lines follow the camera's flag, not its matrix");
  }
  return EXIT_SUCCESS;
}
// Total line coverage of the image, sum over pixels.
double TotalCoverage(const std::vector<double>& coverage)
{
  double sum = 0.0;
  for (double c : coverage)
  {
    sum += c;
  }
  return sum;
}

// A lit sphere before an unlit backdrop: the pair of a lit and an unlit
// pixel is two primitives, and the silhouette shows as it does against
// the background (the lit side's tangent plane alone holds the backdrop's
// point at a limb). Total line coverage within 10% of the one without the
// backdrop (measured: 0.2%; 17% less when the depth gap was left out).
// So must an unlit sphere's, whose pixels' planes come from their depths.
int CheckUnlitBackdrop(vtkRenderWindow* window, bool litSphere, double backdropZ = -2.0)
{
  double totals[2] = { 0.0, 0.0 };
  for (bool backdrop : { false, true })
  {
    auto sphere = Sphere(0.5, 0.5);
    sphere->GetProperty()->SetLighting(litSphere);
    vtkFXToonPass* toon = MakeScene(window, sphere, false);
    toon->BandsOff();
    if (backdrop)
    {
      vtkNew<vtkPlaneSource> plane;
      plane->SetOrigin(-20.0, -20.0, backdropZ);
      plane->SetPoint1(20.0, -20.0, backdropZ);
      plane->SetPoint2(-20.0, 20.0, backdropZ);
      vtkNew<vtkPolyDataMapper> mapper;
      mapper->SetInputConnection(plane->GetOutputPort());
      vtkNew<vtkActor> actor;
      actor->SetMapper(mapper);
      actor->GetProperty()->LightingOff();
      actor->GetProperty()->SetColor(0.6, 0.6, 0.6);
      window->GetRenderers()->GetFirstRenderer()->AddActor(actor);
    }
    totals[backdrop ? 1 : 0] = TotalCoverage(LineCoverage(window, toon));
  }
  std::cout << (litSphere ? "lit" : "unlit") << " sphere's silhouette (backdrop at z = "
            << backdropZ << ", " << window->GetSize()[0] << " x " << window->GetSize()[1]
            << "): line coverage "
            << totals[0] << " against the background, "
            << totals[1] << " against an unlit backdrop" << std::endl;
  FX_CHECK(totals[0] > 100.0 && std::fabs(totals[1] / totals[0] - 1.0) < 0.1,
    "the silhouette against an unlit backdrop: " << totals[1] << " for " << totals[0]);
  return EXIT_SUCCESS;
}

int CheckUnlitBackdrop(vtkRenderWindow* window)
{
  for (const bool litSphere : { true, false })
  {
    if (CheckUnlitBackdrop(window, litSphere) != EXIT_SUCCESS)
    {
      return EXIT_FAILURE;
    }
  }
  // An unlit backdrop just behind an unlit sphere (about 1 unit behind its
  // limb, 5 from the camera) at 1280 x 720: the limb's plane, made from
  // depths, holds the backdrop's point, and the silhouette is kept by the
  // depth step, far beyond the limb's own from pixel to pixel.
  const int* size = window->GetSize();
  const int kept[2] = { size[0], size[1] };
  window->SetSize(1280, 720);
  const int result = CheckUnlitBackdrop(window, false, -1.05);
  window->SetSize(kept[0], kept[1]);
  return result;
}

// A screenshot at twice the window's size (vtkWindowToImageFilter renders
// it in 2 x 2 tiles of the window's size) draws lines as wide, relative to
// the image, as a window of twice the size: total line coverage within 15%
// (the tiles' seams cut a little); so does a renderer on the lower half of
// the window, which covers part of a tile's rows (its lines were twice as
// wide: 1033 against 490).
int CheckScaledScreenshot(vtkRenderWindow* window)
{
  const auto capture = [&](int scale) {
    vtkNew<vtkWindowToImageFilter> filter;
    filter->SetInput(window);
    filter->SetScale(scale);
    filter->ReadFrontBufferOff();
    filter->Update();
    vtkImageData* image = filter->GetOutput();
    const int* dims = image->GetDimensions();
    std::vector<unsigned char> pixels(static_cast<size_t>(dims[0]) * dims[1] * 3);
    auto* data = static_cast<unsigned char*>(image->GetScalarPointer());
    const int components = image->GetNumberOfScalarComponents();
    for (size_t i = 0; i < pixels.size() / 3; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        pixels[3 * i + c] = data[components * i + c];
      }
    }
    return pixels;
  };
  vtkFXToonPass* toon = MakeScene(window, Sphere(0.5, 0.5), false);
  toon->BandsOff();
  // Line coverage of a screenshot at scale 2 of a window of `width` x
  // `height`, over its first `bytes` (its rows bottom up; 0: all of it).
  const auto screenshotCoverage = [&](int width, int height, size_t bytes) {
    window->SetSize(width, height);
    auto lined = capture(2);
    toon->FeatureLinesOff();
    auto plain = capture(2);
    toon->FeatureLinesOn();
    window->SetSize(400, 300);
    if (bytes > 0)
    {
      lined.resize(bytes);
      plain.resize(bytes);
    }
    return TotalCoverage(Coverage(lined, plain));
  };
  window->SetSize(400, 300);
  const double big = TotalCoverage(LineCoverage(window, toon));
  const double tiled = screenshotCoverage(200, 150, 0);
  // A renderer on the lower half of a 200x300 window (200x150 too): a tile
  // of the screenshot holds 300 of its viewport's rows, not all of them.
  // (its 400x300 pixels of the 400x600 image: the window above its
  // viewport is never cleared and holds what earlier tiles left)
  vtkRenderer* renderer = window->GetRenderers()->GetFirstRenderer();
  renderer->SetViewport(0.0, 0.0, 1.0, 0.5);
  const double halfTiled = screenshotCoverage(200, 300, 3 * 400 * 300);
  renderer->SetViewport(0.0, 0.0, 1.0, 1.0);
  std::cout << "lines at 400x300: coverage " << big << " in a window, " << tiled
            << " in a screenshot of a 200x150 window at scale 2, " << halfTiled
            << " of a 200x150 viewport in a 200x300 window at scale 2" << std::endl;
  FX_CHECK(big > 100.0 && std::fabs(tiled / big - 1.0) < 0.15,
    "lines in a scaled screenshot: " << tiled << " for " << big);
  FX_CHECK(std::fabs(halfTiled / big - 1.0) < 0.15,
    "lines of a viewport in a scaled screenshot: " << halfTiled << " for " << big);
  // The same through vtkSSAAPass, which renders the pipeline into a
  // framebuffer larger than the window (the lines are as wide relative to
  // it).
  vtkNew<vtkSSAAPass> ssaa;
  ssaa->SetDelegatePass(renderer->GetPass());
  renderer->SetPass(ssaa);
  const double bigSSAA = TotalCoverage(LineCoverage(window, toon));
  const double tiledSSAA = screenshotCoverage(200, 150, 0);
  renderer->SetPass(ssaa->GetDelegatePass());
  std::cout << "through vtkSSAAPass: coverage " << bigSSAA << " in a 400x300 window, " << tiledSSAA
            << " in a screenshot of a 200x150 window at scale 2" << std::endl;
  FX_CHECK(bigSSAA > 100.0 && std::fabs(tiledSSAA / bigSSAA - 1.0) < 0.15,
    "lines in a scaled screenshot through vtkSSAAPass: " << tiledSSAA << " for " << bigSSAA);
  return EXIT_SUCCESS;
}
}

// An opaque prop the G-buffer does not capture (a vtkImageActor, drawn
// forward) in front of the left half of a lit sphere hides the sphere's
// lines there, as it hides the sphere: with lines on and off, the image
// is the same over the slice (away from its border), and lines show on
// the sphere's uncovered half.
int CheckLinesBehindForwardProps(vtkRenderWindow* window)
{
  window->SetSize(400, 300);
  vtkFXToonPass* toon = MakeScene(window, Sphere(0.5, 0.5), false);
  toon->BandsOff();
  const unsigned char red[3] = { 200, 40, 40 };
  window->GetRenderers()->GetFirstRenderer()->AddViewProp(
    vtkFXTest::UniformSlice(-6.0, 0.0, -3.0, 3.0, 1.5, red));
  std::vector<unsigned char> plain, lined;
  LineCoverage(window, toon, &plain, &lined);
  FX_CHECK(lined.size() == 3u * 400 * 300 && plain.size() == lined.size(), "no images");
  // The slice's right border (x = 0) is the middle column.
  size_t overSlice = 0, elsewhere = 0;
  for (int y = 0; y < 300; ++y)
  {
    for (int x = 0; x < 400; ++x)
    {
      const size_t i = 3 * (static_cast<size_t>(y) * 400 + x);
      const bool differs = lined[i] != plain[i] || lined[i + 1] != plain[i + 1] || lined[i + 2] != plain[i + 2];
      overSlice += (differs && x < 195) ? 1 : 0;
      elsewhere += (differs && x > 205) ? 1 : 0;
    }
  }
  std::cout << "lines behind a forward-drawn slice: " << overSlice << " pixels changed over it, "
            << elsewhere << " on the uncovered half" << std::endl;
  FX_CHECK(overSlice == 0 && elsewhere > 100,
    "lines over a slice in front: " << overSlice << " pixels, " << elsewhere << " elsewhere");
  return EXIT_SUCCESS;
}

// A lit floor (40 x 40, z = 0) seen from 2, 5 and 15 degrees above it in
// perspective: its depth changes fast across pixels near the horizon, but
// it is one plane, so the silhouette test (positions against the tangent
// planes, relative to depth) must draw no line on it. Lines may only run
// along the floor's border with the background (within 3 px of a
// background pixel): no pixel farther in has coverage above 0.04.
// With `bumped`, the floor carries rivets (vtkFXGBufferPass::SetBump, domes
// 0.1 high on a 1-unit grid), lit: lines outline the geometry, so the
// bumps, which only tilt the shading normal, draw none (read with the
// shading normal, they were taken for silhouettes and creases).
int CheckGrazingFloor(vtkRenderWindow* window, bool bumped)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-20.0, -20.0, 0.0);
  plane->SetPoint1(20.0, -20.0, 0.0);
  plane->SetPoint2(-20.0, 20.0, 0.0);
  plane->SetResolution(bumped ? 400 : 40, bumped ? 400 : 40);
  plane->Update();
  vtkNew<vtkFloatArray> rivets;
  rivets->SetName("rivets");
  rivets->SetNumberOfTuples(plane->GetOutput()->GetNumberOfPoints());
  for (vtkIdType i = 0; i < rivets->GetNumberOfTuples(); ++i)
  {
    double p[3];
    plane->GetOutput()->GetPoint(i, p);
    const double dx = p[0] - std::floor(p[0]) - 0.5, dy = p[1] - std::floor(p[1]) - 0.5;
    const double r2 = (dx * dx + dy * dy) / (0.35 * 0.35);
    rivets->SetValue(i, r2 < 1.0 ? static_cast<float>(0.1 * std::sqrt(1.0 - r2)) : 0.0f);
  }
  plane->GetOutput()->GetPointData()->AddArray(rivets);
  auto floor = LitSurface(plane->GetOutputPort());
  if (bumped)
  {
    vtkFXGBufferPass::SetBump(floor, "rivets", 1.0);
  }
  int width = 0, height = 0;
  const std::vector<double> elevations = bumped
    ? std::vector<double>{ 5.0, 15.0, 40.0 }
    : std::vector<double>{ 2.0, 5.0, 15.0, -2.0, -5.0, -15.0 };
  for (const double elevation : elevations)
  {
    // (negative: the same elevation, the floor unlit, which stores no
    // normal in the G-buffer: its plane comes from its depths)
    const bool lit = elevation > 0.0;
    floor->GetProperty()->SetLighting(lit);
    vtkFXToonPass* toon = MakeScene(window, floor, false);
    toon->BandsOff();
    width = window->GetSize()[0];
    height = window->GetSize()[1];
    vtkCamera* camera = window->GetRenderers()->GetFirstRenderer()->GetActiveCamera();
    const double a = vtkMath::RadiansFromDegrees(std::fabs(elevation));
    camera->SetPosition(0.0, -15.0 * std::cos(a), 15.0 * std::sin(a));
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewUp(0.0, 0.0, 1.0);
    camera->SetViewAngle(40.0);
    window->GetRenderers()->GetFirstRenderer()->ResetCameraClippingRange();
    std::vector<unsigned char> plain;
    const auto coverage = LineCoverage(window, toon, &plain);
    unsigned char background[3];
    vtkFXScenes::BackgroundBytes(window->GetRenderers()->GetFirstRenderer(), background);
    const auto isBackground = [&](int x, int y) {
      const size_t i = 3 * (static_cast<size_t>(y) * width + x);
      return plain[i] == background[0] && plain[i + 1] == background[1] &&
        plain[i + 2] == background[2];
    };
    int interior = 0, stray = 0;
    for (int y = 0; y < height; ++y)
    {
      for (int x = 0; x < width; ++x)
      {
        bool nearBorder = false;
        for (int dy = -3; dy <= 3 && !nearBorder; ++dy)
        {
          for (int dx = -3; dx <= 3 && !nearBorder; ++dx)
          {
            const int u = x + dx, v = y + dy;
            nearBorder = u >= 0 && v >= 0 && u < width && v < height && isBackground(u, v);
          }
        }
        if (nearBorder)
        {
          continue;
        }
        ++interior;
        stray += coverage[static_cast<size_t>(y) * width + x] > 0.04 ? 1 : 0;
      }
    }
    std::cout << (lit ? "" : "unlit ") << (bumped ? "bumped " : "") << "floor seen from "
              << std::fabs(elevation)
              << " degrees: " << interior
              << " pixels away from its border, " << stray << " with a line" << std::endl;
    FX_CHECK(interior > width * height / 4, "the floor fills little of the view");
    FX_CHECK(stray == 0, stray << " line pixels on a plane seen at " << std::fabs(elevation)
                               << " degrees" << (lit ? "" : ", unlit")
                               << (bumped ? ", bumped" : ""));
  }
  return EXIT_SUCCESS;
}

// Lines switched off free the lines' textures: the pass is then composite
// code only, and its Render, which freed them before, no longer runs (the
// pipeline frees an effect that changes stage). In a multisampled window,
// where the lines are drawn over every pixel, GetLineTilesCulled says so.
int CheckLineResources()
{
  vtkNew<vtkFXToonPass> toon;
  auto window = vtkFXTest::MakeWindow(200, 150);
  FX_CHECK(!RenderBunny(window, toon).empty(), "the bunny did not render");
  const bool hadEdges = toon->GetEdgeTexture() != nullptr;
  toon->FeatureLinesOff();
  window->Render();
  const bool keptEdges = toon->GetEdgeTexture() != nullptr;
  std::cout << "lines switched off: the edge texture " << (hadEdges ? "existed" : "DID NOT EXIST")
            << " and " << (keptEdges ? "WAS KEPT" : "was freed") << std::endl;
  FX_CHECK(hadEdges && !keptEdges, "the lines' textures outlive the lines");

  window->MakeCurrent();
  if (!vtkFXToonPass::CanFlagLineTiles())
  {
    return EXIT_SUCCESS; // (no culling to report on either path)
  }
  auto multisampled = vtkFXTest::MakeWindow(200, 150);
  multisampled->SetMultiSamples(4);
  vtkNew<vtkFXToonPass> lines;
  FX_CHECK(!RenderBunny(multisampled, lines).empty(), "the bunny did not render");
  multisampled->MakeCurrent();
  std::cout << "multisampled window (" << multisampled->GetMultiSamples()
            << " samples): tiles culled " << (lines->GetLineTilesCulled() ? "YES" : "no")
            << std::endl;
  FX_CHECK(!lines->GetLineTilesCulled(), "lines drawn over every pixel reported as culled");
  return EXIT_SUCCESS;
}

// LineColor: red lines on the sphere's silhouette. Where the green
// channel says a pixel is covered by c (> 0.3), its red channel is the
// blend c x 255 + (1 - c) x plain, within 3 levels (8-bit rounding of
// both images and of the blend).
int CheckLineColor(vtkRenderWindow* window)
{
  window->SetSize(400, 300);
  vtkFXToonPass* toon = MakeScene(window, Sphere(0.4, 0.6), true);
  toon->BandsOff();
  toon->SetLineColor(1.0, 0.0, 0.0);
  std::vector<unsigned char> plain, lined;
  const auto coverage = LineCoverage(window, toon, &plain, &lined);
  int checked = 0;
  double worst = 0.0;
  for (size_t i = 0; i < coverage.size(); ++i)
  {
    if (coverage[i] > 0.3)
    {
      const double expected = coverage[i] * 255.0 + (1.0 - coverage[i]) * plain[3 * i];
      worst = std::max(worst, std::fabs(lined[3 * i] - expected));
      ++checked;
    }
  }
  std::cout << "red lines: " << checked << " covered pixels, red off the blend by at most "
            << worst << " levels" << std::endl;
  FX_CHECK(checked > 200 && worst <= 3.0, "line colour: " << worst << " levels off");
  return EXIT_SUCCESS;
}

int TestToon(int, char*[])
{
  // One window for every part: a window per part can exhaust a virtual X
  // server's connections.
  auto window = vtkFXTest::MakeWindow(400, 300);
  // Refused thresholds leave the list alone.
  vtkNew<vtkFXToonPass> toon;
  toon->AddBandThreshold(0.5); // not above 0.75: refused with an error
  toon->AddBandThreshold(1.5); // outside (0, 1]
  FX_CHECK(toon->GetNumberOfBandThresholds() == 4, toon->GetNumberOfBandThresholds());

  FX_CHECK(CheckBands(window, { 0.05, 0.25, 0.5, 0.75 }) == EXIT_SUCCESS, "seed's bands");
  FX_CHECK(CheckBands(window, { 0.3, 0.6 }) == EXIT_SUCCESS, "custom bands");
  double width1 = 0.0, width2 = 0.0;
  FX_CHECK(CheckSphereLines(window, 300, width1) == EXIT_SUCCESS, "lines at 400x300");
  FX_CHECK(CheckSphereLines(window, 600, width2) == EXIT_SUCCESS, "lines at 800x600");
  FX_CHECK(std::fabs(width2 / width1 - 2.0) < 0.2,
    "lines at twice the size are " << width2 / width1 << " times as wide");
  FX_CHECK(CheckFandiskCreases(window, false) == EXIT_SUCCESS, "fandisk creases");
  FX_CHECK(CheckFandiskCreases(window, true) == EXIT_SUCCESS, "PBR fandisk creases");
  FX_CHECK(CheckTileCulling(window) == EXIT_SUCCESS, "tile culling");
  FX_CHECK(CheckScaleInvariance(window) == EXIT_SUCCESS, "scale invariance");
  FX_CHECK(CheckUnlitBackdrop(window) == EXIT_SUCCESS, "unlit backdrop");
  FX_CHECK(CheckScaledScreenshot(window) == EXIT_SUCCESS, "scaled screenshot");
  FX_CHECK(CheckOffsetViewport(window) == EXIT_SUCCESS, "offset viewport");
  FX_CHECK(CheckGrazingFloor(window, false) == EXIT_SUCCESS, "floor at grazing angles");
  FX_CHECK(CheckGrazingFloor(window, true) == EXIT_SUCCESS, "bumped floor");
  FX_CHECK(CheckLinesBehindForwardProps(window) == EXIT_SUCCESS, "lines behind forward props");
  FX_CHECK(CheckLineColor(window) == EXIT_SUCCESS, "line colour");
  FX_CHECK(CheckLineResources() == EXIT_SUCCESS, "line resources");

  // What a configuration needs and no more: bands alone read no linear
  // depth; lines of no kind (silhouettes and creases off) are no work.
  {
    vtkNew<vtkSphereSource> source;
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(source->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    vtkFXToonPass* configured = MakeScene(window, actor, false);
    auto* pipeline =
      vtkFXPipelinePass::SafeDownCast(window->GetRenderers()->GetFirstRenderer()->GetPass());
    const unsigned int depthBit = vtkFXGBufferPass::ChannelBit(vtkFXGBufferPass::LinearDepth);
    window->Render();
    FX_CHECK(pipeline->GetGBufferChannels() & depthBit, "lines read linear depth");
    configured->FeatureLinesOff();
    window->Render();
    FX_CHECK(!(pipeline->GetGBufferChannels() & depthBit), "bands alone allocate linear depth");
    configured->FeatureLinesOn();
    configured->BandsOff();
    configured->SilhouettesOff();
    configured->CreasesOff();
    window->Render();
    const std::string passes = vtkFXTest::Passes(pipeline);
    std::cout << "lines of no kind: passes " << passes << std::endl;
    FX_CHECK(passes.find("toon") == std::string::npos && !(pipeline->GetGBufferChannels() & depthBit),
      "lines of no kind still ran: " << passes);
  }
  return EXIT_SUCCESS;
}
