// vtkFXBench: what the benchmarks of vtkfx-bench share (options, timing,
// windows, error metrics).
#ifndef vtkFXBench_h
#define vtkFXBench_h

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

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
};

double Median(std::vector<double> v);

// Root-mean-square difference of two byte images, in [0,1] units.
double RMSE(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b);

// Wall-clock milliseconds of one finished frame.
double TimedRender(vtkRenderWindow* window, vtkTimerLog* timer);

// An offscreen window without multisampling, of the options' size.
vtkSmartPointer<vtkRenderWindow> MakeWindow(const Options& o);

// A fresh renderer holding `input` in `window` (windows are reused across
// scenes: each one is an X connection). nullptr on failure, with `error`.
vtkSmartPointer<vtkRenderer> Stage(vtkRenderWindow* window, const std::string& input,
  std::string& error, double dataBounds[6] = nullptr);

// The "ao" benchmark (vtkFXBenchAO.cxx).
int BenchAO(const Options& o);
}

#endif
