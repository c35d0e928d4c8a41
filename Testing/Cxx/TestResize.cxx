// The window changes size between frames: the G-buffer textures follow the
// viewport and the image still matches VTK's forward render. A 1x1 window
// and a renderer that covers only part of the window work too. A
// screenshot drawn tile by tile makes the occlusion and the glow warn
// once each.
#include "vtkFXBloomPass.h"
#include "vtkFXCompositePass.h"
#include "vtkFXGBufferPass.h"
#include "vtkFXPipelinePass.h"
#include "vtkFXSSAOPass.h"
#include "vtkFXScenes.h"
#include "vtkFXTestUtilities.h"

#include "vtkFXOpenGL.h"
#include "vtkRenderWindow.h"
#include "vtkTextureObject.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkWindowToImageFilter.h"

#include <array>
#include <functional>

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
    // (FXAA, which a multisampled window otherwise gets, would turn the
    // level or two between the two images into edge decisions: 16 levels)
    this->Plain->MultisampleFXAAOff();
    this->WithTarget->MultisampleFXAAOff();
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

// Two windows with a pipeline each: releasing one's pipeline while the
// other's context is current (an application closing one view of
// several) frees that pipeline's own textures, not the other's, whose next
// frame is the same image. (Without the release pushing its window's
// context, GL deleted the current window's names.)
// Two windows, each with a renderer and a pipeline with ambient occlusion
// (held by the renderer), rendered once.
struct TwoWindows
{
  vtkSmartPointer<vtkRenderWindow> Windows[2];
  vtkSmartPointer<vtkRenderer> Renderers[2];
  vtkFXPipelinePass* Pipelines[2] = { nullptr, nullptr };
};

bool MakeTwoWindows(TwoWindows& two)
{
  for (int i = 0; i < 2; ++i)
  {
    two.Windows[i] = vtkFXTest::MakeWindow(300, 200);
    two.Renderers[i] = vtkSmartPointer<vtkRenderer>::New();
    two.Windows[i]->AddRenderer(two.Renderers[i]);
    std::string error;
    if (!vtkFXScenes::Populate(two.Renderers[i], i == 0 ? "scene:spheres" : "scene:corner",
          vtkFXScenes::Options(), error))
    {
      std::cerr << error << std::endl;
      return false;
    }
    vtkNew<vtkFXPipelinePass> pipeline;
    pipeline->AmbientOcclusionOn();
    two.Renderers[i]->SetPass(pipeline);
    two.Pipelines[i] = pipeline;
    two.Windows[i]->Render();
  }
  return true;
}

// What each of the first 512 names is in the current context (vertex array,
// buffer, texture, query, framebuffer, program, sampler: a bit each). Two
// contexts number their objects from 1, so the names of two windows'
// pipelines overlap.
std::vector<int> LiveNames()
{
  std::vector<int> alive;
  for (GLuint name = 1; name <= 512; ++name)
  {
    alive.push_back((glIsVertexArray(name) ? 1 : 0) + (glIsBuffer(name) ? 2 : 0) +
      (glIsTexture(name) ? 4 : 0) + (glIsQuery(name) ? 8 : 0) + (glIsFramebuffer(name) ? 16 : 0) +
      (glIsProgram(name) ? 32 : 0) + (glIsSampler(name) ? 64 : 0));
  }
  return alive;
}

int ChangedNames(const std::vector<int>& before, const std::vector<int>& after)
{
  int changed = 0;
  for (size_t i = 0; i < before.size() && i < after.size(); ++i)
  {
    changed += before[i] != after[i] ? 1 : 0;
  }
  return changed;
}

int CheckReleaseFromAnotherWindow()
{
  TwoWindows two;
  FX_CHECK(MakeTwoWindows(two), "no scene");
  vtkSmartPointer<vtkRenderWindow>* windows = two.Windows;
  vtkFXPipelinePass* const* pipelines = two.Pipelines;
  const auto before = vtkFXScenes::Capture(windows[0]);
  windows[0]->MakeCurrent();
  while (glGetError() != GL_NO_ERROR)
  {
  }
  pipelines[1]->ReleaseGraphicsResources(windows[1]);
  // (both contexts number their textures from 1: the names overlap)
  vtkTextureObject* albedo =
    pipelines[0]->GetGBufferPass()->GetChannelTexture(vtkFXGBufferPass::Albedo);
  FX_CHECK(windows[0]->IsCurrent(), "the release left another window's context current");
  const bool kept = albedo && glIsTexture(albedo->GetHandle()) == GL_TRUE;
  // (the composite warns of a GL error left pending by the steps before it)
  vtkFXTest::EventCounter warnings(pipelines[0]->GetCompositePass(), vtkCommand::WarningEvent);
  windows[0]->Render();
  const GLenum glError = glGetError();
  const int largest = vtkFXScenes::MaxDifference(before, vtkFXScenes::Capture(windows[0]));
  windows[1]->Render(); // the released pipeline makes its resources again
  std::cout << "a pipeline released from another window's context: the other window's "
            << (kept ? "textures are kept" : "G-BUFFER TEXTURE WAS DELETED") << ", its next frame "
            << largest << " levels off its last, GL error " << glError << ", " << warnings.Count
            << " warnings" << std::endl;
  FX_CHECK(kept && glError == GL_NO_ERROR && warnings.Count == 0 && largest == 0,
    "releasing one window's pipeline touched another window's resources");
  return EXIT_SUCCESS;
}

// What `action` does to window 1's pipeline, with window 0's context
// current, leaves window 0 alone: its context stays current, none of its
// first 512 GL names changes, and its next frame is the same image without
// a GL error or a warning. `what` names the action in the output.
int CheckOtherWindowUntouched(TwoWindows& two, const std::function<void()>& action, const std::string& what)
{
  vtkRenderWindow* window = two.Windows[0];
  const auto before = vtkFXScenes::Capture(window);
  window->MakeCurrent();
  while (glGetError() != GL_NO_ERROR)
  {
  }
  const std::vector<int> namesBefore = LiveNames();
  action();
  FX_CHECK(window->IsCurrent(), what << " left another window's context current");
  const int lost = ChangedNames(namesBefore, LiveNames());
  vtkFXTest::EventCounter warnings(two.Pipelines[0]->GetCompositePass(), vtkCommand::WarningEvent);
  window->Render();
  const GLenum glError = glGetError();
  const int largest = vtkFXScenes::MaxDifference(before, vtkFXScenes::Capture(window));
  std::cout << what << " while another window is current: " << lost
            << " of the other window's first 512 names changed, its next frame " << largest
            << " levels off its last, GL error " << glError << ", " << warnings.Count
            << " warnings" << std::endl;
  FX_CHECK(lost == 0, what << ": " << lost << " of the other window's GL names deleted");
  FX_CHECK(glError == GL_NO_ERROR && warnings.Count == 0 && largest == 0,
    what << " touched another window's resources");
  return EXIT_SUCCESS;
}

// The same when the pipeline is deleted instead, without a release first
// (an application replacing a renderer's pass, or dropping a view, while
// another window is current): its destructor frees its GL objects in its
// own window's context, and none of the other window's names (vertex
// arrays, buffers, textures, queries, framebuffers, programs, samplers)
// goes. (Without it, its timer queries, which VTK deletes in its
// destructors in whichever context is current, took 8 of the other
// window's names, and its next frame warned of a GL error.)
int CheckDeleteFromAnotherWindow()
{
  TwoWindows two;
  FX_CHECK(MakeTwoWindows(two), "no scene");
  // (its last reference: deleted)
  return CheckOtherWindowUntouched(
    two, [&two] { two.Renderers[1]->SetPass(nullptr); }, "a pipeline deleted");
}

// The same when an effect leaves a pipeline between frames while another
// window's context is current (an application's control turning ambient
// occlusion off in one view of several): the effect frees its objects in
// its own window's context, and the other window's next frame is the same.
int CheckRemoveEffectFromAnotherWindow()
{
  TwoWindows two;
  FX_CHECK(MakeTwoWindows(two), "no scene");
  return CheckOtherWindowUntouched(two, [&two] { two.Pipelines[1]->AmbientOcclusionOff(); },
    "ambient occlusion removed from a pipeline");
}

// A screenshot scaled by vtkWindowToImageFilter is drawn tile by tile:
// the occlusion and the glow, which read beyond a pixel, warn (once each)
// that they leave seams; a plain frame does not.
int CheckTiledScreenshotWarns()
{
  auto window = vtkFXTest::MakeWindow(200, 150);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  std::string error;
  FX_CHECK(vtkFXScenes::Populate(renderer, "scene:glow", vtkFXScenes::Options(), error), error);
  vtkNew<vtkFXPipelinePass> pipeline;
  FX_CHECK(vtkFXTest::AddEffect(pipeline, "ao") && vtkFXTest::AddEffect(pipeline, "bloom"),
    "effects added");
  renderer->SetPass(pipeline);
  vtkFXTest::EventCounter occlusionWarnings(pipeline->GetSSAOPass(), vtkCommand::WarningEvent);
  vtkFXTest::EventCounter glowWarnings(pipeline->GetEffect("bloom"), vtkCommand::WarningEvent);
  window->Render();
  const int plain[2] = { occlusionWarnings.Count, glowWarnings.Count };
  for (int i = 0; i < 2; ++i)
  {
    vtkNew<vtkWindowToImageFilter> screenshot;
    screenshot->SetInput(window);
    screenshot->SetScale(2);
    screenshot->ReadFrontBufferOff();
    screenshot->Update();
  }
  std::cout << "a screenshot scaled by 2, twice: " << occlusionWarnings.Count
            << " occlusion and " << glowWarnings.Count << " glow warning(s) (plain frame: "
            << plain[0] << ", " << plain[1] << "): " << occlusionWarnings.Last << std::endl;
  FX_CHECK(plain[0] == 0 && plain[1] == 0, "a plain frame warns");
  FX_CHECK(occlusionWarnings.Count == 1 && glowWarnings.Count == 1,
    "the tiles' seams are said once for each effect");
  return EXIT_SUCCESS;
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
  FX_CHECK(CheckTiledScreenshotWarns() == EXIT_SUCCESS, "");
  FX_CHECK(CheckReleaseFromAnotherWindow() == EXIT_SUCCESS, "");
  FX_CHECK(CheckDeleteFromAnotherWindow() == EXIT_SUCCESS, "");
  FX_CHECK(CheckRemoveEffectFromAnotherWindow() == EXIT_SUCCESS, "");
  return EXIT_SUCCESS;
}
