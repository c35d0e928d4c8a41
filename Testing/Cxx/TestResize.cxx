// The window changes size between frames: the G-buffer textures follow the
// viewport and the image still matches VTK's forward render. A 1x1 window
// and a renderer that covers only part of the window work too.
#include "vtkFXBloomPass.h"
#include "vtkFXGBufferPass.h"
#include "vtkFXPipelinePass.h"
#include "vtkFXScenes.h"
#include "vtkFXTestUtilities.h"

#include "vtkRenderer.h"
#include "vtkRendererCollection.h"

#include <array>

namespace
{
double PipelineVsForward(vtkRenderWindow* window, vtkRenderer* renderer, vtkFXPipelinePass* pipeline)
{
  renderer->SetPass(nullptr);
  window->Render();
  const auto forward = vtkFXScenes::Capture(window);
  renderer->SetPass(pipeline);
  window->Render();
  return vtkFXScenes::PSNR(forward, vtkFXScenes::Capture(window));
}

// The same renderer without and then with the pipeline's HDR target (for
// a bloom threshold nothing reaches); both pipelines live across frames.
struct HDRTargetComparison
{
  vtkNew<vtkFXPipelinePass> Plain;
  vtkNew<vtkFXPipelinePass> WithTarget;
  vtkNew<vtkFXBloomPass> Bloom;

  HDRTargetComparison()
  {
    this->Bloom->SetThreshold(60000.0);
    this->WithTarget->AddEffect("bloom", this->Bloom);
  }

  // The largest difference in levels; `passes`: what ran with the target.
  int Difference(vtkRenderWindow* window, vtkRenderer* renderer, std::string& passes)
  {
    renderer->SetPass(this->Plain);
    window->Render();
    const auto plain = vtkFXScenes::Capture(window);
    renderer->SetPass(this->WithTarget);
    window->Render();
    passes = vtkFXTest::Passes(this->WithTarget);
    return vtkFXScenes::MaxDifference(plain, vtkFXScenes::Capture(window));
  }
};
}

int TestResize(int, char*[])
{
  auto window = vtkFXTest::MakeWindow(300, 200);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  std::string error;
  FX_CHECK(vtkFXScenes::Populate(renderer, "scene:spheres", vtkFXScenes::Options(), error), error);
  vtkNew<vtkFXPipelinePass> pipeline;
  vtkFXGBufferPass* gbuffer = pipeline->GetGBufferPass();

  const int sizes[][2] = { { 300, 200 }, { 517, 333 }, { 120, 380 }, { 1, 1 }, { 300, 200 } };
  for (const auto& size : sizes)
  {
    window->SetSize(size[0], size[1]);
    const double psnr = PipelineVsForward(window, renderer, pipeline);
    vtkTextureObject* albedo = gbuffer->GetChannelTexture(vtkFXGBufferPass::Albedo);
    std::cout << size[0] << "x" << size[1] << ": PSNR " << psnr << " dB, albedo texture "
              << (albedo ? albedo->GetWidth() : 0) << "x" << (albedo ? albedo->GetHeight() : 0)
              << std::endl;
    FX_CHECK(albedo && static_cast<int>(albedo->GetWidth()) == size[0] &&
        static_cast<int>(albedo->GetHeight()) == size[1],
      "G-buffer follows the window size");
    FX_CHECK(static_cast<int>(gbuffer->GetDepthTexture()->GetWidth()) == size[0],
      "depth follows too");
    FX_CHECK(psnr >= 40.0, "pipeline matches VTK after resizing");
  }

  // Two renderers side by side: the pipeline renders only its viewport.
  window->SetSize(400, 200);
  renderer->SetViewport(0.0, 0.0, 0.5, 1.0);
  vtkNew<vtkRenderer> right;
  right->SetViewport(0.5, 0.0, 1.0, 1.0);
  FX_CHECK(vtkFXScenes::Populate(right, "scene:corner", vtkFXScenes::Options(), error), error);
  window->AddRenderer(right);
  vtkNew<vtkFXPipelinePass> rightPipeline;
  right->SetPass(nullptr);
  renderer->SetPass(nullptr);
  window->Render();
  const auto forward = vtkFXScenes::Capture(window);
  renderer->SetPass(pipeline);
  right->SetPass(rightPipeline);
  window->Render();
  const double psnr = vtkFXScenes::PSNR(forward, vtkFXScenes::Capture(window));
  std::cout << "two viewports: PSNR " << psnr << " dB" << std::endl;
  FX_CHECK(static_cast<int>(gbuffer->GetChannelTexture(vtkFXGBufferPass::Albedo)->GetWidth()) == 200,
    "G-buffer has the renderer's viewport size, not the window's");
  FX_CHECK(psnr >= 40.0, "side-by-side renderers match VTK");

  // The HDR target (here for a bloom threshold nothing reaches) through a
  // resize, with translucent props: VTK's translucent pass draws at the
  // size the target's framebuffer records, which must follow the window
  // (it kept the first size, and the translucent props went to the old
  // corner).
  {
    window->GetRenderers()->RemoveAllItems();
    vtkNew<vtkRenderer> translucent;
    window->AddRenderer(translucent);
    FX_CHECK(vtkFXScenes::Populate(translucent, "scene:cloud", vtkFXScenes::Options(), error), error);
    HDRTargetComparison comparison;
    for (const auto& size : { std::array<int, 2>{ 300, 200 }, std::array<int, 2>{ 600, 400 } })
    {
      window->SetSize(size[0], size[1]);
      std::string passes;
      const int largest = comparison.Difference(window, translucent, passes);
      std::cout << size[0] << "x" << size[1] << " through the HDR target with translucent props: "
                << largest << " levels off the image without it (" << passes << ")" << std::endl;
      FX_CHECK(passes.find("hdr-target") != std::string::npos, "no HDR target: " << passes);
      FX_CHECK(largest <= 2, "the HDR target after a resize");
    }
  }
  // Stencil-capable and multisampled windows: VTK's translucent pass
  // copies the depth of the HDR target into its own texture, whose format
  // it picks from the window (a packed depth-stencil when stencil-capable).
  for (const int variant : { 0, 1 })
  {
    auto special = vtkFXTest::MakeWindow(300, 200);
    if (variant == 0)
    {
      special->SetStencilCapable(1);
    }
    else
    {
      special->SetMultiSamples(4);
    }
    vtkNew<vtkRenderer> translucent;
    special->AddRenderer(translucent);
    FX_CHECK(vtkFXScenes::Populate(translucent, "scene:cloud", vtkFXScenes::Options(), error), error);
    HDRTargetComparison comparison;
    std::string passes;
    const int largest = comparison.Difference(special, translucent, passes);
    std::cout << (variant == 0 ? "stencil-capable" : "multisampled")
              << " window through the HDR target with translucent props: " << largest
              << " levels off the image without it (" << passes << ")" << std::endl;
    FX_CHECK(passes.find("hdr-target") != std::string::npos, "no HDR target: " << passes);
    FX_CHECK(largest <= 2, "the HDR target in a special window");
  }
  return EXIT_SUCCESS;
}
