#include "vtkFXBench.h"

#include "vtkFXScenes.h"

#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkTimerLog.h"

#include <algorithm>
#include <cmath>

namespace vtkFXBench
{
double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n == 0 ? -1.0 : (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
}

double RMSE(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b)
{
  double sum = 0.0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i)
  {
    const double d = (static_cast<double>(a[i]) - b[i]) / 255.0;
    sum += d * d;
  }
  return a.empty() ? 0.0 : std::sqrt(sum / a.size());
}

double TimedRender(vtkRenderWindow* window, vtkTimerLog* timer)
{
  timer->StartTimer();
  window->Render();
  window->WaitForCompletion();
  timer->StopTimer();
  return 1000.0 * timer->GetElapsedTime();
}

vtkSmartPointer<vtkRenderWindow> MakeWindow(const Options& o)
{
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(o.Width, o.Height);
  return window;
}

vtkSmartPointer<vtkRenderer> Stage(
  vtkRenderWindow* window, const std::string& input, std::string& error, double dataBounds[6])
{
  window->GetRenderers()->RemoveAllItems();
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  window->AddRenderer(renderer);
  return vtkFXScenes::Populate(renderer, input, vtkFXScenes::Options(), error, dataBounds)
    ? renderer
    : nullptr;
}
}
