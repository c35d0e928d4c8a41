// vtkfx-bench lights: frame time against the number of point lights, for
// vtkFX's deferred composite (lights culled per screen tile beyond
// vtkFXCompositePass::MaximumUniformLights) and VTK's forward render of
// the same lights (one block of shader code per light).
//
// Each scene is an INPUT (default scene:spheres) on its ground, lit only by N
// point lights over the ground (vtkFXScenes::AddPointLights: VTK's
// attenuation scaled so that each point of the ground is reached by about
// the same few lights whatever N: pi on average). Each N is rendered in a vtkFX window and
// a VTK window, frames interleaved. VTK is rendered up to --max-vtk-lights
// (default 256): its shader grows with N and its frames take seconds
// beyond. Then 1024 lights of narrower and wider ranges (0.5 to 4 grid
// spacings: 0.8 to 50 lights per ground point), vtkFX only: the frame
// follows the lights per tile. Writes DIR/lights.csv (scene, method,
// setting, ms, rmse, psnr; rmse and psnr of vtkFX against VTK where VTK
// rendered; frame_ratio, vtk_ratio, lights_per_tile; rows for every
// scene), DIR/lights.png (frame time against N), DIR/lights-per-tile.png
// (the 1024-light frames against lights per tile) and
// DIR/lights-strip.png (vtkFX at 16, 256 and 1024 lights, VTK at 256);
// with several INPUTs, the images per scene, named -TAG.
#include "vtkFXBench.h"
#include "vtkFXCompositePass.h"
#include "vtkFXPipelinePass.h"
#include "vtkFXScenes.h"

#include "vtkNew.h"
#include "vtkPlotPoints.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTimerLog.h"

#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>

namespace
{
// Light ranges in grid spacings: each point of the ground is within the
// range of pi lights on average ("a few lights per pixel").
const double Reach = 1.0;
// At 1024 lights, the ranges of the second curve: pi x reach^2 lights per
// ground point on average (0.8 to 50), to show the cost follow them.
const double ReachSweep[] = { 0.5, 1.0, 2.0, 4.0 };
}

namespace vtkFXBench
{
namespace
{
// One vtkFX frame of `n` lights of range `reach`: its median time, image
// and mean lights per tile (0 when the lights are uniforms).
struct LightsFrame
{
  double Ms = 0.0;
  double LightsPerTile = 0.0;
  std::vector<unsigned char> Image;
};

// Stages `input` with n lights of range `reach` in both windows and
// renders them interleaved: vtkFX every frame, VTK (when `withVTK`) every
// frame up to 64 lights and 3 frames beyond (its frames take seconds).
bool RenderLights(const Options& o, const std::string& input, int n, double reach, bool withVTK,
  vtkRenderWindow* fxWindow, vtkRenderWindow* vtkWindow, vtkTimerLog* timer, LightsFrame& fx,
  LightsFrame& forward)
{
  std::string error;
  double bounds[6];
  auto fxRenderer = Stage(fxWindow, input, error, bounds);
  auto vtkRenderer = Stage(vtkWindow, input, error, bounds);
  if (!fxRenderer || !vtkRenderer)
  {
    std::cerr << "vtkfx-bench: " << error << "\n";
    return false;
  }
  vtkFXScenes::AddPointLights(fxRenderer, n, bounds, reach);
  vtkFXScenes::AddPointLights(vtkRenderer, n, bounds, reach);
  vtkNew<vtkFXPipelinePass> pipeline;
  fxRenderer->SetPass(pipeline);
  fxWindow->Render(); // warm up: shaders, textures
  if (withVTK)
  {
    vtkWindow->Render();
  }
  std::vector<double> fxMs, vtkMs;
  for (int f = 0; f < o.Frames; ++f)
  {
    std::cerr << "\r" << n << " lights (reach " << reach << "): frame " << f + 1 << "/"
              << o.Frames << std::flush;
    fxMs.push_back(TimedRender(fxWindow, timer));
    if (withVTK && (f < 3 || n <= 64))
    {
      vtkMs.push_back(TimedRender(vtkWindow, timer));
    }
  }
  std::cerr << "\n";
  fx.Ms = Median(fxMs);
  fx.LightsPerTile = pipeline->GetCompositePass()->GetMeanLightsPerTile();
  fx.Image = vtkFXScenes::Capture(fxWindow);
  if (withVTK)
  {
    forward.Ms = Median(vtkMs);
    forward.Image = vtkFXScenes::Capture(vtkWindow);
  }
  return true;
}

std::string TileText(double perTile)
{
  return perTile > 0.0 ? std::to_string(perTile) + " lights per tile" : "uniform lights";
}
}

// One scene: N = 1 .. 1024 lights, then 1024 lights of wider and narrower
// ranges; rows into `csv` (extra columns: frame_ratio, the frame over the
// one-light frame; vtk_ratio, vtkFX's frame over VTK's; lights_per_tile),
// its plot and strip (named after the scene when there are several,
// `suffix`).
int BenchLightsScene(const Options& o, const std::string& input, const std::string& suffix,
  std::ofstream& csv, vtkTimerLog* timer)
{
  const int counts[] = { 1, 16, 64, 256, 1024 };
  auto fxWindow = MakeWindow(o);
  auto vtkWindow = MakeWindow(o);
  std::vector<PlotPoint> points;
  std::map<std::string, std::vector<unsigned char>> strip;
  double oneLight = 0.0;
  for (int n : counts)
  {
    const bool withVTK = n <= o.MaxVTKLights;
    LightsFrame fx, forward;
    if (!RenderLights(o, input, n, Reach, withVTK, fxWindow, vtkWindow, timer, fx, forward))
    {
      return 1;
    }
    oneLight = n == 1 ? fx.Ms : oneLight;
    std::ostringstream setting;
    setting << n << " lights";
    std::cout << std::fixed << std::setprecision(2) << input << ", " << n << " point lights: vtkFX "
              << fx.Ms << " ms (" << fx.Ms / oneLight << "x the one-light frame; "
              << TileText(fx.LightsPerTile) << ")";
    const std::string ratios = "," + std::to_string(fx.Ms / oneLight) + ",";
    if (withVTK)
    {
      const double psnr = vtkFXScenes::PSNR(forward.Image, fx.Image);
      std::cout << ", VTK " << forward.Ms << " ms (vtkFX/VTK " << fx.Ms / forward.Ms << "), PSNR "
                << psnr << " dB";
      csv << input << ",vtk-forward," << setting.str() << "," << forward.Ms << ",0,inf,"
          << forward.Ms / oneLight << ",,\n";
      csv << input << ",vtkfx-pipeline," << setting.str() << "," << fx.Ms << ","
          << RMSE(forward.Image, fx.Image) << "," << psnr << ratios << fx.Ms / forward.Ms << ","
          << fx.LightsPerTile << "\n";
      points.push_back({ 1, std::to_string(n), static_cast<double>(n), forward.Ms });
      if (n == 256)
      {
        strip["vtk256"] = forward.Image;
      }
    }
    else
    {
      std::cout << ", VTK not rendered (more than " << o.MaxVTKLights << " lights)";
      csv << input << ",vtkfx-pipeline," << setting.str() << "," << fx.Ms << ",," << ratios << ","
          << fx.LightsPerTile << "\n";
    }
    std::cout << std::endl;
    points.push_back({ 0, std::to_string(n), static_cast<double>(n), fx.Ms });
    strip["fx" + std::to_string(n)] = fx.Image;
  }
  // The same 1024 lights reaching fewer and more points: the cost follows
  // the lights per tile.
  std::vector<PlotPoint> sweep;
  for (double reach : ReachSweep)
  {
    LightsFrame fx, unused;
    if (!RenderLights(o, input, 1024, reach, false, fxWindow, vtkWindow, timer, fx, unused))
    {
      return 1;
    }
    std::ostringstream setting;
    setting << "1024 lights reach " << reach;
    std::cout << std::fixed << std::setprecision(2) << input << ", 1024 point lights of range "
              << reach << " grid spacings: vtkFX " << fx.Ms << " ms (" << fx.Ms / oneLight
              << "x the one-light frame; " << TileText(fx.LightsPerTile) << ")" << std::endl;
    csv << input << ",vtkfx-pipeline," << setting.str() << "," << fx.Ms << ",,,"
        << fx.Ms / oneLight << ",," << fx.LightsPerTile << "\n";
    std::ostringstream label;
    label << "reach " << reach;
    sweep.push_back({ 0, label.str(), fx.LightsPerTile, fx.Ms });
  }
  WritePointsPlot({ { "vtkFX (tiled deferred lights)", 200, 60, 30, vtkPlotPoints::CIRCLE },
                    { "VTK forward", 30, 80, 200, vtkPlotPoints::SQUARE } },
    points, FileTag(input) + ": frame time against point lights (" + std::to_string(o.Width) +
      "x" + std::to_string(o.Height) + ")",
    "point lights", "frame (ms)", o.Out + "/lights" + suffix + ".png");
  WritePointsPlot({ { "vtkFX, 1024 lights", 200, 60, 30, vtkPlotPoints::CIRCLE } }, sweep,
    FileTag(input) + ": 1024 point lights, frame time against lights per tile",
    "mean lights per 16x16 tile", "frame (ms)", o.Out + "/lights-per-tile" + suffix + ".png");
  std::vector<const std::vector<unsigned char>*> panels;
  for (const char* key : { "fx16", "fx256", "fx1024", "vtk256" })
  {
    if (strip.count(key))
    {
      panels.push_back(&strip[key]);
    }
  }
  WriteRGBStrip(panels, o.Width, o.Height, o.Out + "/lights-strip" + suffix + ".png");
  return 0;
}

int BenchLights(const Options& o)
{
  std::ofstream csv;
  std::string csvPath;
  if (!OpenReport(o, "lights", csv, csvPath, "frame_ratio,vtk_ratio,lights_per_tile"))
  {
    return 1;
  }
  const std::vector<std::string> inputs =
    o.Inputs.empty() ? std::vector<std::string>{ "scene:spheres" } : o.Inputs;
  vtkNew<vtkTimerLog> timer;
  for (const std::string& input : inputs)
  {
    // One scene keeps the plain names; several get theirs.
    const std::string suffix = inputs.size() > 1 ? "-" + FileTag(input) : std::string();
    if (BenchLightsScene(o, input, suffix, csv, timer) != 0)
    {
      return 1;
    }
  }
  std::cout << "wrote " << csvPath << " (" << o.Width << "x" << o.Height << ", median of up to "
            << o.Frames << " interleaved frames)\n";
  return 0;
}
}
