// vtkFXBench: what the benchmarks of vtkfx-bench share (options, timing,
// windows, error metrics).
#ifndef vtkFXBench_h
#define vtkFXBench_h

#include "vtkSmartPointer.h"

#include <fstream>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

class vtkImageData;
class vtkTextureObject;
class vtkRenderWindow;
class vtkRenderer;
class vtkTimerLog;

namespace vtkFXBench
{
struct Options
{
  std::string Effect;
  std::vector<std::string> Inputs;
  int Width = 1280;
  int Height = 720;
  bool SizeGiven = false;
  int Frames = 15;
  std::string Out;
  int Falloff = 0; // ao: vtkFXSSAOPass::Falloff (0 Binary, 1 CubeRoot)
  int MaxVTKLights = 256; // lights: most lights VTK's forward render is timed with
};

double Median(std::vector<double> v);

// The median of the frame-by-frame ratios a[i] / b[i] of two series timed
// in turn (interleaved): a slow spell of the machine slows both frames of a
// pair, so it moves this less than it moves the ratio of the two medians.
// -1 without pairs.
double PairedRatio(const std::vector<double>& a, const std::vector<double>& b);

// Opens DIR/<name>.csv with the shared report's header (scene, method,
// setting, ms, rmse, psnr, then `extraColumns`, comma-separated); false,
// with a message, when it cannot.
bool OpenReport(const Options& o, const std::string& name, std::ofstream& csv, std::string& path,
  const std::string& extraColumns = std::string());

// Root-mean-square difference of two byte images, in [0,1] units.
double RMSE(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b);

// A float texture read back, `components` values per texel, rows bottom-up
// (empty when there is none).
std::vector<float> Download(vtkRenderWindow* window, vtkTextureObject* texture, int components);

// Wall-clock milliseconds of one finished frame.
double TimedRender(vtkRenderWindow* window, vtkTimerLog* timer);

// Times `frames` frames of every method's window, the methods in turn
// within each frame (so that a slow stretch of the machine falls on all of
// them alike), appending to each method's FrameMs; progress goes to stderr
// as "<label>: frame f/frames". `beforeFrame`, when given, runs before
// each method's frame, outside the timing (e.g. to move the camera).
template <typename Method>
void TimeFramesInTurn(std::vector<Method>& methods, int frames, const std::string& label,
  vtkTimerLog* timer,
  const std::function<void(typename std::vector<Method>::value_type&)>& beforeFrame = nullptr)
{
  for (int f = 0; f < frames; ++f)
  {
    std::cerr << "\r" << label << ": frame " << f + 1 << "/" << frames << std::flush;
    for (auto& m : methods)
    {
      if (beforeFrame)
      {
        beforeFrame(m);
      }
      m.FrameMs.push_back(TimedRender(m.Window, timer));
    }
  }
  std::cerr << "\n";
}

// An offscreen window without multisampling, of the options' size.
vtkSmartPointer<vtkRenderWindow> MakeWindow(const Options& o);

// A fresh renderer holding `input` in `window` (windows are reused across
// scenes: each one is an X connection). nullptr on failure, with `error`.
vtkSmartPointer<vtkRenderer> Stage(vtkRenderWindow* window, const std::string& input,
  std::string& error, double dataBounds[6] = nullptr);

// Scatter plots of error against time: points in families (one colour
// and marker each, in the legend), each point labelled with its setting.
struct PlotFamily
{
  std::string Name;
  unsigned char R, G, B;
  int Marker; // vtkPlotPoints marker style
};
struct PlotPoint
{
  int Family; // index into the families
  std::string Label;
  double X, Y;
};
void WritePointsPlot(const std::vector<PlotFamily>& families, const std::vector<PlotPoint>& points,
  const std::string& title, const std::string& xTitle, const std::string& yTitle,
  const std::string& path);

// Curves y(x) on one chart, one colour each, named in the legend.
struct PlotLine
{
  std::string Name;
  unsigned char R, G, B;
  std::vector<double> X, Y;
};
void WriteLinePlot(const std::vector<PlotLine>& lines, const std::string& title,
  const std::string& xTitle, const std::string& yTitle, const std::string& path);

void WritePNG(vtkImageData* image, const std::string& path);

// A name for files about `input`: "bunny" for ".../bunny.obj", "glow" for
// "scene:glow".
std::string FileTag(const std::string& input);

// RGB byte images (bottom row first) of one size, side by side.
void WriteRGBStrip(const std::vector<const std::vector<unsigned char>*>& images, int width,
  int height, const std::string& path);

// The "ao" benchmark (vtkFXBenchAO.cxx).
int BenchAO(const Options& o);

// The "bloom" benchmark (vtkFXBenchBloom.cxx).
int BenchBloom(const Options& o);

// The "lights" benchmark (vtkFXBenchLights.cxx).
int BenchLights(const Options& o);

// The "avsm" benchmark (vtkFXBenchAVSM.cxx).
int BenchAVSM(const Options& o);
}

#endif
