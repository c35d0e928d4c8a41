// The pipeline leaves out what the scene does not need (rule 3):
// - G-buffer channels follow the materials and lights of the scene,
// - no opaque prop: no G-buffer pass and no G-buffer memory,
// - translucent, volume and overlay steps run only when such props exist,
// - an effect slot adds the channels its effect reads while it is active,
// and it reports the passes that ran and the G-buffer's bytes per pixel.
#include "vtkFXEffectPass.h"
#include "vtkFXGBufferPass.h"
#include "vtkFXHDRTargetPass.h"
#include "vtkFXPipelinePass.h"
#include "vtkFXScenes.h"
#include "vtkFXTestUtilities.h"
#include "vtkFXCompositePass.h"
#include "vtkFXToonPass.h"

#include "vtkActor.h"
#include "vtkAssembly.h"
#include "vtkFXBloomPass.h"
#include "vtkActorCollection.h"
#include "vtkLight.h"
#include "vtkObjectFactory.h"
#include "vtkTextureObject.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTextActor.h"

namespace
{
using GB = vtkFXGBufferPass;

// An effect that reads linear depth and records what it saw.
class DepthProbe : public vtkFXEffectPass
{
public:
  static DepthProbe* New();
  vtkTypeMacro(DepthProbe, vtkFXEffectPass);
  unsigned int GetRequiredChannels() override { return GB::ChannelBit(GB::LinearDepth); }
  void Render(const vtkRenderState*) override
  {
    ++this->Runs;
    vtkTextureObject* depth = this->GBuffer ? this->GBuffer->GetChannelTexture(GB::LinearDepth) : nullptr;
    this->SawDepth = depth && depth->GetWidth() > 0;
  }
  int Runs = 0;
  bool SawDepth = false;
};
vtkStandardNewMacro(DepthProbe);

std::string Channels(unsigned int mask)
{
  std::string list;
  for (int c = 0; c < GB::NumberOfChannels; ++c)
  {
    if (mask & GB::ChannelBit(c))
    {
      list += (list.empty() ? "" : ",") + std::string(GB::GetChannelName(c));
    }
  }
  return list;
}
}

int TestPipelineScheduling(int, char*[])
{
  auto window = vtkFXTest::MakeWindow(200, 150);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkFXPipelinePass> pipeline;
  renderer->SetPass(pipeline);

  // Diffuse-only mesh under the light kit: normal + albedo, nothing else.
  std::string error;
  vtkFXScenes::Populate(renderer, vtkFXScenes::DataDirectory() + "/fandisk.obj",
    vtkFXScenes::Options(), error);
  window->Render();
  std::cout << "fandisk: " << vtkFXTest::Passes(pipeline) << " [" << Channels(pipeline->GetGBufferChannels())
            << "] " << pipeline->GetGBufferBytesPerPixel() << " B/px" << std::endl;
  FX_CHECK(vtkFXTest::Passes(pipeline) == "lights,gbuffer,composite", vtkFXTest::Passes(pipeline));
  FX_CHECK(Channels(pipeline->GetGBufferChannels()) == "albedo,normal",
    Channels(pipeline->GetGBufferChannels()));
  FX_CHECK(pipeline->GetGBufferBytesPerPixel() == 12, "RG16F + RGBA8 + depth32F");
  FX_CHECK(!pipeline->GetGBufferPass()->GetChannelTexture(GB::Specular), "no specular texture");

  // An effect slot: the channel it reads exists only while it runs.
  vtkNew<DepthProbe> probe;
  pipeline->AddEffect("probe", probe);
  window->Render();
  FX_CHECK(vtkFXTest::Passes(pipeline) == "lights,gbuffer,probe,composite", vtkFXTest::Passes(pipeline));
  FX_CHECK(probe->Runs == 1 && probe->SawDepth, "the effect ran and saw the depth channel");
  FX_CHECK(Channels(pipeline->GetGBufferChannels()) == "albedo,normal,depth",
    Channels(pipeline->GetGBufferChannels()));
  probe->SetStage(vtkFXEffectPass::PostProcess);
  window->Render();
  FX_CHECK(vtkFXTest::Passes(pipeline) == "lights,gbuffer,hdr-target,composite,probe", vtkFXTest::Passes(pipeline));
  FX_CHECK(pipeline->GetHDRTargetBytesPerPixel() > 0, "a post-process effect gets the HDR target");
  probe->EnabledOff();
  window->Render();
  FX_CHECK(vtkFXTest::Passes(pipeline) == "lights,gbuffer,composite", vtkFXTest::Passes(pipeline));
  FX_CHECK(Channels(pipeline->GetGBufferChannels()) == "albedo,normal",
    "a disabled effect's channel is released: " << Channels(pipeline->GetGBufferChannels()));
  FX_CHECK(probe->Runs == 2, "a disabled effect does not run");
  FX_CHECK(pipeline->GetHDRTargetBytesPerPixel() == 0 &&
      !pipeline->GetHDRTargetPass()->GetColorTexture(),
    "no post-process effect: no HDR target");
  probe->EnabledOn();
  probe->SetStage(vtkFXEffectPass::AfterGBuffer);

  // Specular and ambient terms, translucent and 2D props: all of it runs.
  renderer->RemoveAllViewProps();
  vtkFXScenes::Populate(renderer, "scene:mixed", vtkFXScenes::Options(), error);
  window->Render();
  std::cout << "mixed: " << vtkFXTest::Passes(pipeline) << " [" << Channels(pipeline->GetGBufferChannels())
            << "] " << pipeline->GetGBufferBytesPerPixel() << " B/px" << std::endl;
  FX_CHECK(vtkFXTest::Passes(pipeline) ==
      "lights,gbuffer,probe,composite,forward-opaque,translucent,overlay",
    vtkFXTest::Passes(pipeline));
  FX_CHECK(Channels(pipeline->GetGBufferChannels()) == "albedo,normal,depth,specular,ambient",
    Channels(pipeline->GetGBufferChannels()));
  FX_CHECK(pipeline->GetGBufferBytesPerPixel() == 24, "five 4-byte channels + depth");

  // Nothing the composite lights (Lighting off, PBR) under the lights:
  // albedo alone, no normal or depth for lighting.
  {
    vtkActorCollection* actors = renderer->GetActors();
    vtkCollectionSimpleIterator it;
    std::vector<std::pair<vtkProperty*, int>> changed;
    actors->InitTraversal(it);
    int k = 0;
    while (vtkActor* actor = actors->GetNextActor(it))
    {
      vtkProperty* p = actor->GetProperty();
      changed.emplace_back(p, p->GetInterpolation() + (p->GetLighting() ? 0 : 100));
      if (k++ % 2 == 0)
      {
        p->LightingOff();
      }
      else
      {
        p->SetInterpolationToPBR();
      }
    }
    pipeline->RemoveEffect("probe");
    window->Render();
    std::cout << "unlit and PBR: [" << Channels(pipeline->GetGBufferChannels()) << "]"
              << std::endl;
    FX_CHECK(Channels(pipeline->GetGBufferChannels()) == "albedo",
      "channels nobody reads: " << Channels(pipeline->GetGBufferChannels()));
    // An effect that reads normals (toon bands) there, under a positional
    // light: the composite lights at the renderer's complexity wherever a
    // normal channel exists, and gets the depth positional lights need
    // (without it, it drew no opaque prop). Nothing it lights, so the
    // frame is the one without the effect.
    vtkNew<vtkLight> lamp;
    lamp->SetPositional(true);
    lamp->SetPosition(0.0, 3.0, 3.0);
    renderer->AddLight(lamp);
    window->Render();
    const auto withoutBands = vtkFXScenes::Capture(window);
    vtkNew<vtkFXToonPass> bands;
    bands->FeatureLinesOff();
    pipeline->AddEffect("bands", bands);
    vtkFXTest::EventCounter compositeErrors(pipeline->GetCompositePass());
    window->Render();
    const int bandsDifference =
      vtkFXScenes::MaxDifference(withoutBands, vtkFXScenes::Capture(window));
    std::cout << "unlit and PBR, toon bands, a positional light: ["
              << Channels(pipeline->GetGBufferChannels()) << "], " << compositeErrors.Count
              << " composite error(s), " << bandsDifference << " levels off the frame without bands"
              << std::endl;
    FX_CHECK(compositeErrors.Count == 0 && bandsDifference == 0,
      "normals without lit props under a positional light: " << compositeErrors.Last);
    FX_CHECK(Channels(pipeline->GetGBufferChannels()) == "albedo,normal,depth",
      "the material channels no lit pixel reads: " << Channels(pipeline->GetGBufferChannels()));
    pipeline->RemoveEffect("bands");
    renderer->RemoveLight(lamp);
    for (auto& c : changed)
    {
      c.first->SetLighting(c.second < 100);
      c.first->SetInterpolation(c.second % 100);
    }
    pipeline->AddEffect("probe", probe);
    window->Render();
    FX_CHECK(Channels(pipeline->GetGBufferChannels()) == "albedo,normal,depth,specular,ambient",
      "lit again: " << Channels(pipeline->GetGBufferChannels()));
  }

  // A debug view allocates the channel it shows.
  pipeline->SetDebugChannel(GB::Emission);
  window->Render();
  FX_CHECK(pipeline->GetGBufferChannels() & GB::ChannelBit(GB::Emission), "emission shown");
  pipeline->SetDebugChannel(-1);
  window->Render();
  FX_CHECK(!(pipeline->GetGBufferChannels() & GB::ChannelBit(GB::Emission)),
    "emission released when nobody reads it");

  // Only translucent geometry: no G-buffer pass and no G-buffer memory.
  renderer->RemoveAllViewProps();
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> glass;
  glass->SetMapper(mapper);
  glass->GetProperty()->SetOpacity(0.5);
  renderer->AddActor(glass);
  renderer->ResetCamera();
  window->Render();
  std::cout << "translucent only: " << vtkFXTest::Passes(pipeline) << ", "
            << pipeline->GetGBufferBytesPerPixel() << " B/px" << std::endl;
  const int runs = probe->Runs;
  FX_CHECK(vtkFXTest::Passes(pipeline) == "lights,translucent", vtkFXTest::Passes(pipeline));
  FX_CHECK(probe->Runs == runs, "effects that read the G-buffer do not run without it");
  FX_CHECK(pipeline->GetGBufferBytesPerPixel() == 0, "no G-buffer");
  FX_CHECK(!pipeline->GetGBufferPass()->GetDepthTexture() &&
      !pipeline->GetGBufferPass()->GetChannelTexture(GB::Albedo),
    "G-buffer textures released");

  // 2D props only: VTK's opaque step for them (text builds its texture
  // there) and the overlay, but no G-buffer.
  renderer->RemoveAllViewProps();
  vtkNew<vtkTextActor> text;
  text->SetInput("2D only");
  renderer->AddViewProp(text);
  window->Render();
  FX_CHECK(vtkFXTest::Passes(pipeline) == "lights,forward-opaque,overlay", vtkFXTest::Passes(pipeline));
  FX_CHECK(pipeline->GetGBufferBytesPerPixel() == 0, "no G-buffer for 2D props");

  // A scalar bar next to a diffuse mesh does not add material channels.
  vtkFXScenes::Populate(renderer, vtkFXScenes::DataDirectory() + "/fandisk.obj",
    vtkFXScenes::Options(), error);
  window->Render();
  FX_CHECK(Channels(pipeline->GetGBufferChannels()) == "albedo,normal,depth",
    "2D props leave the channels alone: " << Channels(pipeline->GetGBufferChannels()));

  // An assembly's hidden parts ask for nothing: an unlit one (emissive:
  // glow) and one forced opaque at opacity 0.5 (drawn forward, and with it
  // the whole assembly) beside a visible lit sphere. Before, the glow ran
  // and the emission channel was allocated for nothing on screen. Nor does
  // an empty placeholder actor (no mapper: it draws nothing).
  {
    renderer->RemoveAllViewProps();
    vtkNew<vtkAssembly> assembly;
    vtkNew<vtkActor> placeholder;
    assembly->AddPart(placeholder);
    for (int part = 0; part < 3; ++part)
    {
      vtkNew<vtkActor> actor;
      actor->SetMapper(mapper);
      actor->SetPosition(1.5 * part, 0.0, 0.0);
      actor->SetVisibility(part == 0);
      if (part == 1)
      {
        actor->GetProperty()->LightingOff();
      }
      else if (part == 2)
      {
        actor->GetProperty()->SetOpacity(0.5);
        actor->ForceOpaqueOn();
      }
      assembly->AddPart(actor);
    }
    renderer->AddActor(assembly);
    renderer->ResetCamera();
    vtkNew<vtkFXBloomPass> bloom;
    pipeline->AddEffect("bloom", bloom);
    window->Render();
    const std::string passes = vtkFXTest::Passes(pipeline);
    std::cout << "assembly with hidden parts: " << passes << " ["
              << Channels(pipeline->GetGBufferChannels()) << "]" << std::endl;
    FX_CHECK(passes.find("bloom") == std::string::npos &&
        passes.find("forward-opaque") == std::string::npos && passes.find("gbuffer") != std::string::npos,
      passes);
    FX_CHECK(!(pipeline->GetGBufferChannels() & GB::ChannelBit(GB::Emission)),
      "an emission channel for a hidden part");
    pipeline->RemoveEffect("bloom");
  }

  // An empty renderer: only the lights.
  renderer->RemoveAllViewProps();
  window->Render();
  FX_CHECK(vtkFXTest::Passes(pipeline) == "lights", vtkFXTest::Passes(pipeline));
  pipeline->RemoveEffect("probe");
  FX_CHECK(pipeline->GetNumberOfEffects() == 0, "effect removed");
  return EXIT_SUCCESS;
}
