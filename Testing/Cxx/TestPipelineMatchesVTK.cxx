// With no effect enabled, vtkFXPipelinePass (G-buffer + deferred lighting +
// VTK's translucent/volume/overlay steps) must reproduce VTK's own forward
// render at PSNR >= 40 dB, on every test scene, in perspective and parallel
// projection. Both images come from the same window in the same process.
#include "vtkFXPipelinePass.h"
#include "vtkFXScenes.h"
#include "vtkFXTestUtilities.h"

#include "vtkCamera.h"
#include "vtkRendererCollection.h"
#include "vtkRenderer.h"

#include <limits>

namespace
{
// One window serves every scene: a new X connection per scene can exhaust
// a virtual X server's clients.
double RenderAndCompare(
  vtkRenderWindow* window, const std::string& input, bool parallel, std::string& error)
{
  window->GetRenderers()->RemoveAllItems();
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  if (!vtkFXScenes::Populate(renderer, input, vtkFXScenes::Options(), error))
  {
    return -1.0;
  }
  if (parallel)
  {
    renderer->GetActiveCamera()->ParallelProjectionOn();
    renderer->ResetCamera();
  }
  window->Render();
  const auto forward = vtkFXScenes::Capture(window);

  vtkNew<vtkFXPipelinePass> pipeline;
  renderer->SetPass(pipeline);
  window->Render();
  const auto deferred = vtkFXScenes::Capture(window);
  if (pipeline->GetNumberOfPassesThatRan() < 3 ||
    std::string(pipeline->GetPassThatRan(1)) != "gbuffer")
  {
    error = "the pipeline did not run its G-buffer";
    return -1.0;
  }
  return vtkFXScenes::PSNR(forward, deferred);
}
}

int TestPipelineMatchesVTK(int argc, char* argv[])
{
  std::vector<std::string> inputs = vtkFXScenes::BuiltInSceneNames();
  const std::string data = vtkFXScenes::DataDirectory();
  inputs.push_back(data + "/stanford-bunny.obj");
  inputs.push_back(data + "/fandisk.obj");
  (void)argc;
  (void)argv;

  auto window = vtkFXTest::MakeWindow(400, 300);
  int failures = 0;
  double worst = std::numeric_limits<double>::infinity();
  for (const auto& input : inputs)
  {
    for (bool parallel : { false, true })
    {
      std::string error;
      const double psnr = RenderAndCompare(window, input, parallel, error);
      std::cout << input << (parallel ? " (parallel)" : " (perspective)") << ": PSNR " << psnr
                << " dB" << (error.empty() ? "" : " error: " + error) << std::endl;
      worst = std::min(worst, psnr);
      if (!(psnr >= 40.0))
      {
        ++failures;
      }
    }
  }
  std::cout << "worst PSNR " << worst << " dB over " << 2 * inputs.size() << " renders" << std::endl;
  FX_CHECK(failures == 0, failures << " scene(s) below 40 dB");
  return EXIT_SUCCESS;
}
