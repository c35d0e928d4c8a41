// Many deferred point lights (vtkFXCompositePass's light texture, culled per
// screen tile by vtkFXLightTiles), against VTK's forward render of the same
// lights:
// - 256 point lights over scene:spheres: PSNR >= 55 dB and no byte more than 2 off, and the tiles hold
//   a small part of the lights (culling happened);
// - one point light forced through the tiled path (MaximumUniformLights 0):
//   PSNR >= 55 dB and no byte more than 2 off;
// - a light at the camera (its sphere of influence crosses the near plane)
//   and parallel projection: PSNR >= 55 dB and no byte more than 2 off;
// - an explicit projection matrix (perspective and parallel) with a
//   clipping range it ignores: PSNR >= 55 dB and no byte more than 2 off
//   (the lights' depths were clamped to the clipping range: all culled);
// - culling against none (LightCutoff 0) with 64 lights: PSNR >= 55 dB and no byte more than 2 off
//   (each left-out light adds under 1/512 where it is left out);
// - the range formula: the light adds exactly the cutoff at its range.
#include "vtkFXCompositePass.h"
#include "vtkFXLightTiles.h"
#include "vtkFXPipelinePass.h"
#include "vtkFXScenes.h"
#include "vtkFXToonPass.h"
#include "vtkFXTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkActorCollection.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkRendererCollection.h"
#include "vtkTextureObject.h"
#include "vtkOpenGLRenderWindow.h"

#include <cmath>
#include <limits>

namespace
{
struct Lit
{
  std::vector<unsigned char> FX, VTK;
  double LightsPerTile = 0.0;
};

// A fresh renderer alone in `window` showing scene:spheres on its ground,
// lit by `count` point lights over it; nullptr (with `error`) on failure.
vtkRenderer* LitSpheres(vtkRenderWindow* window, int count, std::string& error)
{
  window->GetRenderers()->RemoveAllItems();
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  double bounds[6];
  if (!vtkFXScenes::Populate(renderer, "scene:spheres", vtkFXScenes::Options(), error, bounds))
  {
    return nullptr;
  }
  vtkFXScenes::AddPointLights(renderer, count, bounds);
  return renderer; // (the window holds it)
}

// scene:spheres on its ground lit by `count` point lights (and, with
// `atCamera`, one more at the camera; with `spots`, every third light a
// spot light of 50 degrees looking down), in vtkFX (with the composite set
// up by `configure`) and in VTK's forward render.
Lit Render(vtkRenderWindow* window, int count, bool atCamera, bool parallel,
  void (*configure)(vtkFXCompositePass*), bool spots = false, bool explicitProjection = false)
{
  Lit result;
  for (bool fx : { true, false })
  {
    std::string error;
    vtkRenderer* renderer = LitSpheres(window, count, error);
    if (!renderer)
    {
      std::cerr << error << std::endl;
      return result;
    }
    if (spots)
    {
      vtkLightCollection* lights = renderer->GetLights();
      for (int i = 0; i < lights->GetNumberOfItems(); i += 3)
      {
        vtkLight* light = vtkLight::SafeDownCast(lights->GetItemAsObject(i));
        light->SetConeAngle(50.0);
        light->SetExponent(2.0);
      }
    }
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetParallelProjection(parallel);
    if (atCamera)
    {
      vtkNew<vtkLight> light;
      light->SetLightTypeToSceneLight();
      light->PositionalOn();
      light->SetConeAngle(180.0);
      light->SetPosition(camera->GetPosition());
      light->SetFocalPoint(camera->GetFocalPoint());
      light->SetAttenuationValues(1.0, 0.0, 0.05);
      renderer->AddLight(light);
    }
    if (explicitProjection)
    {
      // The camera's own projection as an explicit matrix, and a clipping
      // range that matrix ignores (VTK draws by the matrix alone).
      vtkNew<vtkMatrix4x4> projection;
      projection->DeepCopy(
        camera->GetProjectionTransformMatrix(renderer->GetTiledAspectRatio(), -1, 1));
      camera->SetExplicitProjectionTransformMatrix(projection);
      camera->UseExplicitProjectionTransformMatrixOn();
      camera->SetClippingRange(1e-3, 2e-3);
    }
    vtkNew<vtkFXPipelinePass> pipeline;
    if (fx)
    {
      configure(pipeline->GetCompositePass());
      renderer->SetPass(pipeline);
    }
    window->Render();
    (fx ? result.FX : result.VTK) = vtkFXScenes::Capture(window);
    if (fx)
    {
      result.LightsPerTile = pipeline->GetCompositePass()->GetMeanLightsPerTile();
    }
  }
  return result;
}

void Defaults(vtkFXCompositePass*) {}
void AllTiled(vtkFXCompositePass* composite)
{
  composite->SetMaximumUniformLights(0);
}
void NoCulling(vtkFXCompositePass* composite)
{
  composite->SetLightCutoff(0.0);
}
void NoDepthBounds(vtkFXCompositePass* composite)
{
  composite->TileDepthBoundsOff();
}
void IndexEntries(vtkFXCompositePass* composite)
{
  composite->SetMaximumTileRowEntries(0); // every list holds indices
}

int Check(const char* name, const std::vector<unsigned char>& a, const std::vector<unsigned char>& b,
  double minimum, int largest = 255)
{
  const double psnr = vtkFXScenes::PSNR(a, b);
  const int difference = vtkFXScenes::MaxDifference(a, b);
  std::cout << name << ": PSNR " << psnr << " dB, largest difference " << difference << "/255"
            << std::endl;
  FX_CHECK(psnr >= minimum && difference <= largest,
    name << ": " << psnr << " dB, largest difference " << difference);
  return EXIT_SUCCESS;
}
}

// 17 lights whose spheres cover every tile, 12 point lights and then 5
// spot lights; each row holds 100 times its light's number (5 to 21) plus
// the float's index.
std::vector<vtkFXLightTiles::Light> LightsEverywhere()
{
  std::vector<vtkFXLightTiles::Light> everywhere(17);
  for (size_t k = 0; k < everywhere.size(); ++k)
  {
    everywhere[k].Center[0] = everywhere[k].Center[1] = 0.0;
    everywhere[k].Center[2] = -1.0;
    everywhere[k].Radius = HUGE_VAL;
    for (int f = 0; f < 4 * vtkFXLightTiles::EntryTexels; ++f)
    {
      everywhere[k].Row[f] = 100.0f * (5 + k) + f;
    }
  }
  return everywhere;
}

// Where textures are smaller than the 4096 texels the default layouts
// need (OpenGL 3 promises 1024), a row of the entries' texture holds
// fewer entries, and the lists turn to indices, then to one shared list,
// where the textures can hold no more: here at 64 texels, with 17 lights
// over every tile. The uploaded texture has the layout GetEntriesPerRow
// gives the composite's shader.
int CheckSmallTextures(vtkRenderWindow* window)
{
  window->Render();
  window->MakeCurrent();
  auto* glWindow = vtkOpenGLRenderWindow::SafeDownCast(window);
  const std::vector<vtkFXLightTiles::Light> everywhere = LightsEverywhere();
  const double identity[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  vtkFXLightTiles tiles;
  tiles.SetMaximumTextureSize(64);
  // The texture as uploaded, against the entries built: entry e at texel
  // (e % perRow) x texels, e / perRow.
  const auto uploadedAsBuilt = [&](int texelsPerEntry) {
    tiles.Upload(glWindow);
    vtkTextureObject* texture = tiles.GetEntryTexture();
    const int components = texelsPerEntry == 1 ? 1 : 4;
    const size_t floatsPerEntry = static_cast<size_t>(texelsPerEntry) * components;
    const std::vector<float> texels = vtkFXTest::Download(texture, components);
    const std::vector<float>& built = tiles.GetEntryData();
    const int perRow = tiles.GetEntriesPerRow();
    FX_CHECK(texture->GetWidth() <= 64 && texture->GetHeight() <= 64,
      "entries' texture " << texture->GetWidth() << " x " << texture->GetHeight());
    for (size_t e = 0; e < built.size() / floatsPerEntry; ++e)
    {
      const size_t x = (e % perRow) * texelsPerEntry, y = e / perRow;
      const size_t at = (y * texture->GetWidth() + x) * components;
      for (size_t f = 0; f < floatsPerEntry; ++f)
      {
        FX_CHECK(at + f < texels.size() && texels[at + f] == built[e * floatsPerEntry + f],
          "entry " << e << " float " << f);
      }
    }
    return EXIT_SUCCESS;
  };
  // 16 tiles x 17 lights: 272 entries as rows, 16 to a row.
  FX_CHECK(tiles.Build(everywhere, identity, 64, 64, nullptr, 12) && tiles.GetEntriesAreRows() &&
      tiles.GetEntriesPerRow() == 16,
    "rows, 16 to a row: " << tiles.GetEntriesPerRow());
  FX_CHECK(uploadedAsBuilt(vtkFXLightTiles::EntryTexels) == EXIT_SUCCESS, "rows uploaded");
  // 64 tiles: 1088 entries, more than 64 rows of 16: indices, 64 to a row.
  FX_CHECK(tiles.Build(everywhere, identity, 128, 128, nullptr, 12, 5) &&
      !tiles.GetEntriesAreRows() && tiles.GetEntriesPerRow() == 64,
    "indices, 64 to a row: " << tiles.GetEntriesPerRow());
  FX_CHECK(tiles.GetEntryData().size() == 17u * 64 && tiles.GetEntryData()[17] == 5.0f,
    "index entries");
  FX_CHECK(uploadedAsBuilt(1) == EXIT_SUCCESS, "indices uploaded");
  // 256 tiles: 4352 entries, more than 64 rows of 64: one shared list.
  FX_CHECK(!tiles.Build(everywhere, identity, 256, 256, nullptr, 12), "the overflow is reported");
  FX_CHECK(tiles.GetEntriesAreRows() && tiles.GetEntryData().size() == 17u * 16, "one shared list");
  FX_CHECK(uploadedAsBuilt(vtkFXLightTiles::EntryTexels) == EXIT_SUCCESS, "shared list uploaded");
  tiles.ReleaseGraphicsResources(window);

  // The entries' texture is not allocated again for every count of entries
  // (which changes nearly every frame while the lights or the camera move):
  // whole rows, and a power of two of them, kept while they hold the lists.
  vtkFXLightTiles growing;
  std::vector<std::array<unsigned int, 3>> textures; // handle, width, height
  for (size_t lights : { 17, 16, 12, 17, 9 })
  {
    const std::vector<vtkFXLightTiles::Light> some(everywhere.begin(), everywhere.begin() + lights);
    FX_CHECK(growing.Build(some, identity, 64, 64, nullptr, 12), "lists of " << lights << " lights");
    FX_CHECK(growing.GetEntriesAreRows(), "rows");
    growing.Upload(glWindow);
    vtkTextureObject* texture = growing.GetEntryTexture();
    textures.push_back({ texture->GetHandle(), texture->GetWidth(), texture->GetHeight() });
  }
  std::cout << "entries' texture for 17, 16, 12, 17 and 9 lights over 16 tiles:";
  for (const auto& t : textures)
  {
    std::cout << " " << t[1] << " x " << t[2] << " (" << t[0] << ")";
  }
  std::cout << std::endl;
  FX_CHECK(std::all_of(textures.begin(), textures.end(), [&](const std::array<unsigned int, 3>& t) {
    return t == textures[0];
  }),
    "the entries' texture was allocated again for another count of entries");
  growing.ReleaseGraphicsResources(window);
  // Rows of 16 entries (a 64-texel limit): 17 lights over 16 tiles take 17
  // rows (32 allocated), 12 lights 12 rows (the 32 kept), 5 lights 5 rows
  // (8: the 32 were four times too many).
  growing.SetMaximumTextureSize(64);
  std::vector<int> heights;
  for (size_t lights : { 17, 12, 5 })
  {
    const std::vector<vtkFXLightTiles::Light> some(everywhere.begin(), everywhere.begin() + lights);
    FX_CHECK(growing.Build(some, identity, 64, 64, nullptr, 12) && growing.GetEntriesPerRow() == 16,
      "rows of 16 entries");
    growing.Upload(glWindow);
    heights.push_back(static_cast<int>(growing.GetEntryTexture()->GetHeight()));
  }
  std::cout << "entries' texture rows for 17, 12 and 5 lights, 16 entries to a row: " << heights[0]
            << ", " << heights[1] << ", " << heights[2] << std::endl;
  FX_CHECK(heights == std::vector<int>({ 32, 32, 8 }), "rows allocated");
  growing.ReleaseGraphicsResources(window);
  return EXIT_SUCCESS;
}

// vtkFXLightTiles::MeasureTileDepths on a 40 x 20 linear-depth image (3 x
// 2 tiles of 16 pixels, the last column and row partial): tile (0, 0)
// depths 3 to 7 with a NaN pixel, tile (1, 0) all 5, tile (2, 0) (24 x
// 16 pixels, 8 of them columns past the image's edge) 9 except a 0
// (background) pixel, the upper row background. The ranges read back
// exactly (empty tiles: nearest above farthest); Build then lists a light
// for a tile only where its sphere's depth extent (depth of its centre,
// -z in view space, plus or minus its radius) meets the range. Seen
// through a projection that magnifies x and y a hundredfold, every
// sphere covers every tile's rectangle, so the depth bounds alone decide.
int CheckTileDepths(vtkRenderWindow* window)
{
  window->Render();
  window->MakeCurrent();
  const int w = 40, h = 20;
  std::vector<float> depth(static_cast<size_t>(w) * h, 0.0f);
  for (int y = 0; y < 16; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      float& d = depth[static_cast<size_t>(y) * w + x];
      d = x < 16 ? 3.0f + 4.0f * (x + 16 * y) / 255.0f : x < 32 ? 5.0f : 9.0f;
    }
  }
  depth[5 * w + 7] = std::numeric_limits<float>::quiet_NaN();
  depth[3 * w + 35] = 0.0f;
  vtkNew<vtkTextureObject> texture;
  texture->SetContext(vtkOpenGLRenderWindow::SafeDownCast(window));
  FX_CHECK(texture->Create2DFromRaw(w, h, 1, VTK_FLOAT, depth.data()), "depth texture");
  vtkFXLightTiles tiles;
  FX_CHECK(tiles.MeasureTileDepths(vtkOpenGLRenderWindow::SafeDownCast(window), texture, w, h),
    "the depth pass ran");
  const auto& ranges = tiles.GetTileDepths();
  FX_CHECK(ranges.size() == 12, ranges.size() << " values for 6 tiles");
  std::cout << "tile depths:";
  for (size_t t = 0; t < 6; ++t)
  {
    std::cout << " (" << ranges[2 * t] << ", " << ranges[2 * t + 1] << ")";
  }
  std::cout << std::endl;
  FX_CHECK(ranges[0] == 3.0f && ranges[1] == depth[15 * w + 15], "tile (0, 0)");
  FX_CHECK(ranges[2] == 5.0f && ranges[3] == 5.0f, "tile (1, 0)");
  FX_CHECK(ranges[4] == 9.0f && ranges[5] == 9.0f, "tile (2, 0): background and the edge");
  for (size_t t = 3; t < 6; ++t)
  {
    FX_CHECK(ranges[2 * t] > ranges[2 * t + 1], "tile " << t << " has no surface");
  }
  // Lights over every tile's rectangle (a projection that magnifies x and
  // y a hundredfold), told apart by depth only.
  const double magnifying[16] = { 100, 0, 0, 0, 0, 100, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  const auto listed = [&](double depthOfCentre, double radius) {
    vtkFXLightTiles::Light light{ { 0.0, 0.0, -depthOfCentre }, radius, {} };
    tiles.Build({ light }, magnifying, w, h);
    std::vector<int> per(6);
    for (size_t t = 0; t < 6; ++t)
    {
      per[t] = static_cast<int>(tiles.GetHeaderData()[vtkFXLightTiles::HeaderValues * t + 1]);
    }
    return per;
  };
  FX_CHECK(listed(8.0, 0.5) == std::vector<int>({ 0, 0, 0, 0, 0, 0 }), "a light between depths");
  FX_CHECK(listed(8.5, 0.6) == std::vector<int>({ 0, 0, 1, 0, 0, 0 }), "a light reaching 9");
  FX_CHECK(listed(8.0, 1.0) == std::vector<int>({ 1, 0, 1, 0, 0, 0 }), "one touching 7 and 9");
  FX_CHECK(listed(4.0, 1.0) == std::vector<int>({ 1, 1, 0, 0, 0, 0 }), "a light from 3 to 5");
  FX_CHECK(listed(4.0, HUGE_VAL) == std::vector<int>({ 1, 1, 1, 1, 1, 1 }),
    "an unbounded light reaches every tile");
  tiles.ForgetTileDepths();
  FX_CHECK(listed(8.0, 0.5) == std::vector<int>({ 1, 1, 1, 1, 1, 1 }),
    "without depths, every tile its rectangle covers");
  tiles.ReleaseGraphicsResources(window);
  return EXIT_SUCCESS;
}

// Lights with a NaN or infinite number in what VTK's light uniforms carry
// (position, focal point, colour x intensity, also past a float's range;
// a positional light's attenuation, a spot's exponent) among good ones,
// first and in between: vtkFX's deferred lighting leaves them out (VTK's
// own render turns them into NaN: black), so the image is the one without
// them, on VTK's uniforms (3 + 5 point lights; 2 + 2 directional ones,
// lighting complexity 2) and on the light texture (3 + 7, forced, and
// 64 + 7), with one warning for two frames. Made finite again, they light
// as a fresh pipeline draws them.
int CheckNonFiniteLights(vtkRenderWindow* window)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const struct
  {
    int Good, Bad;
    bool Texture, Directional;
  } cases[] = { { 3, 5, false, false }, { 3, 7, true, false }, { 64, 7, false, false },
    { 2, 2, false, true } };
  for (const auto& c : cases)
  {
    std::string error;
    vtkRenderer* renderer = LitSpheres(window, c.Good, error);
    FX_CHECK(renderer, error);
    std::vector<vtkSmartPointer<vtkLight>> lights;
    vtkCollectionSimpleIterator it;
    renderer->GetLights()->InitTraversal(it);
    while (vtkLight* light = renderer->GetLights()->GetNextLight(it))
    {
      light->SetPositional(!c.Directional);
      lights.push_back(light);
    }
    auto pipeline = vtkSmartPointer<vtkFXPipelinePass>::New();
    if (c.Texture)
    {
      pipeline->GetCompositePass()->SetMaximumUniformLights(0);
    }
    renderer->SetPass(pipeline);
    window->Render();
    const auto good = vtkFXScenes::Capture(window);

    std::vector<vtkSmartPointer<vtkLight>> bad;
    for (int k = 0; k < c.Bad; ++k)
    {
      auto light = vtkSmartPointer<vtkLight>::New();
      light->DeepCopy(lights.front());
      switch (c.Directional ? 2 * k : k)
      {
        case 0: light->SetPosition(nan, 1.0, 0.0); break;
        case 1: light->SetIntensity(inf); break;
        case 2: light->SetColor(nan, 1.0, 1.0); break;
        case 3: light->SetAttenuationValues(1.0, nan, 0.0); break;
        case 4: light->SetIntensity(1e39); break; // (finite, not as a float)
        case 5: // a spot light's exponent (VTK's clamp lets NaN through)
          light->SetConeAngle(50.0);
          light->SetExponent(nan);
          break;
        default: light->SetFocalPoint(0.0, -inf, 0.0); break;
      }
      bad.push_back(light);
    }
    renderer->RemoveAllLights();
    renderer->AddLight(bad[0]); // before every good one: the places shift
    for (size_t i = 0; i < lights.size(); ++i)
    {
      renderer->AddLight(lights[i]);
      if (i + 1 < bad.size())
      {
        renderer->AddLight(bad[i + 1]);
      }
    }
    for (size_t i = lights.size() + 1; i < bad.size(); ++i)
    {
      renderer->AddLight(bad[i]);
    }
    vtkFXTest::EventCounter warnings(pipeline, vtkCommand::WarningEvent);
    window->Render();
    window->Render();
    const std::string name = std::to_string(c.Good) + (c.Directional ? " directional" : "") +
      " lights and " + std::to_string(c.Bad) + " with NaN or infinite numbers" +
      (c.Texture ? ", light texture" : "");
    FX_CHECK(Check(name.c_str(), good, vtkFXScenes::Capture(window), 60.0, 1) == EXIT_SUCCESS, "");
    std::cout << name << ": " << warnings.Count << " warning(s): " << warnings.Last << std::endl;
    FX_CHECK(warnings.Count == 1, warnings.Count << " warnings about the lights");

    // Made finite again (copies of the first good light): lit as a fresh
    // pipeline lights them, nothing left dark.
    for (auto& light : bad)
    {
      light->DeepCopy(lights.front());
    }
    window->Render();
    const auto mended = vtkFXScenes::Capture(window);
    auto fresh = vtkSmartPointer<vtkFXPipelinePass>::New();
    fresh->GetCompositePass()->SetMaximumUniformLights(
      pipeline->GetCompositePass()->GetMaximumUniformLights());
    renderer->SetPass(fresh);
    window->Render();
    FX_CHECK(Check((name + ", made finite").c_str(), vtkFXScenes::Capture(window), mended, 60.0, 1) ==
        EXIT_SUCCESS, "");
    FX_CHECK(vtkFXScenes::MaxDifference(good, mended) > 10, name << ": the mended lights add no light");
    pipeline->ReleaseGraphicsResources(window);
  }
  return EXIT_SUCCESS;
}

int TestLights(int, char*[])
{
  // The range: 2 x intensity / (a0 + a1 d + a2 d^2) is the cutoff there.
  const double attenuation[3] = { 1.0, 0.5, 2.0 };
  const double range = vtkFXLightTiles::Range(0.8, attenuation, 1.0 / 512.0);
  const double added = 2.0 * 0.8 / (1.0 + 0.5 * range + 2.0 * range * range);
  FX_CHECK(std::fabs(added - 1.0 / 512.0) < 1e-12, "range " << range << " adds " << added);
  const double flat[3] = { 1.0, 0.0, 0.0 };
  FX_CHECK(std::isinf(vtkFXLightTiles::Range(1.0, flat, 1.0 / 512.0)), "VTK's default never fades");
  const double dim[3] = { 2000.0, 0.0, 0.0 };
  FX_CHECK(vtkFXLightTiles::Range(1.0, dim, 1.0 / 512.0) < 0.0, "a light under the cutoff");
  // Denominators that fall: to 0 (no range), or dip before they grow (the
  // range beyond the dip, though the light is dim at its own position).
  {
    const double falling[3] = { 1.0, 0.0, -0.01 }, linearFalling[3] = { 1.0, -0.1, 0.0 };
    FX_CHECK(std::isinf(vtkFXLightTiles::Range(5e-4, falling, 1.0 / 512.0)), "a2 < 0");
    FX_CHECK(std::isinf(vtkFXLightTiles::Range(5e-4, linearFalling, 1.0 / 512.0)), "a1 < 0, a2 = 0");
    // 1 - 0.4 d + 0.05 d^2: lowest 0.2 at d = 4; with intensity 0.1 the
    // light there is 0.5, at the light 0.1; 2 x 0.1 / cutoff 0.25 = 0.8
    // is reached again at d = 4 + sqrt(12) = 7.46.
    const double dip[3] = { 1.0, -0.4, 0.05 };
    const double r = vtkFXLightTiles::Range(0.1, dip, 0.25);
    FX_CHECK(std::fabs(r - (4.0 + std::sqrt(12.0))) < 1e-9, "a dipping denominator: range " << r);
    const double zeroDip[3] = { 1.0, -2.0, 1.0 }; // (1 - d)^2: infinite at d = 1
    FX_CHECK(std::isinf(vtkFXLightTiles::Range(1e-6, zeroDip, 1.0 / 512.0)), "a dip to 0");
  }
  // A quadratic term tiny against the linear one: the range of the linear
  // term (1023), not 0 from cancellation.
  const double nearlyLinear[3] = { 1.0, 1.0, 1e-20 };
  const double linearRange = vtkFXLightTiles::Range(1.0, nearlyLinear, 1.0 / 512.0);
  std::cout << "attenuation (1, 1, 1e-20): range " << linearRange << std::endl;
  FX_CHECK(std::fabs(linearRange - 1023.0) < 1e-6, "range " << linearRange << " for (1, 1, 1e-20)");

  // Lists past 2^20 entries (17 lights over every tile of a 16384^2
  // viewport: 17.8 million) are not built: every tile lists every light
  // instead, in light order. The 17 are 12 point lights and then 5 spot
  // lights; each entry carries its light's row (here 16 times the light's
  // number, 5 to 21).
  {
    vtkFXLightTiles tiles;
    const std::vector<vtkFXLightTiles::Light> everywhere = LightsEverywhere();
    const double identity[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
    const size_t H = vtkFXLightTiles::HeaderValues;
    const size_t E = 4 * vtkFXLightTiles::EntryTexels; // floats per entry
    FX_CHECK(!tiles.Build(everywhere, identity, 16384, 16384, nullptr, 12),
      "the overflow is reported");
    const auto& headers = tiles.GetHeaderData();
    const auto& entries = tiles.GetEntryData();
    FX_CHECK(headers.size() == H * 1024 * 1024 && entries.size() == 17 * E, "one shared list");
    for (size_t t = 0; t < headers.size() / H; ++t)
    {
      FX_CHECK(headers[H * t] == 0.0f && headers[H * t + 1] == 12.0f && headers[H * t + 2] == 5.0f,
        "tile " << t);
    }
    for (size_t i = 0; i < entries.size(); ++i)
    {
      FX_CHECK(entries[i] == 100.0f * (5 + i / E) + i % E, "entry value " << i);
    }
    FX_CHECK(tiles.Build(everywhere, identity, 256, 256, nullptr, 12), "small lists are built");
    FX_CHECK(tiles.GetEntryData().size() == 17u * 16 * 16 * E, "every tile lists the 17 lights");
    // Each tile's list: its point lights, then its spot lights, each
    // entry its light's row.
    for (size_t t = 0; t < 16 * 16; ++t)
    {
      const auto& h = tiles.GetHeaderData();
      FX_CHECK(h[H * t + 1] == 12.0f && h[H * t + 2] == 5.0f, "tile " << t << " counts");
      const size_t first = static_cast<size_t>(h[H * t]);
      for (size_t k = 0; k < 17; ++k)
      {
        for (size_t f = 0; f < E; ++f)
        {
          FX_CHECK(tiles.GetEntryData()[(first + k) * E + f] == 100.0f * (5 + k) + f,
            "tile " << t << " entry " << k);
        }
      }
    }
    FX_CHECK(std::fabs(tiles.GetMeanLightsPerTile() - 17.0) < 1e-12, "17 lights per tile");
    FX_CHECK(tiles.GetEntriesAreRows(), "small lists carry the rows");
    // Past 2^20 entries (17 lights over the 65,536 tiles of 4096^2: 1.1
    // million) the entries are the rows' indices, here from row 5 on.
    FX_CHECK(tiles.Build(everywhere, identity, 4096, 4096, nullptr, 12, 5), "indices are built");
    FX_CHECK(!tiles.GetEntriesAreRows() && tiles.GetEntryData().size() == 17u * 256 * 256,
      "lists past 2^20 entries hold indices");
    const size_t last = static_cast<size_t>(tiles.GetHeaderData()[H * (256 * 256 - 1)]);
    for (size_t k = 0; k < 17; ++k)
    {
      FX_CHECK(tiles.GetEntryData()[last + k] == static_cast<float>(5 + k), "index entry " << k);
    }
  }

  // A light whose sphere crosses the camera's plane lights surfaces only
  // between the clipping planes: beside the camera (out of view) it reaches
  // no tile; in front of it, some; without the depth range, every tile.
  {
    vtkNew<vtkCamera> camera; // at the origin, looking down -z
    camera->SetPosition(0.0, 0.0, 0.0);
    camera->SetFocalPoint(0.0, 0.0, -1.0);
    camera->SetClippingRange(1.0, 100.0);
    vtkMatrix4x4* projection = camera->GetProjectionTransformMatrix(1.0, -1, 1);
    const double* p = &projection->Element[0][0];
    const double depths[2] = { 1.0, 100.0 };
    vtkFXLightTiles tiles;
    const std::vector<vtkFXLightTiles::Light> beside = { { { 50.0, 0.0, 0.0 }, 2.0 } };
    const std::vector<vtkFXLightTiles::Light> ahead = { { { 0.0, 0.0, 1.0 }, 5.0 } };
    tiles.Build(beside, p, 64, 64, depths);
    const double besideTiles = tiles.GetMeanLightsPerTile();
    tiles.Build(beside, p, 64, 64);
    const double besideUnranged = tiles.GetMeanLightsPerTile();
    tiles.Build(ahead, p, 64, 64, depths);
    const double aheadTiles = tiles.GetMeanLightsPerTile();
    std::cout << "a light across the camera's plane: beside " << besideTiles << " (without depths "
              << besideUnranged << "), ahead " << aheadTiles << " of the tiles" << std::endl;
    FX_CHECK(besideTiles == 0.0 && besideUnranged == 1.0 && aheadTiles > 0.0, "depth range");
  }

  auto window = vtkFXTest::MakeWindow(200, 150);
  FX_CHECK(CheckTileDepths(window) == EXIT_SUCCESS, "tile depths");
  FX_CHECK(CheckSmallTextures(window) == EXIT_SUCCESS, "lists within small textures");
  FX_CHECK(CheckNonFiniteLights(window) == EXIT_SUCCESS, "lights with NaN or infinite numbers");
  const Lit many = Render(window, 256, false, false, Defaults);
  std::cout << "256 lights: " << many.LightsPerTile << " lights per tile" << std::endl;
  FX_CHECK(Check("256 point lights", many.FX, many.VTK, 55.0, 2) == EXIT_SUCCESS, "");
  FX_CHECK(many.LightsPerTile > 0.0 && many.LightsPerTile < 256 / 4.0,
    "tiles hold " << many.LightsPerTile << " of 256 lights");

  const Lit one = Render(window, 1, false, false, AllTiled);
  FX_CHECK(one.LightsPerTile > 0.0, "one light did not take the tiled path");
  FX_CHECK(Check("1 point light, tiled", one.FX, one.VTK, 55.0, 2) == EXIT_SUCCESS, "");

  const Lit near = Render(window, 16, true, false, Defaults);
  FX_CHECK(Check("a light at the camera", near.FX, near.VTK, 55.0, 2) == EXIT_SUCCESS, "");
  const Lit parallel = Render(window, 64, false, true, Defaults);
  FX_CHECK(Check("64 lights, parallel projection", parallel.FX, parallel.VTK, 55.0, 2) == EXIT_SUCCESS, "");

  // An explicit projection matrix, the camera's clipping range elsewhere:
  // the lights' depth range is the matrix's.
  for (bool parallelView : { false, true })
  {
    const Lit given = Render(window, 64, false, parallelView, Defaults, false, true);
    FX_CHECK(Check(parallelView ? "64 lights, explicit parallel projection"
                                : "64 lights, explicit projection",
               given.FX, given.VTK, 55.0, 2) == EXIT_SUCCESS,
      "");
  }

  const Lit culled = Render(window, 64, false, false, Defaults);
  const Lit all = Render(window, 64, false, false, NoCulling);
  std::cout << "64 lights: " << culled.LightsPerTile << " lights per tile" << std::endl;
  FX_CHECK(culled.LightsPerTile < 64 / 2, "culling left out too little");
  FX_CHECK(all.LightsPerTile == 0.0, "tiles without a cutoff");
  FX_CHECK(Check("culled against all lights", culled.FX, all.FX, 55.0, 2) == EXIT_SUCCESS, "");
  const int culledOff = vtkFXScenes::MaxDifference(culled.FX, all.FX);
  std::cout << "culled against all lights: at most " << culledOff << " levels off" << std::endl;
  FX_CHECK(culledOff <= 2, "culling cut visible light");
  // The tiles' depth bounds (TileDepthBounds) leave a light out of tiles
  // whose surfaces its sphere does not reach in depth: far fewer lights
  // per tile on the ground seen at an angle, the same image (a light is
  // only left out where it adds under the cutoff: within 2 levels of the
  // unbounded tiles, and of VTK).
  const Lit unbounded = Render(window, 64, false, false, NoDepthBounds);
  const int boundsOff = vtkFXScenes::MaxDifference(culled.FX, unbounded.FX);
  std::cout << "64 lights, tiles bounded in depth: " << culled.LightsPerTile
            << " lights per tile against " << unbounded.LightsPerTile << " unbounded, images at most "
            << boundsOff << " levels apart" << std::endl;
  FX_CHECK(culled.LightsPerTile < 0.75 * unbounded.LightsPerTile,
    "depth bounds left out too little: " << culled.LightsPerTile << " of "
                                        << unbounded.LightsPerTile);
  FX_CHECK(boundsOff <= 2, "depth bounds cut visible light");
  FX_CHECK(Check("64 lights, tiles bounded in depth", culled.FX, culled.VTK, 55.0, 2) == EXIT_SUCCESS,
    "");
  // Tile entries as indices into the light texture instead of copies of
  // the lights' rows (lists past MaximumTileRowEntries): the same image,
  // spots included.
  const Lit indexed = Render(window, 64, false, false, IndexEntries, true);
  // Every third light a spot light (50 degrees, looking down: the spot
  // loop), culled by tiles and depth, and untiled (LightCutoff 0: the
  // untiled spot loop), against VTK.
  const Lit spots = Render(window, 64, false, false, Defaults, true);
  FX_CHECK(spots.LightsPerTile > 0.0 && spots.LightsPerTile < 64 / 2, "spots culled");
  FX_CHECK(Check("64 lights, a third spots", spots.FX, spots.VTK, 55.0, 2) == EXIT_SUCCESS, "");
  const Lit spotsUntiled = Render(window, 64, false, false, NoCulling, true);
  FX_CHECK(Check("64 lights, a third spots, untiled", spotsUntiled.FX, spotsUntiled.VTK, 55.0, 2) ==
      EXIT_SUCCESS,
    "");
  FX_CHECK(vtkFXScenes::MaxDifference(indexed.FX, spots.FX) == 0 &&
      std::fabs(indexed.LightsPerTile - spots.LightsPerTile) < 1e-12,
    "index entries change the image");
  FX_CHECK(vtkFXScenes::PSNR(spots.FX, spots.VTK) < 90.0 &&
      vtkFXScenes::MaxDifference(spots.FX, culled.FX) > 10,
    "the spot cones change the image");

  // Toon bands raise a light's diffuse factor from the first threshold on
  // (here 0.001) to a whole band (0.5) however dim the light is: the tiles
  // must reach wherever the factor gets to 0.001, not only where the light
  // exceeds the cutoff. Likewise a diffuse colour of 40 multiplies what a
  // light adds. Culled and unculled images agree.
  // Without thresholds every positive factor becomes 1: no light ends.
  for (int variant : { 0, 1, 2 })
  {
    const bool toon = variant < 2;
    std::vector<unsigned char> images[2];
    for (bool culling : { true, false })
    {
      std::string error;
      vtkRenderer* renderer = LitSpheres(window, 64, error);
      FX_CHECK(renderer, error);
      // dim lights: their cutoff ranges end well before their factors
      // fall to 0.001
      vtkLightCollection* lights = renderer->GetLights();
      vtkCollectionSimpleIterator it;
      lights->InitTraversal(it);
      while (vtkLight* light = lights->GetNextLight(it))
      {
        light->SetIntensity(0.05 * light->GetIntensity());
      }
      vtkNew<vtkFXPipelinePass> pipeline;
      vtkNew<vtkFXToonPass> bands;
      bands->FeatureLinesOff();
      bands->RemoveAllBandThresholds();
      if (variant == 0)
      {
        bands->AddBandThreshold(0.001);
        bands->AddBandThreshold(0.5);
      }
      if (toon)
      {
        pipeline->AddEffect("toon", bands);
      }
      else
      {
        // (GetActors rebuilds its collection on every call: once)
        vtkActorCollection* actors = renderer->GetActors();
        vtkCollectionSimpleIterator it;
        actors->InitTraversal(it);
        while (vtkActor* actor = actors->GetNextActor(it))
        {
          actor->GetProperty()->SetDiffuseColor(40.0, 40.0, 40.0);
        }
      }
      pipeline->GetCompositePass()->SetLightCutoff(culling ? 1.0 / 512.0 : 0.0);
      renderer->SetPass(pipeline);
      window->Render();
      images[culling ? 0 : 1] = vtkFXScenes::Capture(window);
    }
    const int largest = vtkFXScenes::MaxDifference(images[0], images[1]);
    const char* names[] = { "toon bands from 0.001", "toon bands without thresholds",
      "diffuse colour 40" };
    std::cout << names[variant] << " over 64 culled lights: "
              << largest << " levels off the unculled image" << std::endl;
    FX_CHECK(largest <= 1, "culled lights cut light at tile edges");
  }

  // Spotlights against VTK's forward render: cones of 45 and of exactly 90
  // degrees (vtkOpenGLPolyDataMapper applies a cone below 90 only), the
  // second also with a dim light close to a small scene (attenuation far
  // above the largest half float, times a tiny intensity).
  for (int variant : { 0, 1, 2 })
  {
    std::vector<unsigned char> images[2];
    for (bool fx : { true, false })
    {
      window->GetRenderers()->RemoveAllItems();
      vtkNew<vtkRenderer> renderer;
      window->AddRenderer(renderer);
      renderer->AutomaticLightCreationOff();
      const double scale = variant == 2 ? 1e-3 : 1.0;
      vtkNew<vtkSphereSource> sphere;
      sphere->SetRadius(scale);
      sphere->SetThetaResolution(64);
      sphere->SetPhiResolution(64);
      vtkNew<vtkPolyDataMapper> mapper;
      mapper->SetInputConnection(sphere->GetOutputPort());
      vtkNew<vtkActor> actor;
      actor->SetMapper(mapper);
      actor->GetProperty()->SetSpecular(0.3);
      renderer->AddActor(actor);
      vtkNew<vtkLight> light;
      light->SetLightTypeToSceneLight();
      light->PositionalOn();
      light->SetConeAngle(variant == 0 ? 45.0 : 90.0);
      light->SetExponent(2.0);
      light->SetPosition(0.6 * scale, 1.5 * scale, 1.5 * scale);
      light->SetFocalPoint(0.0, 0.0, 0.0);
      if (variant == 2)
      {
        light->SetAttenuationValues(0.0, 0.0, 1.0);
        // 1 / d^2 is 1e5 to 7e5 on the sphere: lit up to about 1.1
        light->SetIntensity(1.6 * scale * scale);
      }
      renderer->AddLight(light);
      renderer->ResetCamera();
      vtkNew<vtkFXPipelinePass> pipeline;
      if (fx)
      {
        renderer->SetPass(pipeline);
      }
      window->Render();
      images[fx ? 0 : 1] = vtkFXScenes::Capture(window);
    }
    const char* names[] = { "spotlight, cone 45", "spotlight, cone 90",
      "spotlight, cone 90, scene 1e-3 (attenuation 1e6)" };
    FX_CHECK(Check(names[variant], images[0], images[1], 55.0, 2) == EXIT_SUCCESS, "");
  }

  // A positional light with all attenuation coefficients 0 (VTK: 1 / 0 =
  // inf, and a back face's specular inf x 0 = NaN) over a shiny sphere with
  // an ambient term: no pixel of the sphere is black (NaN was made 0, the
  // ambient and every other light with it).
  {
    window->GetRenderers()->RemoveAllItems();
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    renderer->AutomaticLightCreationOff();
    renderer->SetBackground(0.2, 0.3, 0.4);
    vtkNew<vtkSphereSource> sphere;
    sphere->SetThetaResolution(48);
    sphere->SetPhiResolution(48);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(sphere->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetAmbient(0.2);
    actor->GetProperty()->SetSpecular(0.5);
    renderer->AddActor(actor);
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->PositionalOn();
    light->SetConeAngle(180.0);
    light->SetPosition(2.0, 0.0, 0.0);
    light->SetFocalPoint(0.0, 0.0, 0.0);
    light->SetAttenuationValues(0.0, 0.0, 0.0);
    renderer->AddLight(light);
    renderer->ResetCamera();
    vtkNew<vtkFXPipelinePass> pipeline;
    renderer->SetPass(pipeline);
    window->Render();
    // (neither the background nor any lit point is black)
    const auto image = vtkFXScenes::Capture(window);
    int black = 0;
    for (size_t i = 0; i + 2 < image.size(); i += 3)
    {
      black += (image[i] == 0 && image[i + 1] == 0 && image[i + 2] == 0) ? 1 : 0;
    }
    std::cout << "zero attenuation: " << black << " black pixels of " << image.size() / 3
              << std::endl;
    FX_CHECK(!image.empty() && black == 0, black << " black pixels under a zero-attenuation light");
  }
  return EXIT_SUCCESS;
}
