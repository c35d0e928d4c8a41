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
// beyond. Writes DIR/lights.csv (scene, method, setting, ms, rmse, psnr;
// rmse and psnr of vtkFX against VTK where VTK rendered; rows for every
// scene), DIR/lights.png (frame time against N) and DIR/lights-strip.png
// (vtkFX at 16, 256 and 1024 lights, VTK at 256); with several INPUTs,
// lights-TAG.png and lights-strip-TAG.png per scene.
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
}

namespace vtkFXBench
{
// One scene: N = 1 .. 1024 lights, rows into `csv`, its plot and strip
// (named after the scene when there are several, `suffix`).
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
    std::string error;
    double bounds[6];
    auto fx = Stage(fxWindow, input, error, bounds);
    auto forward = Stage(vtkWindow, input, error, bounds);
    if (!fx || !forward)
    {
      std::cerr << "vtkfx-bench: " << error << "\n";
      return 1;
    }
    vtkFXScenes::AddPointLights(fx, n, bounds, Reach);
    vtkFXScenes::AddPointLights(forward, n, bounds, Reach);
    vtkNew<vtkFXPipelinePass> pipeline;
    fx->SetPass(pipeline);
    const bool withVTK = n <= o.MaxVTKLights;
    fxWindow->Render(); // warm up: shaders, textures
    if (withVTK)
    {
      vtkWindow->Render();
    }
    std::vector<double> fxMs, vtkMs;
    for (int f = 0; f < o.Frames; ++f)
    {
      std::cerr << "\r" << n << " lights: frame " << f + 1 << "/" << o.Frames << std::flush;
      fxMs.push_back(TimedRender(fxWindow, timer));
      if (withVTK && (f < 3 || n <= 64)) // VTK's frames with hundreds of lights take seconds
      {
        vtkMs.push_back(TimedRender(vtkWindow, timer));
      }
    }
    std::cerr << "\n";
    const double fxMedian = Median(fxMs);
    oneLight = n == 1 ? fxMedian : oneLight;
    const auto image = vtkFXScenes::Capture(fxWindow);
    const double perTile = pipeline->GetCompositePass()->GetMeanLightsPerTile();
    std::ostringstream setting;
    setting << n << " lights";
    std::cout << std::fixed << std::setprecision(2) << input << ", " << n << " point lights: vtkFX "
              << fxMedian << " ms (" << fxMedian / oneLight << "x the one-light frame; "
              << (perTile > 0.0 ? std::to_string(perTile) + " lights per tile" : "uniform lights")
              << ")";
    if (withVTK)
    {
      const auto reference = vtkFXScenes::Capture(vtkWindow);
      const double vtk = Median(vtkMs);
      const double psnr = vtkFXScenes::PSNR(reference, image);
      std::cout << ", VTK " << vtk << " ms (vtkFX/VTK " << fxMedian / vtk << "), PSNR " << psnr
                << " dB";
      csv << input << ",vtk-forward," << setting.str() << "," << vtk << ",0,inf\n";
      csv << input << ",vtkfx-pipeline," << setting.str() << "," << fxMedian << ","
          << RMSE(reference, image) << "," << psnr << "\n";
      points.push_back({ 1, std::to_string(n), static_cast<double>(n), vtk });
      if (n == 256)
      {
        strip["vtk256"] = reference;
      }
    }
    else
    {
      std::cout << ", VTK not rendered (more than " << o.MaxVTKLights << " lights)";
      csv << input << ",vtkfx-pipeline," << setting.str() << "," << fxMedian << ",,\n";
    }
    std::cout << std::endl;
    points.push_back({ 0, std::to_string(n), static_cast<double>(n), fxMedian });
    strip["fx" + std::to_string(n)] = image;
  }
  WritePointsPlot({ { "vtkFX (tiled deferred lights)", 200, 60, 30, vtkPlotPoints::CIRCLE },
                    { "VTK forward", 30, 80, 200, vtkPlotPoints::SQUARE } },
    points, FileTag(input) + ": frame time against point lights (" + std::to_string(o.Width) +
      "x" + std::to_string(o.Height) + ")",
    "point lights", "frame (ms)", o.Out + "/lights" + suffix + ".png");
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
  if (!OpenReport(o, "lights", csv, csvPath))
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
