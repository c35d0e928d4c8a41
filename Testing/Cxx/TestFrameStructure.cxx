// The frame structure of vtkFXPipelinePass, with probe effects:
// - one probe per stage runs where the stage says (light-space also without
//   opaque props; composite-stage effects add code only, no pass);
// - named inputs order the effects whatever order they were added in; a
//   missing effect or output, an input from a later stage and a cycle are
//   reported (once) and keep the effects concerned out; a producer without
//   work keeps its consumer out silently; an optional input may stay open;
// - each composite hook changes the lit colour as its code says, with '@'
//   made unique per effect, on the uniform and on the light-texture path;
// - more lights than VTK's per-light uniforms serve still match VTK;
// - layered renderers that preserve depth (and colour) match VTK, with and
//   without the HDR target;
// - emission above 1 is kept in a float channel and survives, through the
//   HDR target, a post-process that halves the image.
#include "vtkFXAVSMPass.h"
#include "vtkFXBilateralBlurPass.h"
#include "vtkFXBloomPass.h"
#include "vtkFXCompositePass.h"
#include "vtkFXEffectPass.h"
#include "vtkFXGBufferPass.h"
#include "vtkFXHDRTargetPass.h"
#include "vtkFXPipelinePass.h"
#include "vtkFXRenderUtilities.h"
#include "vtkFXScenes.h"
#include "vtkFXTestUtilities.h"

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkStringOutputWindow.h"
#include "vtkOutputWindow.h"
#include "vtkRendererCollection.h"
#include "vtkShaderProgram.h"
#include "vtkSphereSource.h"
#include "vtkTextureObject.h"
#include "vtkFXOpenGL.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

namespace
{
using GB = vtkFXGBufferPass;
std::vector<std::string> RunLog; // names of the probes, in the order they rendered

// One window serves every part of the test: a new X connection per window
// can exhaust a virtual X server's clients. Each part gets it cleared.
vtkRenderWindow* SharedWindow = nullptr;
vtkSmartPointer<vtkRenderWindow> FreshWindow(int width, int height)
{
  SharedWindow->GetRenderers()->RemoveAllItems();
  SharedWindow->SetNumberOfLayers(1);
  SharedWindow->SetSize(width, height);
  return SharedWindow;
}

// An effect with an output "out" and an input "in" (optional for a Probe,
// required for a Consumer), unconnected until a test connects it. It
// renders nothing; it logs that it ran.
class Probe : public vtkFXEffectPass
{
public:
  static Probe* New();
  vtkTypeMacro(Probe, vtkFXEffectPass);
  Probe() : Probe(true) {}
  explicit Probe(bool optional)
  {
    this->DeclareInput("in", optional, false);
    this->DeclareOutput("out");
  }
  unsigned int GetRequiredChannels() override { return 0; }
  bool HasWork(const vtkFXSceneInfo& scene) override
  {
    return this->NeedsTranslucent ? !scene.TranslucentProps.empty() && !scene.Lights.empty()
                                  : !scene.OpaqueProps.empty();
  }
  Output GetOutput(const char* name) override
  {
    Output output;
    if (std::string(name) == "out" && this->Ran)
    {
      output.Components = 1;
      output.Step = 1;
    }
    return output;
  }
  void Render(const vtkRenderState*) override
  {
    RunLog.push_back(this->Label);
    this->Ran = true;
  }
  std::string Label;
  bool NeedsTranslucent = false;
  bool Ran = false;
};
vtkStandardNewMacro(Probe);

class Consumer : public Probe
{
public:
  static Consumer* New();
  vtkTypeMacro(Consumer, Probe);
  Consumer() : Probe(false) {}
};
vtkStandardNewMacro(Consumer);

// An effect made of composite code only; `@gain` is a uniform it binds.
class HookProbe : public vtkFXEffectPass
{
public:
  static HookProbe* New();
  vtkTypeMacro(HookProbe, vtkFXEffectPass);
  HookProbe() { this->Stage = Composite; }
  unsigned int GetRequiredChannels() override { return this->Channels; }
  void Render(const vtkRenderState*) override {} // composite-stage: never called
  std::string GetCompositeCode(int hook) override { return this->Code[hook]; }
  void BindCompositeResources(vtkShaderProgram* program, const std::string& prefix) override
  {
    const std::string gain = prefix + "gain";
    if (program->IsUniformUsed(gain.c_str()))
    {
      program->SetUniformf(gain.c_str(), this->Gain);
    }
  }
  std::string Code[NumberOfCompositeHooks];
  float Gain = 1.0f;
  unsigned int Channels = 0; // the G-buffer channels it asks for
};
vtkStandardNewMacro(HookProbe);

// A post-process that multiplies the image by 0.5 (blending), so values
// above 1 in an HDR target come out at or above 0.5 after the halving.
class HalveProbe : public vtkFXEffectPass
{
public:
  static HalveProbe* New();
  vtkTypeMacro(HalveProbe, vtkFXEffectPass);
  HalveProbe() { this->Stage = PostProcess; }
  unsigned int GetRequiredChannels() override { return 0; }
  bool HasWork(const vtkFXSceneInfo&) override { return true; }
  void Render(const vtkRenderState* s) override
  {
    RunLog.push_back("halve");
    this->SawFrameBuffer = s->GetFrameBuffer() != nullptr;
    auto* window = vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow());
    // Halving, or (WriteNaN) NaN computed at run time, replacing the image.
    const std::string fs = this->WriteNaN
      ? "//VTK::System::Dec\nin vec2 texCoord;\n//VTK::Output::Dec\n"
        "void main() { float z = texCoord.x < -1.0 ? 1.0 : 0.0; gl_FragData[0] = vec4(z / z); }\n"
      : "//VTK::System::Dec\nin vec2 texCoord;\n//VTK::Output::Dec\n"
        "void main() { gl_FragData[0] = vec4(texCoord.x < -1.0 ? 1.0 : 0.5); }\n";
    vtkShaderProgram* program = vtkFXRenderUtilities::ReadyQuad(this->Quad, window, fs);
    if (!program)
    {
      return;
    }
    vtkOpenGLState* state = window->GetState();
    vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable depth(state, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglBlendFuncSeparate func(state);
    if (this->WriteNaN)
    {
      state->vtkglDisable(GL_BLEND);
    }
    else
    {
      state->vtkglEnable(GL_BLEND);
    }
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglBlendFuncSeparate(GL_ZERO, GL_SRC_COLOR, GL_ZERO, GL_ONE);
    this->Quad.Helper->Render();
  }
  void ReleaseGraphicsResources(vtkWindow* w) override
  {
    vtkFXRenderUtilities::ReleaseQuad(this->Quad, w);
  }
  bool SawFrameBuffer = false;
  bool WriteNaN = false;
  vtkFXRenderUtilities::FullScreenQuad Quad;
};
vtkStandardNewMacro(HalveProbe);

std::string Log()
{
  std::string list;
  for (const auto& name : RunLog)
  {
    list += (list.empty() ? "" : ",") + name;
  }
  return list;
}

bool Contains(const std::string& s, const char* what)
{
  return s.find(what) != std::string::npos;
}

vtkSmartPointer<vtkActor> MakeActor(vtkPolyDataAlgorithm* source, double r, double g, double b)
{
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  return actor;
}

// A plane facing a parallel camera that it fills, lit by a headlight
// (diffuse = albedo exactly): every pixel shows the same colour.
struct FlatScene
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkFXPipelinePass> Pipeline;
  vtkNew<vtkPlaneSource> Plane;
  vtkSmartPointer<vtkActor> Actor;
  explicit FlatScene(double grey)
  {
    this->Window = FreshWindow(64, 48);
    this->Window->AddRenderer(this->Renderer);
    this->Plane->SetOrigin(-10, -10, 0);
    this->Plane->SetPoint1(10, -10, 0);
    this->Plane->SetPoint2(-10, 10, 0);
    this->Actor = MakeActor(this->Plane, grey, grey, grey);
    this->Renderer->AddActor(this->Actor);
    this->Renderer->GetActiveCamera()->ParallelProjectionOn();
    this->Renderer->GetActiveCamera()->SetParallelScale(1.0);
    this->Renderer->GetActiveCamera()->SetPosition(0, 0, 5);
    this->Renderer->ResetCameraClippingRange();
    this->Renderer->SetPass(this->Pipeline);
  }
  // The centre pixel's RGB after a render.
  std::vector<int> Centre()
  {
    this->Window->Render();
    const auto image = vtkFXScenes::Capture(this->Window);
    const size_t i = 3 * (24 * 64 + 32);
    return { image[i], image[i + 1], image[i + 2] };
  }
};

vtkSmartPointer<Probe> AddProbe(vtkFXPipelinePass* pipeline, const char* name, int stage,
  bool required = false, const char* input = "")
{
  vtkSmartPointer<Probe> p;
  if (required)
  {
    p = vtkSmartPointer<Consumer>::New();
  }
  else
  {
    p = vtkSmartPointer<Probe>::New();
  }
  p->Label = name;
  p->SetStage(stage);
  p->SetInputConnection("in", input);
  pipeline->AddEffect(name, p);
  return p;
}

// A blur whose source ran but wrote no texture (an occlusion texture the
// driver could not allocate, say, which its own pass reports) says so
// once, not every frame.
int TestBlurWithoutTexture()
{
  FlatScene scene(0.8);
  AddProbe(scene.Pipeline, "producer", vtkFXEffectPass::AfterGBuffer);
  vtkNew<vtkFXBilateralBlurPass> blur;
  blur->SetInputConnection("source", "producer.out");
  scene.Pipeline->AddEffect("blur", blur);
  vtkFXTest::EventCounter errors(blur);
  for (int frame = 0; frame < 3; ++frame)
  {
    scene.Centre();
  }
  const std::string passes = vtkFXTest::Passes(scene.Pipeline);
  std::cout << "a blur whose source wrote no texture, three frames: passes " << passes << ", "
            << errors.Count << " error(s): " << errors.Last << std::endl;
  FX_CHECK(passes.find("producer,blur") != std::string::npos, "the blur ran: " << passes);
  FX_CHECK(errors.Count == 1, errors.Count << " errors in three frames");
  return EXIT_SUCCESS;
}

int TestStages()
{
  FlatScene scene(0.8);
  // Added in reverse frame order: the stages decide, not the order added.
  AddProbe(scene.Pipeline, "pp", vtkFXEffectPass::PostProcess);
  AddProbe(scene.Pipeline, "ag", vtkFXEffectPass::AfterGBuffer);
  auto ls = AddProbe(scene.Pipeline, "ls", vtkFXEffectPass::LightSpace);
  ls->NeedsTranslucent = true;
  vtkNew<HookProbe> hooks;
  scene.Pipeline->AddEffect("hooks", hooks);
  RunLog.clear();
  scene.Centre();
  std::cout << "opaque only: " << vtkFXTest::Passes(scene.Pipeline) << std::endl;
  FX_CHECK(vtkFXTest::Passes(scene.Pipeline) == "lights,gbuffer,ag,hdr-target,composite,pp",
    "light-space needs translucent props; composite-stage effects have no pass: "
      << vtkFXTest::Passes(scene.Pipeline));
  FX_CHECK(scene.Pipeline->GetCompositePass()->GetNumberOfContributors() == 3,
    "every effect that ran contributes to the composite");
  // Timings follow a pass in and out of the HDR target (results arrive a
  // few frames late).
  auto timedAfterFrames = [&scene](const char* pass) {
    for (int frame = 0; frame < 6; ++frame)
    {
      scene.Centre();
    }
    return scene.Pipeline->GetPassMilliseconds(pass);
  };
  FX_CHECK(timedAfterFrames("composite") >= 0.0, "composite timed inside the target");
  vtkSmartPointer<vtkFXEffectPass> pp = scene.Pipeline->GetEffect("pp");
  scene.Pipeline->RemoveEffect("pp");
  FX_CHECK(timedAfterFrames("composite") >= 0.0, "composite timed again outside the target");
  scene.Pipeline->AddEffect("pp", pp);

  vtkNew<vtkSphereSource> sphere;
  auto glass = MakeActor(sphere, 1, 1, 1);
  glass->GetProperty()->SetOpacity(0.5);
  scene.Renderer->AddActor(glass);
  RunLog.clear();
  scene.Centre();
  std::cout << "opaque and translucent: " << vtkFXTest::Passes(scene.Pipeline) << std::endl;
  FX_CHECK(vtkFXTest::Passes(scene.Pipeline) == "lights,ls,gbuffer,ag,hdr-target,composite,translucent,pp",
    vtkFXTest::Passes(scene.Pipeline));
  FX_CHECK(Log() == "ls,ag,pp", Log());

  // Translucent only: no G-buffer, no composite, but light-space effects
  // still run (the probes of the other stages want opaque props).
  scene.Renderer->RemoveActor(scene.Actor);
  RunLog.clear();
  scene.Centre();
  std::cout << "translucent only: " << vtkFXTest::Passes(scene.Pipeline) << std::endl;
  FX_CHECK(vtkFXTest::Passes(scene.Pipeline) == "lights,ls,translucent", vtkFXTest::Passes(scene.Pipeline));
  FX_CHECK(scene.Pipeline->GetGBufferBytesPerPixel() == 0, "no G-buffer");
  FX_CHECK(scene.Pipeline->GetLastSceneInfo().TranslucentProps.size() == 1 &&
      scene.Pipeline->GetLastSceneInfo().Lights.size() == 1,
    "the scene summary lists the translucent prop and the light");
  return EXIT_SUCCESS;
}

int TestConnections()
{
  FlatScene scene(0.8);
  vtkFXTest::ErrorCounter errors(scene.Pipeline);
  // A consumer added before its producer runs after it.
  AddProbe(scene.Pipeline, "consumer", vtkFXEffectPass::AfterGBuffer, true, "producer.out");
  auto producer = AddProbe(scene.Pipeline, "producer", vtkFXEffectPass::AfterGBuffer);
  RunLog.clear();
  scene.Centre();
  FX_CHECK(Log() == "producer,consumer", "dependency order: " << Log());
  FX_CHECK(std::string(scene.Pipeline->GetScheduleProblems()).empty() && errors.Count == 0,
    scene.Pipeline->GetScheduleProblems());
  // "producer" alone names its first output.
  scene.Pipeline->GetEffect("consumer")->SetInputConnection("in", "producer");
  RunLog.clear();
  scene.Centre();
  FX_CHECK(Log() == "producer,consumer", "first output by default: " << Log());

  // A producer without work: its consumer is out, and that is no fault.
  producer->EnabledOff();
  RunLog.clear();
  scene.Centre();
  FX_CHECK(Log().empty() && errors.Count == 0, "consumer left out silently: " << Log());
  producer->EnabledOn();

  struct Case
  {
    const char* Connection;
    int ProducerStage;
    const char* Problem;
  };
  const Case cases[] = {
    { "nobody.out", vtkFXEffectPass::AfterGBuffer, "no effect has that name" },
    { "producer.nothing", vtkFXEffectPass::AfterGBuffer, "has no output 'nothing'" },
    { "producer.out", vtkFXEffectPass::PostProcess, "runs at the post-process stage" },
    { "", vtkFXEffectPass::AfterGBuffer, "input 'in' is not connected" },
  };
  int expectedErrors = 0;
  for (const Case& c : cases)
  {
    scene.Pipeline->GetEffect("consumer")->SetInputConnection("in", c.Connection);
    producer->SetStage(c.ProducerStage);
    RunLog.clear();
    scene.Centre();
    scene.Centre(); // a second frame reports nothing new
    ++expectedErrors;
    std::cout << "'" << c.Connection << "': " << Log() << " / "
              << scene.Pipeline->GetScheduleProblems();
    FX_CHECK(Contains(scene.Pipeline->GetScheduleProblems(), c.Problem),
      "expected '" << c.Problem << "'");
    FX_CHECK(!Contains(Log(), "consumer"), "the consumer is left out");
    FX_CHECK(errors.Count == expectedErrors, "one error per new problem: " << errors.Count);
  }
  producer->SetStage(vtkFXEffectPass::AfterGBuffer);

  // A cycle: both out, reported.
  scene.Pipeline->GetEffect("consumer")->SetInputConnection("in", "producer.out");
  producer->SetInputConnection("in", "consumer.out");
  RunLog.clear();
  scene.Centre();
  std::cout << "cycle: " << scene.Pipeline->GetScheduleProblems();
  FX_CHECK(Contains(scene.Pipeline->GetScheduleProblems(), "in a cycle") && Log().empty(),
    "a cycle is reported and its effects left out: " << Log());

  // Effects that read from a cycle are not part of it: an optional reader
  // runs without its input, a required one is left out silently.
  auto optionalReader = AddProbe(scene.Pipeline, "optional-reader", vtkFXEffectPass::AfterGBuffer,
    false, "consumer.out");
  AddProbe(scene.Pipeline, "required-reader", vtkFXEffectPass::AfterGBuffer, true, "consumer.out");
  RunLog.clear();
  scene.Centre();
  std::cout << "readers of a cycle: " << Log() << " / " << scene.Pipeline->GetScheduleProblems();
  FX_CHECK(Log() == "optional-reader", "only the optional reader runs: " << Log());
  FX_CHECK(!Contains(scene.Pipeline->GetScheduleProblems(), "reader"),
    "readers are not named as cycle members");
  FX_CHECK(!optionalReader->GetInputProducer("in"), "its input is unbound");
  scene.Pipeline->RemoveEffect("required-reader");

  // An optional input from a later stage: reported, and left unbound.
  producer->SetInputConnection("in", "");
  optionalReader->SetInputConnection("in", "producer.out");
  producer->SetStage(vtkFXEffectPass::PostProcess);
  RunLog.clear();
  scene.Centre();
  FX_CHECK(Contains(scene.Pipeline->GetScheduleProblems(), "'optional-reader': input 'in'") &&
      !optionalReader->GetInputProducer("in") && Contains(Log(), "optional-reader"),
    "a late optional input is reported and unbound: " << Log());
  producer->SetStage(vtkFXEffectPass::AfterGBuffer);
  scene.Pipeline->RemoveEffect("optional-reader");

  // Fixed: nothing to report, both run again.
  producer->SetInputConnection("in", "");
  RunLog.clear();
  scene.Centre();
  FX_CHECK(std::string(scene.Pipeline->GetScheduleProblems()).empty() &&
      Log() == "producer,consumer",
    Log());
  FX_CHECK(scene.Pipeline->GetEffect("consumer")->GetInputProducer("in") == producer,
    "the input is bound to its producer");
  std::ostringstream printed;
  scene.Pipeline->Print(printed);
  FX_CHECK(Contains(printed.str(), "consumer: Consumer, after-gbuffer stage, enabled, ran") &&
      Contains(printed.str(), "input in <- producer.out") &&
      Contains(printed.str(), "ScheduleProblems: none"),
    "PrintSelf shows the effects, their inputs and the problems:\n" << printed.str());
  return EXIT_SUCCESS;
}

// A PBR plane (VTK's colour, which the composite keeps) receives the
// ambient visibility v in linear light, as diffuse light: VTK writes
// pow(linear, 1 / 2.2), so v = 0.5 scales the colour by 0.5^(1 / 2.2) =
// 0.7297 at strength 1, and by nothing at strength 0. Before, PBR
// fragments carried no normal and no ambient hook ran for them: no
// occlusion at all. The hook's normal channel is all that asks for one.
bool CheckPrelitOcclusion(FlatScene& scene, HookProbe* probe)
{
  scene.Actor->GetProperty()->SetInterpolationToPBR();
  scene.Actor->GetProperty()->SetRoughness(0.5);
  probe->Channels = vtkFXGBufferPass::ChannelBit(vtkFXGBufferPass::Normal);
  probe->Code[vtkFXEffectPass::Ambient] = "";
  const auto open = scene.Centre();
  probe->Code[vtkFXEffectPass::Ambient] = "ambientVisibility *= 0.5;";
  const auto occluded = scene.Centre();
  scene.Pipeline->GetCompositePass()->SetOcclusionDiffuseStrength(0.0);
  const auto kept = scene.Centre();
  scene.Pipeline->GetCompositePass()->SetOcclusionDiffuseStrength(1.0);
  // VTK's own forward render of the same plane.
  scene.Renderer->SetPass(nullptr);
  const auto forward = scene.Centre();
  scene.Renderer->SetPass(scene.Pipeline);
  scene.Actor->GetProperty()->SetInterpolationToGouraud();
  probe->Channels = 0;
  const double expected = open[0] * std::pow(0.5, 1.0 / 2.2);
  std::cout << "PBR plane: VTK " << forward[0] << ", open " << open[0] << ", ambient 0.5 "
            << occluded[0] << " (expected " << expected << "), strength 0 " << kept[0]
            << std::endl;
  return open[0] > 100 && std::abs(open[0] - forward[0]) <= 1 &&
    std::abs(occluded[0] - expected) <= 1.5 && std::abs(kept[0] - open[0]) <= 1;
}

int TestHooks()
{
  // Albedo 0.8 under a headlight facing the plane: 204 grey.
  FlatScene scene(0.8);
  vtkNew<HookProbe> a, b;
  scene.Pipeline->AddEffect("a", a);
  scene.Pipeline->AddEffect("b", b);
  auto expect = [&](int grey, const char* what) {
    const auto c = scene.Centre();
    std::cout << what << ": " << c[0] << "," << c[1] << "," << c[2] << std::endl;
    return std::abs(c[0] - grey) <= 1 && std::abs(c[1] - grey) <= 1;
  };
  FX_CHECK(expect(204, "no hook code"), "plain lit colour");
  a->Code[vtkFXEffectPass::Ambient] = "ambientVisibility *= 0.5;";
  FX_CHECK(expect(102, "ambient 0.5"), "ambient visibility scales diffuse light by strength 1");
  scene.Pipeline->GetCompositePass()->SetOcclusionDiffuseStrength(0.0);
  FX_CHECK(expect(204, "ambient 0.5, strength 0"), "strength 0 keeps diffuse light");
  scene.Pipeline->GetCompositePass()->SetOcclusionDiffuseStrength(1.0);
  FX_CHECK(CheckPrelitOcclusion(scene, a), "PBR colours are occluded in linear light");
  a->Code[vtkFXEffectPass::Ambient] = "";
  a->Code[vtkFXEffectPass::LightVisibility] = "lightVisibility = lightIndex == 0 ? 0.25 : 1.0;";
  FX_CHECK(expect(51, "light 0 at 0.25"), "per-light visibility");
  a->Code[vtkFXEffectPass::LightVisibility] = "";
  // The same declaration in two effects: '@' keeps them apart.
  for (HookProbe* p : { a.Get(), b.Get() })
  {
    p->Code[vtkFXEffectPass::Declarations] = "uniform float @gain;";
    p->Code[vtkFXEffectPass::Color] = "color *= @gain;";
  }
  a->Gain = 0.5f;
  b->Gain = 0.25f;
  FX_CHECK(expect(26, "gains 0.5 and 0.25"), "each effect's uniform");
  for (HookProbe* p : { a.Get(), b.Get() })
  {
    p->Code[vtkFXEffectPass::Declarations] = "";
    p->Code[vtkFXEffectPass::Color] = "";
  }

  // Two directional lights (VTK's complexity 2), then a point light before
  // them (complexity 3), on the uniform and on the light-texture path
  // (which sorts its rows: directional lights first): hiding a light by
  // its lightIndex equals switching it off, for each directional light
  // and for the point light.
  for (bool withPoint : { false, true })
  {
    scene.Renderer->RemoveAllLights();
    if (withPoint)
    {
      vtkNew<vtkLight> point;
      point->SetLightTypeToSceneLight();
      point->PositionalOn();
      point->SetConeAngle(180.0);
      point->SetPosition(0, -0.5, 3);
      point->SetFocalPoint(0, 0, 0);
      point->SetIntensity(0.4);
      scene.Renderer->AddLight(point);
    }
    for (double x : { -1.0, 1.0 })
    {
      vtkNew<vtkLight> light;
      light->SetLightTypeToSceneLight();
      light->SetPosition(x, 0.5, 3);
      light->SetFocalPoint(0, 0, 0);
      light->SetIntensity(0.5);
      scene.Renderer->AddLight(light);
    }
    const int count = scene.Renderer->GetLights()->GetNumberOfItems();
    for (int maxUniform : { 8, 1 })
    {
      scene.Pipeline->GetCompositePass()->SetMaximumUniformLights(maxUniform);
      const auto all = scene.Centre();
      for (int index = 0; index < count; ++index)
      {
        vtkLight* light = vtkLight::SafeDownCast(scene.Renderer->GetLights()->GetItemAsObject(index));
        light->SwitchOff();
        const auto off = scene.Centre();
        light->SwitchOn();
        a->Code[vtkFXEffectPass::LightVisibility] =
          "if (lightIndex == " + std::to_string(index) + ") lightVisibility = 0.0;";
        const auto hidden = scene.Centre();
        a->Code[vtkFXEffectPass::LightVisibility] = "";
        std::cout << (maxUniform == 1 ? "light texture" : "uniforms") << ", "
                  << (withPoint ? "a point light and two directional" : "two directional")
                  << ": light " << index << " off " << off[0] << ", hidden " << hidden[0]
                  << ", all on " << all[0] << std::endl;
        FX_CHECK(all[0] > off[0] + 10, "light " << index << " adds");
        FX_CHECK(std::abs(hidden[0] - off[0]) <= 1, "lightIndex follows VTK's light order");
      }
      FX_CHECK(scene.Pipeline->GetLastSceneInfo().LightingComplexity == (withPoint ? 3 : 2),
        "lighting complexity");
    }
  }
  return EXIT_SUCCESS;
}

// 20 lights on the fandisk, in mixed order: spots and points with
// attenuation, and two directional lights: the light texture (whose rows
// are sorted by kind) must give VTK's forward image.
int TestManyLights()
{
  auto window = FreshWindow(400, 300);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  std::string error;
  FX_CHECK(vtkFXScenes::Populate(renderer, vtkFXScenes::DataDirectory() + "/fandisk.obj",
             vtkFXScenes::Options(), error),
    error);
  renderer->RemoveAllLights();
  double bounds[6];
  renderer->ComputeVisiblePropBounds(bounds);
  const double centre[3] = { (bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2,
    (bounds[4] + bounds[5]) / 2 };
  const double size = bounds[1] - bounds[0];
  for (int i = 0; i < 20; ++i)
  {
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetPositional(i != 5 && i != 13); // two directional lights among them
    const double angle = 2.0 * 3.14159265358979 * i / 20;
    light->SetPosition(centre[0] + size * std::cos(angle), centre[1] + size * std::sin(angle),
      centre[2] + size * (0.5 + 0.05 * i));
    light->SetFocalPoint(centre);
    light->SetConeAngle(i % 3 == 0 ? 30.0 : 180.0);
    light->SetExponent(2.0);
    light->SetAttenuationValues(1.0, 0.1 / size, 0.05 / (size * size));
    light->SetColor(0.5 + 0.5 * std::cos(angle), 0.7, 0.5 + 0.5 * std::sin(angle));
    light->SetIntensity(0.15);
    renderer->AddLight(light);
  }
  window->Render();
  const auto forward = vtkFXScenes::Capture(window);
  vtkNew<vtkFXPipelinePass> pipeline;
  renderer->SetPass(pipeline);
  unsigned char background[3];
  vtkFXScenes::BackgroundBytes(renderer, background);
  // Uniforms; the light texture culled per tile; the light texture
  // untiled (LightCutoff 0).
  for (int variant : { 0, 1, 2 })
  {
    const int maxUniform = variant == 0 ? 64 : 8;
    pipeline->GetCompositePass()->SetMaximumUniformLights(maxUniform);
    pipeline->GetCompositePass()->SetLightCutoff(variant == 2 ? 0.0 : 1.0 / 512.0);
    window->Render();
    const auto deferred = vtkFXScenes::Capture(window);
    const double psnr = vtkFXScenes::PSNR(forward, deferred, background);
    const int diff = vtkFXScenes::MaxDifference(forward, deferred);
    std::cout << "20 lights of three kinds, "
              << (variant == 0 ? "uniforms" : variant == 1 ? "light texture" : "light texture, untiled")
              << ": PSNR " << psnr << " dB, largest difference " << diff << std::endl;
    FX_CHECK(pipeline->GetLastSceneInfo().LightingComplexity == 3, "positional lighting");
    FX_CHECK(psnr >= 50.0 && diff <= 2, "matches VTK's forward render");
  }
  // A debug view on the light-texture path: its program reads no light,
  // and the lights' texture is kept from frame to frame (it was freed and
  // made again every frame).
  pipeline->GetCompositePass()->SetMaximumUniformLights(8);
  pipeline->SetDebugChannel(vtkFXGBufferPass::Normal);
  std::vector<vtkTextureObject*> kept;
  for (int frame = 0; frame < 3; ++frame)
  {
    window->Render();
    kept.push_back(pipeline->GetCompositePass()->GetLightTexture());
  }
  std::cout << "20 lights, normal view: the lights' texture " << kept[0] << ", " << kept[1] << ", "
            << kept[2] << std::endl;
  FX_CHECK(kept[0] && kept[1] == kept[0] && kept[2] == kept[0],
    "the lights' texture was not kept under a debug view");
  pipeline->SetDebugChannel(-1);
  return EXIT_SUCCESS;
}

// Layer 0: a sphere; layer 1 (preserving colour and depth): a plane through
// its centre. VTK keeps the half of the sphere in front of the plane.
int TestLayers()
{
  auto window = FreshWindow(400, 300);
  window->SetNumberOfLayers(2);
  vtkNew<vtkRenderer> bottom, top;
  top->SetLayer(1);
  top->SetPreserveDepthBuffer(1);
  top->SetPreserveColorBuffer(1);
  window->AddRenderer(bottom);
  window->AddRenderer(top);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(48);
  bottom->AddActor(MakeActor(sphere, 0.9, 0.2, 0.2));
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-1.5, -1.5, 0);
  plane->SetPoint1(1.5, -1.5, 0);
  plane->SetPoint2(-1.5, 1.5, 0);
  top->AddActor(MakeActor(plane, 0.3, 0.6, 0.9));
  bottom->GetActiveCamera()->SetPosition(2, 1.5, 4);
  bottom->ResetCamera();
  top->SetActiveCamera(bottom->GetActiveCamera());
  window->Render();
  const auto forward = vtkFXScenes::Capture(window);
  unsigned char background[3];
  vtkFXScenes::BackgroundBytes(bottom, background);

  vtkNew<vtkFXPipelinePass> pipelineBottom, pipelineTop;
  bottom->SetPass(pipelineBottom);
  top->SetPass(pipelineTop);
  vtkNew<HalveProbe> halve;
  for (bool hdr : { false, true })
  {
    if (hdr)
    {
      // The HDR target must start from what the layer below drew (colour
      // and depth): halve the top layer's image, compare with VTK's halved.
      pipelineTop->AddEffect("halve", halve);
    }
    window->Render();
    auto deferred = vtkFXScenes::Capture(window);
    auto reference = forward;
    if (hdr)
    {
      for (auto& v : reference)
      {
        v = static_cast<unsigned char>((v * 128 + 127) / 255);
      }
    }
    const double psnr = vtkFXScenes::PSNR(reference, deferred, hdr ? nullptr : background);
    const int diff = vtkFXScenes::MaxDifference(reference, deferred);
    std::cout << "layers" << (hdr ? " through the HDR target (halved)" : "") << ": PSNR " << psnr
              << " dB, largest difference " << diff << "; top: " << vtkFXTest::Passes(pipelineTop) << std::endl;
    FX_CHECK(psnr >= 50.0 && diff <= 2, "layered renderers match VTK");
  }
  FX_CHECK(halve->SawFrameBuffer && pipelineTop->GetHDRTargetPass()->GetColorTexture() &&
      pipelineTop->GetHDRTargetPass()->GetColorTexture()->GetVTKDataType() == VTK_FLOAT,
    "the post-process drew into the float target");
  return EXIT_SUCCESS;
}

// The window's depth buffer over the whole window.
std::vector<float> CaptureDepth(vtkRenderWindow* window)
{
  const int* size = window->GetSize();
  std::vector<float> depth(static_cast<size_t>(size[0]) * size[1]);
  window->GetZbufferData(0, 0, size[0] - 1, size[1] - 1, depth.data());
  return depth;
}

// The composite's depth pre-pass (vtkFXCompositePass::UseDepthPrepass)
// changes which pixels the lighting shades, not what any pixel gets: with
// and without it, the same colours and depth buffer, bit for bit, and as
// a blit the same within a grey level where a volume ends its rays at the
// depth and the depth within float rounding,
// on scenes with forward-drawn, translucent, volume and overlay props,
// with and without an effect in the composite, in a viewport that does not
// start at the window's corner. It stays off where the framebuffer's depth
// is not the clear value at the composite (preserved depth, no erase).
int TestDepthPrepass()
{
  auto window = FreshWindow(400, 300);
  for (const std::string input : { "scene:mixed", "scene:splats", "scene:volume", "scene:glyphs" })
  {
    std::vector<float> depthWithoutEffect; // (one pass)
    // none, ambient occlusion, and a post-process effect (the composite
    // then draws into the HDR target)
    for (int effect : { 0, 1, 2 })
    {
      const bool occlusion = effect == 1;
      window->GetRenderers()->RemoveAllItems();
      vtkNew<vtkRenderer> renderer;
      renderer->SetViewport(0.1, 0.2, 0.9, 1.0);
      window->AddRenderer(renderer);
      std::string error;
      FX_CHECK(vtkFXScenes::Populate(renderer, input, vtkFXScenes::Options(), error), error);
      vtkNew<vtkFXPipelinePass> pipeline;
      pipeline->SetAmbientOcclusion(occlusion);
      vtkNew<HalveProbe> halve;
      if (effect == 2)
      {
        pipeline->AddEffect("halve", halve);
      }
      renderer->SetPass(pipeline);
      vtkFXCompositePass* composite = pipeline->GetCompositePass();
      // 0: one pass; 1: the pre-pass as a full-screen pass; 2: as a blit
      std::vector<unsigned char> colour[3];
      std::vector<float> depth[3];
      for (int prepass : { 0, 1, 2 })
      {
        composite->SetUseDepthPrepass(prepass != 0);
        composite->SetUseDepthBlit(prepass == 2);
        window->Render();
        // (no GL error left behind: the depth format queries ask only
        // attachment points that hold something)
        const GLenum error = glGetError();
        FX_CHECK(error == GL_NO_ERROR, input << ": GL error " << error << " after the frame");
        FX_CHECK(composite->GetUsedDepthPrepass() == (prepass != 0) &&
            composite->GetUsedDepthBlit() == (prepass == 2),
          input << ": the pre-pass ran " << composite->GetUsedDepthPrepass() << ", as a blit "
                << composite->GetUsedDepthBlit());
        colour[prepass] = vtkFXScenes::Capture(window);
        depth[prepass] = CaptureDepth(window);
      }
      float depthDifference[3] = { 0.0f, 0.0f, 0.0f };
      int colourDifference[3] = { 0, 0, 0 };
      for (int prepass : { 1, 2 })
      {
        for (size_t i = 0; i < depth[0].size(); ++i)
        {
          depthDifference[prepass] =
            std::max(depthDifference[prepass], std::abs(depth[0][i] - depth[prepass][i]));
        }
        colourDifference[prepass] = vtkFXScenes::MaxDifference(colour[0], colour[prepass]);
      }
      std::cout << input
                << (effect == 1 ? " with ambient occlusion" : effect == 2 ? " through the HDR target" : "")
                << ": against one pass, the pre-pass as a pass differs by " << colourDifference[1]
                << "/255 and " << depthDifference[1] << " in depth, as a blit by "
                << colourDifference[2] << "/255 and " << depthDifference[2] << std::endl;
      FX_CHECK(colourDifference[1] == 0 && depthDifference[1] == 0.0f,
        input << ": the depth pre-pass changed the image");
      // (the passes carry the 32-bit fixed-point depth of VTK's window
      // through a float, 24 bits of mantissa: a step of 2^-24 to 2^-23
      // below 1; the blit copies it exactly. A volume's rays end at that
      // depth: one grey level.)
      FX_CHECK(colourDifference[2] <= 1 && depthDifference[2] <= 2.5e-7f,
        input << ": the depth blit changed the image");
      // The HDR target writes back the depth it was drawn with (a blit
      // where the window takes one): the window's depth buffer is the one
      // the frame without the target leaves.
      if (effect == 0)
      {
        depthWithoutEffect = depth[0];
      }
      else if (effect == 2)
      {
        float targetDifference = 0.0f;
        for (size_t i = 0; i < depth[0].size(); ++i)
        {
          targetDifference =
            std::max(targetDifference, std::abs(depthWithoutEffect[i] - depth[0][i]));
        }
        std::cout << input << ": the window's depth after the HDR target differs by "
                  << targetDifference << " from the frame without it" << std::endl;
        FX_CHECK(targetDifference <= 2.5e-7f, input << ": the HDR target changed the depth by "
                                                    << targetDifference);
      }
    }
  }
  // A window asked for 4 samples: with the pre-pass (a blit where the
  // window's framebuffer takes one, a pass otherwise) the image is the
  // same as one pass's.
  {
    auto msaa = vtkFXTest::MakeWindow(200, 150);
    msaa->SetMultiSamples(4);
    vtkNew<vtkRenderer> renderer;
    msaa->AddRenderer(renderer);
    std::string error;
    FX_CHECK(vtkFXScenes::Populate(renderer, "scene:mixed", vtkFXScenes::Options(), error), error);
    vtkNew<vtkFXPipelinePass> pipeline;
    renderer->SetPass(pipeline);
    vtkFXCompositePass* composite = pipeline->GetCompositePass();
    std::vector<unsigned char> colour[2];
    for (int prepass : { 0, 1 })
    {
      composite->SetUseDepthPrepass(prepass != 0);
      msaa->Render();
      colour[prepass] = vtkFXScenes::Capture(msaa);
    }
    std::cout << "multisampled window: pre-pass " << composite->GetUsedDepthPrepass()
              << ", as a blit " << composite->GetUsedDepthBlit() << ", largest colour difference "
              << vtkFXScenes::MaxDifference(colour[0], colour[1]) << "/255" << std::endl;
    FX_CHECK(composite->GetUsedDepthPrepass() && !colour[0].empty() && colour[0] == colour[1],
      "multisampled window: the pre-pass changed the image");
  }
  // Where the depth buffer holds more than the clear value, one pass.
  vtkRenderer* renderer = window->GetRenderers()->GetFirstRenderer();
  auto* pipeline = vtkFXPipelinePass::SafeDownCast(renderer->GetPass());
  for (int keep : { 0, 1 })
  {
    renderer->SetPreserveDepthBuffer(keep == 0);
    renderer->SetErase(keep == 0);
    window->Render();
    FX_CHECK(!pipeline->GetCompositePass()->GetUsedDepthPrepass(),
      (keep == 0 ? "preserved depth" : "no erase") << ": the pre-pass ran; passes "
                                                     << vtkFXTest::Passes(pipeline));
    renderer->SetPreserveDepthBuffer(0);
    renderer->SetErase(1);
  }
  return EXIT_SUCCESS;
}

// Emission 2.0 in red: kept in a float channel, and through the HDR target
// a halving post-process still leaves red at 1.
int TestEmission()
{
  FlatScene scene(0.2);
  scene.Centre();
  FX_CHECK(!(scene.Pipeline->GetGBufferChannels() & GB::ChannelBit(GB::Emission)),
    "no emissive prop: no emission channel");
  const double emissive[3] = { 2.0, 0.5, 0.0 };
  scene.Actor->SetPropertyKeys(vtkSmartPointer<vtkInformation>::New());
  scene.Actor->GetPropertyKeys()->Set(GB::EMISSIVE_COLOR(), emissive, 3);
  const auto lit = scene.Centre();
  vtkFXGBufferPass* gb = scene.Pipeline->GetGBufferPass();
  FX_CHECK(gb->GetHDREmission() && gb->GetChannelFormat(GB::Emission) == vtkFXRenderUtilities::RGBA16F,
    "emission above 1 gets a float channel");
  const auto values = vtkFXTest::Download(gb->GetChannelTexture(GB::Emission), 4);
  const size_t centre = 4 * (24 * 64 + 32);
  std::cout << "emission texel " << values[centre] << "," << values[centre + 1] << ","
            << values[centre + 2] << "; lit colour " << lit[0] << "," << lit[1] << "," << lit[2]
            << std::endl;
  FX_CHECK(std::fabs(values[centre] - 2.0f) < 1e-3f && std::fabs(values[centre + 1] - 0.5f) < 1e-3f,
    "the emission channel keeps 2.0");
  FX_CHECK(lit[0] == 255 && std::abs(lit[1] - 179) <= 1 && std::abs(lit[2] - 51) <= 1,
    "lit colour = albedo x light + emission");
  FX_CHECK(scene.Pipeline->GetLastSceneInfo().EmissiveProps.size() == 1, "listed as emissive");

  vtkNew<HalveProbe> halve;
  scene.Pipeline->AddEffect("halve", halve);
  const auto halved = scene.Centre();
  std::cout << "halved in the HDR target: " << halved[0] << "," << halved[1] << "," << halved[2]
            << std::endl;
  FX_CHECK(halved[0] == 255 && std::abs(halved[1] - 90) <= 1 && std::abs(halved[2] - 26) <= 1,
    "values above 1 survive until the HDR target is written");

  const double dim[3] = { 0.5, 0.0, 0.0 };
  scene.Actor->GetPropertyKeys()->Set(GB::EMISSIVE_COLOR(), dim, 3);
  scene.Centre();
  FX_CHECK(!gb->GetHDREmission() && gb->GetBytesPerPixel() == 16,
    "emission within [0, 1]: RGBA8 (albedo, normal, emission, depth)");

  // NaN, infinite and negative emission: kept out, the prop lit as without.
  scene.Pipeline->RemoveEffect("halve");
  const double bad[3] = { std::nan(""), std::numeric_limits<double>::infinity(), -1.0 };
  scene.Actor->GetPropertyKeys()->Set(GB::EMISSIVE_COLOR(), bad, 3);
  const auto sane = scene.Centre();
  const auto channel = vtkFXTest::Download(gb->GetChannelTexture(GB::Emission), 4);
  for (float v : channel)
  {
    FX_CHECK(std::isfinite(v) && v >= 0.0f, "emission channel finite and >= 0: " << v);
  }
  std::cout << "bad emission: lit colour " << sane[0] << "," << sane[1] << "," << sane[2]
            << std::endl;
  // (vtkFXGBufferPass::GetEmissiveColor drops non-finite and negative
  // components: 0.2 x 255 = 51 grey, as without emission)
  FX_CHECK(std::abs(sane[0] - 51) <= 1 && std::abs(sane[1] - 51) <= 1 &&
      std::abs(sane[2] - 51) <= 1,
    "NaN, infinite and negative emission add nothing");

  // A PBR prop's emission adds to VTK's colour as a lit prop's does to its
  // light (before, the glow had it and the surface did not).
  scene.Actor->GetProperty()->SetInterpolationToPBR();
  scene.Actor->GetPropertyKeys()->Remove(GB::EMISSIVE_COLOR());
  const auto plainPbr = scene.Centre();
  const double red[3] = { 0.4, 0.0, 0.0 };
  scene.Actor->GetPropertyKeys()->Set(GB::EMISSIVE_COLOR(), red, 3);
  const auto emittingPbr = scene.Centre();
  std::cout << "PBR plane: " << plainPbr[0] << "," << plainPbr[1] << "," << plainPbr[2]
            << "; emitting 0.4 red: " << emittingPbr[0] << "," << emittingPbr[1] << ","
            << emittingPbr[2] << std::endl;
  FX_CHECK(std::abs(emittingPbr[0] - std::min(255, plainPbr[0] + 102)) <= 1 &&
      std::abs(emittingPbr[1] - plainPbr[1]) <= 1 && std::abs(emittingPbr[2] - plainPbr[2]) <= 1,
    "a PBR prop's emission adds to its colour");
  // Occlusion darkens the light a PBR surface reflects, VTK's colour, by
  // v^(1 / 2.2) (see CheckPrelitOcclusion), not the light it gives off:
  // under an ambient visibility of 0.5 its emission still adds 102 (before,
  // the emission was part of the occluded colour: 0.7297 x (colour + 102)).
  vtkNew<HookProbe> occluder;
  occluder->Channels = GB::ChannelBit(GB::Normal);
  occluder->Code[vtkFXEffectPass::Ambient] = "ambientVisibility *= 0.5;";
  scene.Pipeline->AddEffect("occluder", occluder);
  const auto occludedPbr = scene.Centre();
  // An effect that reads the emission channel alone (as bloom does): no
  // normal, the composite passes the colour through, emission included.
  occluder->Channels = GB::ChannelBit(GB::Emission);
  occluder->Code[vtkFXEffectPass::Ambient] = "";
  const auto emissionOnly = scene.Centre();
  std::cout << "emitting PBR plane, emission channel without normals: " << emissionOnly[0]
            << "," << emissionOnly[1] << "," << emissionOnly[2] << std::endl;
  FX_CHECK(emissionOnly == emittingPbr, "the emission stays without a normal channel");
  scene.Pipeline->RemoveEffect("occluder");
  scene.Actor->GetProperty()->SetInterpolationToGouraud();
  const double factor = std::pow(0.5, 1.0 / 2.2);
  const double expectedRed = std::min(255.0, plainPbr[0] * factor + 102);
  std::cout << "emitting PBR plane under ambient 0.5: " << occludedPbr[0] << ","
            << occludedPbr[1] << "," << occludedPbr[2] << " (expected red " << expectedRed
            << ", green " << plainPbr[1] * factor << ")" << std::endl;
  FX_CHECK(std::abs(occludedPbr[0] - expectedRed) <= 1.5 &&
      std::abs(occludedPbr[1] - plainPbr[1] * factor) <= 1.5,
    "occlusion leaves a PBR prop's emission alone");
  return EXIT_SUCCESS;
}
}

// VTK's own steps inside the HDR target: scene:mixed (translucent props,
// forward-opaque text, overlay) and scene:volume through a post-process
// that draws nothing give the image they give without it (8-bit values
// survive 16-bit floats exactly; blending rounds differently, see below).
int TestHDRIdentity()
{
  for (const char* input : { "scene:mixed", "scene:volume" })
  {
    auto window = FreshWindow(400, 300);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    std::string error;
    FX_CHECK(vtkFXScenes::Populate(renderer, input, vtkFXScenes::Options(), error), error);
    vtkNew<vtkFXPipelinePass> pipeline;
    renderer->SetPass(pipeline);
    window->Render();
    const auto direct = vtkFXScenes::Capture(window);
    vtkNew<Probe> nothing; // renders nothing
    nothing->SetStage(vtkFXEffectPass::PostProcess);
    nothing->Label = "nothing";
    pipeline->AddEffect("nothing", nothing);
    window->Render();
    const auto throughTarget = vtkFXScenes::Capture(window);
    unsigned char background[3];
    vtkFXScenes::BackgroundBytes(renderer, background);
    const double psnr = vtkFXScenes::PSNR(direct, throughTarget, background);
    const int diff = vtkFXScenes::MaxDifference(direct, throughTarget);
    std::cout << input << " through the HDR target: " << vtkFXTest::Passes(pipeline) << ", PSNR "
              << psnr << " dB, largest difference " << diff << std::endl;
    FX_CHECK(Contains(vtkFXTest::Passes(pipeline), "hdr-target"), "the target ran");
    // (Translucent layers blend in 16-bit floats there, rounded once at the
    // end, and in 8 bits in the window, rounded per layer: 2 levels apart at
    // most where layers stack.)
    FX_CHECK(psnr >= 50.0 && diff <= 2, "VTK's steps draw into the target as into the window");
  }
  return EXIT_SUCCESS;
}

// The HDR target at a 1x1 viewport, and NaN written into it by a
// post-process: no crash, and 0 where NaN was, never NaN. (An 8-bit window
// turns NaN into 0 by itself on Mesa, so the write-back's own sanitising is
// checked into a float framebuffer, with the target pass used alone.)
int TestHDRRobustness()
{
  FlatScene scene(0.8);
  vtkNew<HalveProbe> probe;
  scene.Pipeline->AddEffect("probe", probe);
  scene.Window->SetSize(1, 1);
  scene.Window->Render();
  const auto tiny = vtkFXScenes::Capture(scene.Window);
  std::cout << "1x1 through the HDR target: " << int(tiny[0]) << "," << int(tiny[1]) << ","
            << int(tiny[2]) << std::endl;
  FX_CHECK(tiny.size() == 3 && std::abs(tiny[0] - 102) <= 1, "1x1: 204 halved");
  scene.Window->SetSize(64, 48);
  // An OpenGL error left pending before the frame (by the application, or
  // a step before the target): the target's copy-in says so, once, and
  // draws the same frame (before, it cleared such errors silently). A VTK
  // built to check GL errors itself (ParaView's) reports it first, in
  // vtkOpenGLRenderWindow::Start, and nothing is left pending for the
  // target.
  const auto clean = scene.Centre();
  vtkFXTest::EventCounter warnings(scene.Pipeline->GetHDRTargetPass(), vtkCommand::WarningEvent);
  vtkSmartPointer<vtkOutputWindow> previousOutput = vtkOutputWindow::GetInstance();
  vtkNew<vtkStringOutputWindow> output;
  vtkOutputWindow::SetInstance(output);
  std::vector<int> pending;
  for (int frame = 0; frame < 2; ++frame)
  {
    scene.Window->MakeCurrent();
    glEnable(0x1234); // (not a capability: GL_INVALID_ENUM)
    pending = scene.Centre();
  }
  vtkOutputWindow::SetInstance(previousOutput);
  const bool vtkReported = Contains(output->GetOutput(), "OpenGL errors detected");
  std::cout << "a GL error pending before two frames: " << warnings.Count << " warning ("
            << warnings.Last << "), centre " << pending[0] << " (" << clean[0] << " without)"
            << (vtkReported ? "; VTK's own checks reported it first" : "") << std::endl;
  FX_CHECK((warnings.Count == 1 || (warnings.Count == 0 && vtkReported)) && pending == clean,
    "a pending GL error is reported once and changes nothing");
  probe->WriteNaN = true;
  probe->ReleaseGraphicsResources(scene.Window); // rebuild its shader
  const auto c = scene.Centre();
  std::cout << "NaN written by a post-process: " << c[0] << "," << c[1] << "," << c[2] << std::endl;
  FX_CHECK(c[0] == 0 && c[1] == 0 && c[2] == 0, "NaN reaches the window as 0");

  // Alone, writing back into an RGBA32F framebuffer of our own.
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(scene.Window.Get());
  vtkSmartPointer<vtkTextureObject> target;
  vtkFXRenderUtilities::EnsureTexture(target, window, 8, 8, vtkFXRenderUtilities::RGBA32F);
  vtkNew<vtkOpenGLFramebufferObject> framebuffer;
  framebuffer->SetContext(window);
  vtkNew<vtkFXHDRTargetPass> hdr;
  hdr->SetDelegatePass(probe);
  // (a colour-only framebuffer: asking VTK the depth size of one was a GL
  // error, which the copy-in then reported as pending)
  vtkFXTest::EventCounter hdrWarnings(hdr, vtkCommand::WarningEvent);
  window->GetState()->PushFramebufferBindings();
  framebuffer->Bind();
  framebuffer->AddColorAttachment(0, target);
  framebuffer->ActivateDrawBuffers(1);
  // Filled with 7 first: a texel the write-back left alone fails the range
  // check below (a new texture's zeros would pass it).
  const float sentinel[4] = { 7.0f, 7.0f, 7.0f, 7.0f };
  glClearBufferfv(GL_COLOR, 0, sentinel);
  {
    vtkOpenGLState::ScopedglViewport viewport(window->GetState());
    window->GetState()->vtkglViewport(0, 0, 8, 8);
    vtkRenderState state(scene.Renderer);
    hdr->Render(&state);
  }
  window->GetState()->PopFramebufferBindings();
  FX_CHECK(hdrWarnings.Count == 0, "no warning into a colour-only framebuffer: " << hdrWarnings.Last);
  const auto values = vtkFXTest::Download(target, 4);
  FX_CHECK(values.size() == 8 * 8 * 4, "read back");
  for (float v : values)
  {
    FX_CHECK(std::isfinite(v) && v >= 0.0f && v <= 1.0f, "written back finite and in [0, 1]: " << v);
  }
  hdr->ReleaseGraphicsResources(window);
  target->ReleaseGraphicsResources(window);
  framebuffer->ReleaseGraphicsResources(window);
  return EXIT_SUCCESS;
}

// One pipeline serves one renderer. Moved to a renderer of another window
// (GL objects of one context are not valid in another), it draws there
// what a fresh pipeline draws; shared by two renderers of one window, it
// warns once.
int TestPipelineOwner()
{
  // (with bloom, whose sampler, and AVSM, whose storage buffers, are bare
  // GL names of one context)
  const auto withEffects = [](vtkFXPipelinePass* pipeline) {
    vtkNew<vtkFXBloomPass> bloom;
    bloom->SetThreshold(0.5);
    pipeline->AddEffect("bloom", bloom);
    vtkNew<vtkFXAVSMPass> avsm;
    pipeline->AddEffect("avsm", avsm);
  };
  vtkNew<vtkFXPipelinePass> moving;
  withEffects(moving);
  vtkFXTest::EventCounter moveWarnings(moving, vtkCommand::WarningEvent);
  std::vector<unsigned char> images[2];
  // (both windows live on: the pipeline moves between two contexts)
  vtkSmartPointer<vtkRenderWindow> windows[2] = { vtkFXTest::MakeWindow(200, 150),
    vtkFXTest::MakeWindow(200, 150) };
  for (int w : { 0, 1 })
  {
    vtkRenderWindow* window = windows[w];
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    std::string error;
    FX_CHECK(vtkFXScenes::Populate(renderer, "scene:mixed", vtkFXScenes::Options(), error), error);
    vtkFXTest::ErrorCounter errors(moving);
    renderer->SetPass(moving);
    window->Render();
    // (a name of the other context's framebuffers or vertex arrays raises
    // GL errors here, even where this context happens to have one)
    window->MakeCurrent();
    const GLenum glError = glGetError();
    images[w] = vtkFXScenes::Capture(window);
    FX_CHECK(glError == GL_NO_ERROR, "GL error " << glError << " in window " << w);
    FX_CHECK(errors.Count == 0, "the pipeline in window " << w << ": " << errors.Last);
    const std::string passes = vtkFXTest::Passes(moving);
    FX_CHECK(passes.find("bloom") != std::string::npos && passes.find("avsm") != std::string::npos,
      "window " << w << " ran " << passes);
    if (w == 1)
    {
      vtkNew<vtkFXPipelinePass> fresh;
      withEffects(fresh);
      renderer->SetPass(fresh);
      window->Render();
      const auto expected = vtkFXScenes::Capture(window);
      std::cout << "a pipeline moved to a second window: largest difference from a fresh one "
                << vtkFXScenes::MaxDifference(expected, images[1]) << "/255" << std::endl;
      FX_CHECK(!expected.empty() && expected == images[1],
        "a pipeline moved to another window draws what a fresh one draws");
    }
    renderer->SetPass(nullptr);
  }
  FX_CHECK(images[0] == images[1], "the same scene in two windows of one size");
  FX_CHECK(moveWarnings.Count == 0, "a pipeline moved once warned: " << moveWarnings.Last);
  // Two renderers of one window, one pipeline: one warning over frames.
  auto window = vtkFXTest::MakeWindow(200, 150);
  vtkNew<vtkRenderer> left, right;
  left->SetViewport(0.0, 0.0, 0.5, 1.0);
  right->SetViewport(0.5, 0.0, 1.0, 1.0);
  window->AddRenderer(left);
  window->AddRenderer(right);
  std::string error;
  FX_CHECK(vtkFXScenes::Populate(left, "scene:corner", vtkFXScenes::Options(), error) &&
      vtkFXScenes::Populate(right, "scene:corner", vtkFXScenes::Options(), error),
    error);
  vtkNew<vtkFXPipelinePass> shared;
  vtkFXTest::EventCounter warnings(shared, vtkCommand::WarningEvent);
  left->SetPass(shared);
  right->SetPass(shared);
  for (int frame = 0; frame < 3; ++frame)
  {
    window->Render();
  }
  std::cout << "one pipeline on two renderers: " << warnings.Count << " warning(s): "
            << warnings.Last << std::endl;
  FX_CHECK(warnings.Count == 1, "a pipeline shared by two renderers warns once");
  left->SetPass(nullptr);
  right->SetPass(nullptr);
  return EXIT_SUCCESS;
}

// vtkFXRenderUtilities::IsOpenGLSupported answers from the context (no
// GLEW): the context's own version and the one below it are there, the
// next minor and major versions are not; its first and last extensions
// are there (asked twice: the second answer comes from the cache), a
// made-up one and a prefix of a real one are not.
int TestOpenGLQueries()
{
  auto window = FreshWindow(64, 64);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  window->Render();
  window->MakeCurrent();
  using U = vtkFXRenderUtilities;
  GLint major = 0, minor = 0, count = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  const auto version = [](int a, int b) {
    return "GL_VERSION_" + std::to_string(a) + "_" + std::to_string(b);
  };
  FX_CHECK(major >= 3 && count > 0, "a core context with extensions");
  FX_CHECK(U::IsOpenGLSupported(version(major, minor).c_str()) &&
      U::IsOpenGLSupported(version(major, 0).c_str()) &&
      U::IsOpenGLSupported(version(major - 1, 9).c_str()),
    "the context's version and the ones below");
  FX_CHECK(!U::IsOpenGLSupported(version(major, minor + 1).c_str()) &&
      !U::IsOpenGLSupported(version(major + 1, 0).c_str()),
    "versions above the context's");
  for (GLint i : { GLint(0), count - 1 })
  {
    const std::string extension = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, i));
    for (int ask = 0; ask < 2; ++ask)
    {
      FX_CHECK(U::IsOpenGLSupported(extension.c_str()), extension << " is there");
    }
    FX_CHECK(!U::IsOpenGLSupported(extension.substr(0, extension.size() - 1).c_str()),
      "a prefix of " << extension);
  }
  FX_CHECK(!U::IsOpenGLSupported("GL_FX_no_such_extension") && !U::IsOpenGLSupported(nullptr),
    "an extension the context lacks");
  std::cout << "OpenGL queries: version " << major << "." << minor << " and " << count
            << " extensions answered from the context" << std::endl;
  return EXIT_SUCCESS;
}

int TestFrameStructure(int, char*[])
{
  auto window = vtkFXTest::MakeWindow(400, 300);
  SharedWindow = window;
  for (auto test : { TestOpenGLQueries, TestStages, TestBlurWithoutTexture, TestConnections, TestHooks, TestManyLights,
         TestLayers, TestDepthPrepass, TestEmission, TestHDRIdentity, TestHDRRobustness,
         TestPipelineOwner })
  {
    if (test() != EXIT_SUCCESS)
    {
      return EXIT_FAILURE;
    }
  }
  return EXIT_SUCCESS;
}
