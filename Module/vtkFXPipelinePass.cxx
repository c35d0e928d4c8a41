#include "vtkFXPipelinePass.h"

#include "vtkFXAntiAliasingPass.h"
#include "vtkFXBilateralBlurPass.h"
#include "vtkFXCompositePass.h"
#include "vtkFXDirectionalOcclusionPass.h"
#include "vtkFXSSAOPass.h"
#include "vtkFXEffectPass.h"
#include "vtkFXForwardOpaquePass.h"
#include "vtkFXGBufferPass.h"
#include "vtkFXHDRTargetPass.h"
#include "vtkFXOpenGL.h"
#include "vtkFXRenderUtilities.h"
#include "vtkFXSelectionPass.h"
#include "vtkFXTimedSequencePass.h"
#include "vtkFXTranslucentPass.h"
#include "vtkFXVolumePass.h"

#include "vtkActor.h"
#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkCamera.h"
#include "vtkCameraPass.h"
#include "vtkPropCollection.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLightsPass.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkHiddenLineRemovalPass.h"
#include "vtkOpaquePass.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOverlayPass.h"
#include "vtkProp.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"

#include <algorithm>
#include <sstream>

vtkStandardNewMacro(vtkFXPipelinePass);

namespace
{
// Records which optional material terms an actor's shaders will produce,
// and whether it emits light of its own.
// Besides Ambient > 0, VTK 9.1 puts colour into the ambient term for
// surface edges (the edge colour, unscaled) and for vertices (intensity
// forced to 1), and a backface property has its own terms.
void AddMaterialTerms(vtkActor* actor, vtkFXSceneInfo& scene, bool& emissive)
{
  for (vtkProperty* p : { actor->GetProperty(), actor->GetBackfaceProperty() })
  {
    if (!p)
    {
      continue;
    }
    // vtkProperty does not clamp colours, and VTK's shaders use them as
    // given: above 1 the G-buffer's 8 bits would clamp them.
    for (const double* c : { p->GetDiffuseColor(), p->GetAmbientColor(), p->GetSpecularColor() })
    {
      scene.LargestColor = std::max({ scene.LargestColor, c[0], c[1], c[2] });
    }
    if (!p->GetLighting())
    {
      emissive = true; // an unlit colour is light-independent
      continue;
    }
    // (PBR keeps its forward colour: the composite does not light it)
    scene.AnyLitProp = scene.AnyLitProp || p->GetInterpolation() != VTK_PBR;
    if (p->GetAmbient() > 0.0 || p->GetEdgeVisibility() || p->GetVertexVisibility())
    {
      scene.AnyAmbient = true;
    }
    if (p->GetSpecular() > 0.0)
    {
      scene.AnySpecular = true;
    }
  }
  scene.AnyPerturbedNormal = scene.AnyPerturbedNormal || vtkFXGBufferPass::PerturbsNormal(actor);
  double color[3];
  if (vtkFXGBufferPass::GetEmissiveColor(actor, color))
  {
    emissive = true;
    scene.AnyEmissiveColor = true;
    scene.AnyEmissionAboveOne =
      scene.AnyEmissionAboveOne || color[0] > 1.0 || color[1] > 1.0 || color[2] > 1.0;
  }
}

// Adds one prop of the renderer to the scene summary.
void AnalyzeProp(vtkProp* prop, vtkFXSceneInfo& scene)
{
  if (prop->IsA("vtkActor2D"))
  {
    // 2D props draw in the overlay step, but VTK calls their opaque step
    // too (text actors build their texture there): that is forward work,
    // not a reason to run the G-buffer.
    scene.OverlayProps.push_back(prop);
    if (prop->HasOpaqueGeometry())
    {
      scene.ForwardOpaqueProps.push_back(prop);
    }
    return;
  }
  if (!prop->IsA("vtkOpenGLActor") && !prop->IsA("vtkVolume") && !prop->IsA("vtkAssembly"))
  {
    // Widgets' representations and other props may draw overlays too, and
    // so may actors of classes other than VTK's own (vtkCubeAxesActor and
    // vtkPolarAxesActor draw their 2D-mode labels there).
    scene.OverlayProps.push_back(prop);
  }
  if (prop->IsA("vtkVolume"))
  {
    scene.VolumeProps.push_back(prop);
    return;
  }
  if (!vtkFXRenderUtilities::GetVolumesDrawn(prop).empty())
  {
    scene.VolumeProps.push_back(prop); // (its other parts are sorted below)
  }
  if (prop->HasTranslucentPolygonalGeometry())
  {
    scene.TranslucentProps.push_back(prop);
  }
  if (!prop->HasOpaqueGeometry())
  {
    return;
  }
  if (!vtkFXGBufferPass::CanCapture(prop))
  {
    scene.ForwardOpaqueProps.push_back(prop);
    return;
  }
  scene.OpaqueProps.push_back(prop);
  // Assemblies hold their actors as paths; a plain actor is its own path.
  // (A part VTK does not draw, its visibility off, asks for nothing.)
  bool emissive = false;
  prop->InitPathTraversal();
  while (vtkAssemblyPath* path = prop->GetNextPath())
  {
    vtkActor* actor = vtkActor::SafeDownCast(path->GetLastNode()->GetViewProp());
    if (actor && actor->GetVisibility())
    {
      AddMaterialTerms(actor, scene, emissive);
    }
  }
  if (emissive)
  {
    scene.EmissiveProps.push_back(prop);
  }
}

// Splits "effect.output" (or "effect") at the first dot.
void SplitConnection(const std::string& connection, std::string& effect, std::string& output)
{
  const size_t dot = connection.find('.');
  effect = connection.substr(0, dot);
  output = dot == std::string::npos ? std::string() : connection.substr(dot + 1);
}
}

// An input of a slot's effect, resolved to the slot that produces it.
struct vtkFXPipelinePass::Connection
{
  std::string Input;
  size_t Producer = 0;
  std::string Output;
  bool Optional = false;
  bool ReadInComposite = false;
};

vtkFXPipelinePass::vtkFXPipelinePass()
{
  this->CameraPass = vtkSmartPointer<vtkCameraPass>::New();
  this->Sequence = vtkSmartPointer<vtkFXTimedSequencePass>::New();
  this->HDRSequence = vtkSmartPointer<vtkFXTimedSequencePass>::New();
  this->HDRTargetPass = vtkSmartPointer<vtkFXHDRTargetPass>::New();
  this->LightsPass = vtkSmartPointer<vtkLightsPass>::New();
  this->OpaquePass = vtkSmartPointer<vtkOpaquePass>::New();
  this->HiddenLinePass = vtkSmartPointer<vtkHiddenLineRemovalPass>::New();
  this->GBufferPass = vtkSmartPointer<vtkFXGBufferPass>::New();
  this->CompositePass = vtkSmartPointer<vtkFXCompositePass>::New();
  this->TranslucentPass = vtkSmartPointer<vtkFXTranslucentPass>::New();
  this->VolumetricPass = vtkSmartPointer<vtkFXVolumePass>::New();
  this->OverlayPass = vtkSmartPointer<vtkOverlayPass>::New();
  this->AntiAliasingPass = vtkSmartPointer<vtkFXAntiAliasingPass>::New();
  this->ForwardOpaquePass = vtkSmartPointer<vtkFXForwardOpaquePass>::New();
  this->SelectionPass = vtkSmartPointer<vtkFXSelectionPass>::New();

  this->SSAOPass = vtkSmartPointer<vtkFXSSAOPass>::New();
  this->OcclusionBlurPass = vtkSmartPointer<vtkFXBilateralBlurPass>::New();
  this->OcclusionBlurPass->SetInputConnection("source", "ssao.occlusion");
  this->SSAOPass->SetInputConnection("denoised", "ssao-blur.blurred");
  // The composite upsamples the half-resolution occlusion itself, by depth
  // (vtkFXSSAOPass::DepthAwareUpsample, the same joint-bilateral weights as
  // the blur's upsample pass): at 1280x720 that saves a full-resolution
  // pass and its texture.
  this->OcclusionBlurPass->UpsampleOff();
  this->ApplyAmbientOcclusionPreset();
  this->DirectionalOcclusionPass = vtkSmartPointer<vtkFXDirectionalOcclusionPass>::New();
  this->DirectionalOcclusionBlurPass = vtkSmartPointer<vtkFXBilateralBlurPass>::New();
  this->DirectionalOcclusionBlurPass->SetInputConnection("source", "do.occlusion");
  this->DirectionalOcclusionPass->SetInputConnection("denoised", "do-blur.blurred");
  this->DirectionalOcclusionBlurPass->SetNumberOfComponents(3);
  this->DirectionalOcclusionBlurPass->UpsampleOff();
  this->BleedingBlurPass = vtkSmartPointer<vtkFXBilateralBlurPass>::New();
  this->BleedingBlurPass->SetInputConnection("source", "do.bleeding");
  this->DirectionalOcclusionPass->SetInputConnection("bleeding-denoised", "do-bleed-blur.blurred");
  this->BleedingBlurPass->SetNumberOfComponents(3);
  this->BleedingBlurPass->UpsampleOff();

  this->GBufferPass->SetDelegatePass(this->OpaquePass);
  this->CompositePass->SetGBuffer(this->GBufferPass);
  this->HDRTargetPass->SetDelegatePass(this->HDRSequence);
  this->CameraPass->SetDelegatePass(this->Sequence);
}

vtkFXPipelinePass::~vtkFXPipelinePass()
{
  // VTK deletes a vertex array or a timer query in its own destructor, in
  // whichever context is current, and vtkRenderer::SetPass does not release
  // the pass it drops: a pipeline deleted while another window is current
  // would take that window's names (the vertex arrays of its full-screen
  // quads, its timers' queries). Released here, in the last window's own
  // context, first; effects someone else still holds keep theirs (they may
  // go on in another pipeline: an AVSM pass keeps the list buffer it grew).
  if (this->LastWindow)
  {
    // (the sequences and the composite would release or hold every effect
    // of the last frame: they let go of them here, and the effects are
    // released below as their owners say)
    this->Sequence->ClearPasses();
    this->HDRSequence->ClearPasses();
    this->CompositePass->RemoveAllContributors();
    this->Release(this->LastWindow, true);
  }
}

int vtkFXPipelinePass::OwnReferences(vtkFXEffectPass* effect) const
{
  int references = 0;
  for (const EffectSlot& slot : this->Effects)
  {
    references += slot.Effect == effect ? 1 : 0;
  }
  const vtkFXEffectPass* const members[] = { this->SSAOPass.Get(), this->OcclusionBlurPass.Get(),
    this->DirectionalOcclusionPass.Get(), this->DirectionalOcclusionBlurPass.Get(),
    this->BleedingBlurPass.Get() };
  for (const vtkFXEffectPass* member : members)
  {
    references += member == effect ? 1 : 0;
  }
  return references;
}

vtkFXGBufferPass* vtkFXPipelinePass::GetGBufferPass()
{
  return this->GBufferPass;
}

vtkFXCompositePass* vtkFXPipelinePass::GetCompositePass()
{
  return this->CompositePass;
}

vtkFXHDRTargetPass* vtkFXPipelinePass::GetHDRTargetPass()
{
  return this->HDRTargetPass;
}

vtkFXSceneInfo vtkFXPipelinePass::AnalyzeScene(const vtkRenderState* s) const
{
  vtkFXSceneInfo scene;
  scene.Renderer = s->GetRenderer();
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    AnalyzeProp(s->GetPropArray()[i], scene);
  }
  vtkPropCollection* viewProps = s->GetRenderer()->GetViewProps();
  vtkCollectionSimpleIterator viewIt;
  viewProps->InitTraversal(viewIt);
  while (vtkProp* prop = viewProps->GetNextProp(viewIt))
  {
    if (prop->GetVisibility() && prop->HasTranslucentPolygonalGeometry())
    {
      scene.TranslucentViewProps.push_back(prop);
    }
  }
  scene.KeepsLowerDepth = vtkFXRenderUtilities::KeepsEarlierDepth(s->GetRenderer());
  scene.PeelsVolumes =
    s->GetRenderer()->GetUseDepthPeeling() && s->GetRenderer()->GetUseDepthPeelingForVolumes();
  scene.UsesFXAA = s->GetRenderer()->GetUseFXAA();
  GLint sampleBuffers = 0;
  glGetIntegerv(GL_SAMPLE_BUFFERS, &sampleBuffers);
  scene.Multisampled = sampleBuffers != 0;
  scene.RemovesHiddenLines = s->GetRenderer()->GetUseHiddenLineRemoval() &&
    vtkHiddenLineRemovalPass::WireframePropsExist(
      scene.OpaqueProps.data(), static_cast<int>(scene.OpaqueProps.size()));
  // The lights pass ran before the analysis: read what VTK decided.
  vtkOpenGLRenderer* ren = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  if (ren && ren->GetLightingCount() > 0)
  {
    scene.LightingComplexity = ren->GetLightingComplexity();
    vtkCollectionSimpleIterator it;
    ren->GetLights()->InitTraversal(it);
    while (vtkLight* light = ren->GetLights()->GetNextLight(it))
    {
      if (light->GetSwitch() > 0)
      {
        scene.Lights.push_back(light);
      }
    }
  }
  return scene;
}

void vtkFXPipelinePass::WarnAboutNonFiniteLights(const vtkFXSceneInfo& scene)
{
  std::vector<int> places;
  for (size_t i = 0; i < scene.Lights.size(); ++i)
  {
    if (!vtkFXRenderUtilities::IsLightFinite(scene.Lights[i]))
    {
      places.push_back(static_cast<int>(i));
    }
  }
  // (when the set of such lights changes: not every frame)
  if (!places.empty() && places != this->NonFiniteLights)
  {
    std::ostringstream list;
    for (int place : places)
    {
      list << (place == places.front() ? "" : ", ") << place;
    }
    vtkWarningMacro("Light(s) " << list.str() << " (counting the lights that are on) have a "
                                   "position, focal point, colour x intensity, attenuation or "
                                   "(a spot light's) exponent that is NaN or infinite, also as "
                                   "a float: vtkFX's lighting and shadows leave them out.");
  }
  this->NonFiniteLights = places;
}

bool vtkFXPipelinePass::ResolveInputs(size_t consumer, std::vector<Connection>& connections)
{
  // Returns false when a required input cannot be resolved; problems go to
  // ScheduleProblems.
  vtkFXEffectPass* effect = this->Effects[consumer].Effect;
  const std::string& name = this->Effects[consumer].Name;
  connections.clear();
  bool complete = true;
  for (int i = 0; i < effect->GetNumberOfInputs(); ++i)
  {
    Connection c;
    c.Input = effect->GetInputName(i);
    c.Optional = effect->IsInputOptional(i);
    c.ReadInComposite = effect->IsInputReadInComposite(i);
    std::string producer;
    SplitConnection(effect->GetInputConnection(c.Input.c_str()), producer, c.Output);
    auto slot = std::find_if(this->Effects.begin(), this->Effects.end(),
      [&producer](const EffectSlot& s) { return s.Name == producer; });
    std::string problem;
    if (producer.empty())
    {
      problem = "input '" + c.Input + "' is not connected";
    }
    else if (slot == this->Effects.end())
    {
      problem = "input '" + c.Input + "' reads '" + producer + "', but no effect has that name";
    }
    else
    {
      c.Producer = static_cast<size_t>(slot - this->Effects.begin());
      if (c.Output.empty() && slot->Effect->GetNumberOfOutputs() > 0)
      {
        c.Output = slot->Effect->GetOutputName(0);
      }
      if (!slot->Effect->HasOutput(c.Output.c_str()))
      {
        problem = "input '" + c.Input + "' reads '" + producer + "." + c.Output + "', but " +
          slot->Effect->GetClassName() + " has no output '" + c.Output + "'";
      }
      else if (c.Producer == consumer)
      {
        problem = "input '" + c.Input + "' reads the effect's own output";
      }
    }
    if (problem.empty())
    {
      connections.push_back(c);
    }
    else if (!c.Optional || !producer.empty())
    {
      // An optional input stays unbound without a word when it is not
      // connected or its producer is not in the pipeline (a blur removed);
      // a wrong output name of an existing producer is a mistake to report.
      if (!c.Optional || slot != this->Effects.end())
      {
        this->ScheduleProblems += "'" + name + "': " + problem + "\n";
      }
      complete = complete && c.Optional;
    }
  }
  return complete;
}

std::vector<size_t> vtkFXPipelinePass::OrderEffects(const vtkFXSceneInfo& scene, bool deferred)
{
  const size_t n = this->Effects.size();
  std::vector<bool> candidate(n, false);
  std::vector<std::vector<Connection>> inputs(n);
  for (size_t i = 0; i < n; ++i)
  {
    vtkFXEffectPass* e = this->Effects[i].Effect;
    if (!e->GetEnabled() || !e->HasWork(scene))
    {
      continue;
    }
    // (after HasWork, from which the channels may follow) Effects that read
    // G-buffer channels, run between the G-buffer and the composite or only
    // add composite code need the G-buffer.
    const bool needsGBuffer = e->GetRequiredChannels() != 0 ||
      e->GetStage() == vtkFXEffectPass::AfterGBuffer ||
      e->GetStage() == vtkFXEffectPass::Composite;
    candidate[i] = (deferred || !needsGBuffer) && this->ResolveInputs(i, inputs[i]);
  }
  // Leave out consumers of producers that do not run (silently: no work is
  // no fault), and report inputs that come from a later stage, until
  // nothing changes; then order by stage and dependencies (Kahn's
  // algorithm, ties in the order added). Effects left over form a cycle.
  std::vector<size_t> order;
  std::string problems; // lines found in this loop, each kept once
  // Whether a connection's producer runs too late for it: after the
  // consumer's stage, or, for an input read in the composite, not before it.
  auto isLate = [this](const Connection& c, int consumerStage) {
    const int producerStage = this->Effects[c.Producer].Effect->GetStage();
    return c.ReadInComposite ? producerStage >= vtkFXEffectPass::Composite
                             : producerStage > consumerStage;
  };
  for (bool changed = true; changed;)
  {
    changed = false;
    for (size_t i = 0; i < n; ++i)
    {
      if (!candidate[i])
      {
        continue;
      }
      const int stage = this->Effects[i].Effect->GetStage();
      for (const Connection& c : inputs[i])
      {
        const int producerStage = this->Effects[c.Producer].Effect->GetStage();
        const bool late = isLate(c, stage);
        if (late && candidate[c.Producer])
        {
          problems += "'" + this->Effects[i].Name + "': input '" + c.Input +
            "' reads '" + this->Effects[c.Producer].Name + "', which runs at the " +
            vtkFXEffectPass::GetStageName(producerStage) + " stage, after " +
            (c.ReadInComposite ? std::string("the composite")
                               : std::string("the ") + vtkFXEffectPass::GetStageName(stage) +
                 " stage") +
            "\n";
        }
        if ((late || !candidate[c.Producer]) && !c.Optional)
        {
          candidate[i] = false;
          changed = true;
          break;
        }
      }
      // An optional input from a later stage stays unbound: it would read
      // the previous frame's output.
      inputs[i].erase(std::remove_if(inputs[i].begin(), inputs[i].end(),
                        [&](const Connection& c) { return isLate(c, stage); }),
        inputs[i].end());
    }
    if (changed)
    {
      continue;
    }
    order.clear();
    std::vector<bool> placed(n, false);
    for (bool progress = true; progress;)
    {
      progress = false;
      size_t best = n;
      for (size_t i = 0; i < n; ++i)
      {
        if (!candidate[i] || placed[i])
        {
          continue;
        }
        bool ready = true;
        for (const Connection& c : inputs[i])
        {
          ready = ready && (c.ReadInComposite || !candidate[c.Producer] || placed[c.Producer]);
        }
        if (ready &&
          (best == n ||
            this->Effects[i].Effect->GetStage() < this->Effects[best].Effect->GetStage()))
        {
          best = i;
        }
      }
      if (best < n)
      {
        placed[best] = true;
        order.push_back(best);
        progress = true;
      }
    }
    // Left unplaced: cycle members and what depends on them. Leave out the
    // members (an effect that reaches itself through unplaced producers);
    // the next round drops or unbinds their dependents.
    std::string cycle;
    std::vector<size_t> members;
    for (size_t i = 0; i < n; ++i)
    {
      if (candidate[i] && !placed[i] && this->ReachesItself(i, inputs, candidate, placed))
      {
        cycle += (cycle.empty() ? "'" : ", '") + this->Effects[i].Name + "'";
        members.push_back(i);
      }
    }
    for (size_t i : members)
    {
      candidate[i] = false;
      changed = true;
    }
    if (!cycle.empty())
    {
      problems += "effects " + cycle + " read each other's outputs in a cycle\n";
    }
  }
  // Each line once, however many rounds found it.
  std::istringstream lines(problems);
  for (std::string line; std::getline(lines, line);)
  {
    if (this->ScheduleProblems.find(line + "\n") == std::string::npos)
    {
      this->ScheduleProblems += line + "\n";
    }
  }
  // Bind each input to its producer, or unbind it when that one is out.
  for (size_t i = 0; i < n; ++i)
  {
    vtkFXEffectPass* e = this->Effects[i].Effect;
    for (int k = 0; k < e->GetNumberOfInputs(); ++k)
    {
      e->SetInputProducer(e->GetInputName(k), nullptr, nullptr);
    }
    for (const Connection& c : inputs[i])
    {
      if (candidate[i] && candidate[c.Producer])
      {
        e->SetInputProducer(c.Input.c_str(), this->Effects[c.Producer].Effect, c.Output.c_str());
      }
    }
  }
  return order;
}

bool vtkFXPipelinePass::ReachesItself(size_t start, const std::vector<std::vector<Connection>>& inputs,
  const std::vector<bool>& candidate, const std::vector<bool>& placed) const
{
  // Depth-first through the render-time producers that are still unplaced.
  std::vector<size_t> stack(1, start);
  std::vector<bool> seen(candidate.size(), false);
  while (!stack.empty())
  {
    const size_t i = stack.back();
    stack.pop_back();
    for (const Connection& c : inputs[i])
    {
      if (c.ReadInComposite || !candidate[c.Producer] || placed[c.Producer])
      {
        continue;
      }
      if (c.Producer == start)
      {
        return true;
      }
      if (!seen[c.Producer])
      {
        seen[c.Producer] = true;
        stack.push_back(c.Producer);
      }
    }
  }
  return false;
}

void vtkFXPipelinePass::ActivateEffects(const std::vector<size_t>& order, vtkWindow* window)
{
  this->ReleasePendingEffects(window);
  std::vector<bool> active(this->Effects.size(), false);
  for (size_t i : order)
  {
    active[i] = true;
  }
  for (size_t i = 0; i < this->Effects.size(); ++i)
  {
    EffectSlot& slot = this->Effects[i];
    // An effect that leaves the frame, or runs at another stage than last
    // frame, frees what it made: a toon pass whose lines go off becomes
    // composite code, and its Render, which would free the lines'
    // textures, no longer runs.
    const bool movedStage = slot.Active && active[i] && slot.Stage != slot.Effect->GetStage();
    if (slot.Active && (!active[i] || movedStage))
    {
      slot.Effect->ReleaseGraphicsResources(window);
    }
    slot.Active = active[i];
    slot.Stage = slot.Effect->GetStage();
    slot.Effect->SetGBuffer(active[i] && this->GBufferRan ? this->GBufferPass.Get() : nullptr);
  }
}

void vtkFXPipelinePass::AddEffectPasses(
  vtkFXTimedSequencePass* sequence, const std::vector<size_t>& order, int stage)
{
  for (size_t i : order)
  {
    vtkFXEffectPass* effect = this->Effects[i].Effect;
    if (effect->GetStage() == stage)
    {
      // (one that reads channels after the G-buffer has nothing to do in a
      // frame whose G-buffer could not be made)
      const bool reads = stage != vtkFXEffectPass::LightSpace && this->GBufferRan &&
        effect->GetRequiredChannels() != 0;
      sequence->AddPass(
        this->Effects[i].Name.c_str(), effect, reads ? this->GBufferPass.Get() : nullptr);
    }
  }
}

void vtkFXPipelinePass::ScheduleDeferredFrame(const vtkFXSceneInfo& scene, vtkWindow* window)
{
  using E = vtkFXEffectPass;
  this->Sequence->ClearPasses();
  this->HDRSequence->ClearPasses();
  // The bleeding's blur has work only while directional occlusion bleeds
  // (which needs a light).
  this->BleedingBlurPass->SetEnabled(
    this->DirectionalOcclusionPass->GetBleeding() > 0.0 && scene.LightingComplexity > 0);
  const bool deferred = !scene.OpaqueProps.empty();
  if (this->GBufferRan && !deferred)
  {
    // Nothing opaque any more: keep no G-buffer memory around.
    this->GBufferPass->ReleaseGraphicsResources(window);
    this->CompositePass->ReleaseGraphicsResources(window);
  }
  this->GBufferRan = deferred;

  const std::string previousProblems = this->ScheduleProblems;
  this->ScheduleProblems.clear();
  const std::vector<size_t> order = this->OrderEffects(scene, deferred);
  if (!this->ScheduleProblems.empty() && this->ScheduleProblems != previousProblems)
  {
    vtkErrorMacro("Effects left out of the frame:\n" << this->ScheduleProblems);
  }
  this->ActivateEffects(order, window);

  bool postProcess = false;   // a post-process effect needs the HDR target
  bool transmittance = false; // and one reads the lit surfaces' transmittance there
  for (size_t i : order)
  {
    E* effect = this->Effects[i].Effect;
    const bool inTarget = effect->GetStage() == E::PostProcess && effect->GetNeedsHDRTarget();
    postProcess = postProcess || inTarget;
    transmittance = transmittance || (inTarget && effect->GetReadsTransmittance());
  }
  if (this->HDRTargetRan && !postProcess)
  {
    this->HDRTargetPass->ReleaseGraphicsResources(window);
  }
  this->HDRTargetRan = postProcess;
  // (in a multisampled framebuffer FXAA stands in for the samples the
  // G-buffer does not have: MultisampleFXAA)
  const bool fxaa = scene.UsesFXAA || (this->MultisampleFXAA && deferred && scene.Multisampled);
  if (this->AntiAliasingRan && !fxaa)
  {
    this->AntiAliasingPass->ReleaseGraphicsResources(window);
  }
  this->AntiAliasingRan = fxaa;

  this->AddEffectPasses(this->Sequence, order, E::LightSpace);
  vtkFXCompositePass* composite = this->CompositePass;
  composite->RemoveAllContributors();
  if (deferred)
  {
    composite->SetDebugChannel(this->DebugChannel);
    composite->SetUseAmbient(scene.AnyAmbient);
    composite->SetUseSpecular(scene.AnySpecular);
    composite->SetUseEmission(scene.AnyEmissiveColor);
    composite->SetMarksTransmittance(transmittance);
    // (no prop the composite lights: no normal or depth for lighting)
    unsigned int channels =
      composite->GetRequiredChannels(scene.AnyLitProp ? scene.LightingComplexity : 0);
    bool geometric = false; // an effect samples the surfaces' own orientation
    for (size_t i : order)
    {
      channels |= this->Effects[i].Effect->GetRequiredChannels();
      geometric = geometric || this->Effects[i].Effect->GetReadsGeometricNormal();
      composite->AddContributor(this->Effects[i].Effect);
    }
    if (geometric && scene.AnyPerturbedNormal)
    {
      channels |= vtkFXGBufferPass::ChannelBit(vtkFXGBufferPass::GeometricNormal);
    }
    // The composite lights at the renderer's complexity wherever a normal
    // channel exists, also one only an effect or the debug view reads:
    // then it needs the depth positional lights read, lit props or not
    // (without it, it drew no opaque prop at all), and the emission of
    // pre-lit (PBR) props, which it keeps out of their occlusion; the
    // material channels no unlit pixel reads stay out.
    using GB = vtkFXGBufferPass;
    if (!scene.AnyLitProp && (channels & GB::ChannelBit(GB::Normal)))
    {
      channels |= composite->GetRequiredChannels(scene.LightingComplexity) &
        (GB::ChannelBit(GB::LinearDepth) | GB::ChannelBit(GB::Emission));
    }
    this->GBufferPass->SetRequiredChannels(channels);
    this->GBufferPass->SetHDREmission(scene.AnyEmissionAboveOne);
    this->GBufferPass->SetHDRMaterial(scene.LargestColor > 1.0);
    composite->SetMaterialColorScale(scene.LargestColor); // (clamped: inf becomes 65504)
    // (colour masked off, the hidden-line pass's depth-only draw leaves
    // every channel alone)
    vtkRenderPass* draw = scene.RemovesHiddenLines ? this->HiddenLinePass.Get()
                                                   : static_cast<vtkRenderPass*>(this->OpaquePass.Get());
    if (this->GBufferPass->GetDelegatePass() != draw)
    {
      this->GBufferPass->SetDelegatePass(draw);
    }
    this->Sequence->AddPass("gbuffer", this->GBufferPass);
    this->AddEffectPasses(this->Sequence, order, E::AfterGBuffer);
  }
  // With a post-process effect, the lit image and everything drawn onto it
  // go to the HDR target, which writes the framebuffer before the overlay.
  vtkFXTimedSequencePass* lit = postProcess ? this->HDRSequence : this->Sequence;
  if (deferred)
  {
    lit->AddPass("composite", composite, this->GBufferPass);
  }
  if (!scene.ForwardOpaqueProps.empty())
  {
    lit->AddPass("forward-opaque", this->ForwardOpaquePass);
  }
  // With depth peeling for volumes, VTK peels them with the translucent
  // geometry and skips its volume step (vtkRenderer::UpdateGeometry).
  const bool peeledVolumes = scene.PeelsVolumes && !scene.VolumeProps.empty();
  if (!scene.TranslucentProps.empty() || peeledVolumes)
  {
    this->TranslucentPass->RemoveAllForwardShadingEffects();
    for (size_t i : order)
    {
      if (this->Effects[i].Effect->GetShadesForward())
      {
        this->TranslucentPass->AddForwardShadingEffect(this->Effects[i].Effect);
      }
    }
    lit->AddPass("translucent", this->TranslucentPass);
  }
  if (!scene.VolumeProps.empty() && !peeledVolumes)
  {
    lit->AddPass("volumes", this->VolumetricPass);
  }
  this->AddEffectPasses(lit, order, E::PostProcess);
  if (postProcess)
  {
    this->HDRTargetPass->SetGBuffer(deferred ? this->GBufferPass.Get() : nullptr);
    this->Sequence->AddPass("hdr-target", this->HDRTargetPass);
  }
  if (fxaa)
  {
    this->Sequence->AddPass("fxaa", this->AntiAliasingPass);
  }
  if (!scene.OverlayProps.empty())
  {
    this->Sequence->AddPass("overlay", this->OverlayPass);
  }
}

void vtkFXPipelinePass::SetEffectGroup(
  bool enabled, const std::vector<std::pair<const char*, vtkFXEffectPass*>>& group)
{
  for (const auto& named : group)
  {
    if (enabled)
    {
      this->AddEffect(named.first, named.second);
    }
    else
    {
      this->RemoveEffect(named.first);
    }
  }
  this->Modified();
}

void vtkFXPipelinePass::SetAmbientOcclusion(bool enabled)
{
  if (enabled == this->AmbientOcclusion)
  {
    return;
  }
  this->AmbientOcclusion = enabled;
  if (enabled)
  {
    this->SetDirectionalOcclusion(false); // the pipeline runs one of the two
  }
  this->SetEffectGroup(
    enabled, { { "ssao", this->SSAOPass }, { "ssao-blur", this->OcclusionBlurPass } });
}

void vtkFXPipelinePass::SetDirectionalOcclusion(bool enabled)
{
  if (enabled == this->DirectionalOcclusion)
  {
    return;
  }
  this->DirectionalOcclusion = enabled;
  if (enabled)
  {
    this->SetAmbientOcclusion(false);
  }
  this->SetEffectGroup(enabled,
    { { "do", this->DirectionalOcclusionPass }, { "do-blur", this->DirectionalOcclusionBlurPass },
      { "do-bleed-blur", this->BleedingBlurPass } });
}

vtkFXDirectionalOcclusionPass* vtkFXPipelinePass::GetDirectionalOcclusionPass()
{
  return this->DirectionalOcclusionPass;
}

vtkFXBilateralBlurPass* vtkFXPipelinePass::GetDirectionalOcclusionBlurPass()
{
  return this->DirectionalOcclusionBlurPass;
}

void vtkFXPipelinePass::SetAmbientOcclusionQuality(int quality)
{
  if (quality < Low || quality > High)
  {
    vtkErrorMacro("Ambient occlusion quality " << quality
                                               << " is not Low (0), Medium (1) or High (2); "
                                                  "keeping "
                                               << this->AmbientOcclusionQuality << ".");
    return;
  }
  this->AmbientOcclusionQuality = quality;
  this->ApplyAmbientOcclusionPreset();
  this->Modified();
}

void vtkFXPipelinePass::SetAmbientOcclusionFalloff(int falloff)
{
  if (falloff != vtkFXSSAOPass::Binary && falloff != vtkFXSSAOPass::CubeRoot)
  {
    vtkErrorMacro("Ambient occlusion falloff " << falloff
                                               << " is not Binary (0) or CubeRoot (1); keeping "
                                               << this->SSAOPass->GetFalloff() << ".");
    return;
  }
  this->SSAOPass->SetFalloff(falloff);
  this->DirectionalOcclusionPass->SetFalloff(falloff);
  this->ApplyAmbientOcclusionPreset();
  this->Modified();
}

int vtkFXPipelinePass::GetAmbientOcclusionFalloff()
{
  return this->SSAOPass->GetFalloff();
}

void vtkFXPipelinePass::ApplyAmbientOcclusionPreset()
{
  // The settings vtkfx-bench ao measured best per definition (see the header).
  struct Preset
  {
    int Method, Samples;
    bool Half;
    int BlurRadius, BlurKernel;
  };
  using S = vtkFXSSAOPass;
  const int gauss = vtkFXBilateralBlurPass::Gaussian, box = vtkFXBilateralBlurPass::Box;
  static const Preset presets[2][3] = {
    { { S::Hemisphere, 8, true, 4, gauss }, { S::Horizon, 16, true, 4, gauss },
      { S::Horizon, 16, false, 2, box } },
    { { S::Hemisphere, 8, true, 4, gauss }, { S::Horizon, 8, true, 4, gauss },
      { S::Hemisphere, 16, true, 4, gauss } },
  };
  const Preset& p = presets[this->SSAOPass->GetFalloff() == S::CubeRoot ? 1 : 0]
                           [this->AmbientOcclusionQuality];
  this->SSAOPass->SetMethod(p.Method);
  this->SSAOPass->SetNumberOfSamples(p.Samples);
  this->SSAOPass->SetHalfResolution(p.Half);
  this->OcclusionBlurPass->SetRadius(p.BlurRadius);
  this->OcclusionBlurPass->SetKernel(p.BlurKernel);
  this->OcclusionBlurPass->EnabledOn();
}

vtkFXSSAOPass* vtkFXPipelinePass::GetSSAOPass()
{
  return this->SSAOPass;
}

vtkFXBilateralBlurPass* vtkFXPipelinePass::GetOcclusionBlurPass()
{
  return this->OcclusionBlurPass;
}

void vtkFXPipelinePass::AddEffect(const char* name, vtkFXEffectPass* effect)
{
  if (!name || !*name || !effect)
  {
    vtkErrorMacro("AddEffect needs a name and an effect.");
    return;
  }
  for (EffectSlot& slot : this->Effects)
  {
    if (slot.Name == name)
    {
      if (slot.Active && slot.Effect != effect)
      {
        this->ReleaseEffect(slot.Effect);
      }
      slot.Effect = effect;
      slot.Active = false;
      return;
    }
  }
  this->Effects.push_back({ name, effect, false });
}

void vtkFXPipelinePass::RemoveEffect(const char* name)
{
  for (EffectSlot& slot : this->Effects)
  {
    if (!name || slot.Name != name)
    {
      continue;
    }
    if (slot.Active)
    {
      this->ReleaseEffect(slot.Effect);
    }
    // Out of the pipeline, it keeps nothing of it: no G-buffer, no
    // producers, no place among the composite's contributors.
    slot.Effect->SetGBuffer(nullptr);
    for (int i = 0; i < slot.Effect->GetNumberOfInputs(); ++i)
    {
      slot.Effect->SetInputProducer(slot.Effect->GetInputName(i), nullptr, nullptr);
    }
    this->CompositePass->RemoveAllContributors();
  }
  this->Effects.erase(std::remove_if(this->Effects.begin(), this->Effects.end(),
                        [name](const EffectSlot& slot) { return name && slot.Name == name; }),
    this->Effects.end());
}

vtkFXEffectPass* vtkFXPipelinePass::GetEffect(const char* name)
{
  for (const EffectSlot& slot : this->Effects)
  {
    if (name && slot.Name == name)
    {
      return slot.Effect;
    }
  }
  return nullptr;
}

int vtkFXPipelinePass::GetNumberOfEffects() const
{
  return static_cast<int>(this->Effects.size());
}

const char* vtkFXPipelinePass::GetEffectName(int i) const
{
  return (i >= 0 && i < this->GetNumberOfEffects()) ? this->Effects[i].Name.c_str() : nullptr;
}

void vtkFXPipelinePass::ScheduleSelectionFrame()
{
  // What VTK's forward renderer does while a hardware selector renders:
  // lights, then the props drawn by the selector itself.
  this->Sequence->ClearPasses();
  this->Sequence->AddPass("selection-lights", this->LightsPass);
  this->Sequence->AddPass("selection", this->SelectionPass);
}

void vtkFXPipelinePass::UpdateCameraStereo(vtkRenderer* renderer)
{
  // VTK 9.1 gives the camera the window's stereo state (whether the
  // projection takes the eye's shear) in vtkOpenGLCamera::Render, which
  // vtkOpenGLRenderer calls only when no render pass is set: under a pass,
  // VTK's own included, both eyes would see the mono view. The camera's
  // Render also sets the viewport and clears as vtkCameraPass does after
  // it, so it runs only when the state changes. It does not mark the
  // camera modified, and VTK's mappers keep the matrices they took from an
  // unmodified camera: the first eye of a camera turned to stereo kept the
  // mono view (33 dB against VTK).
  vtkCamera* camera = renderer->GetActiveCamera();
  if (camera->GetStereo() != renderer->GetRenderWindow()->GetStereoRender())
  {
    camera->Render(renderer);
    camera->Modified();
  }
}

void vtkFXPipelinePass::Render(const vtkRenderState* s)
{
  vtkRenderer* renderer = s->GetRenderer();
  vtkRenderWindow* window = renderer->GetRenderWindow();
  const bool moved = this->LastWindow && this->LastWindow != window;
  if (moved)
  {
    // GL objects belong to one context (framebuffers and vertex arrays are
    // never shared): moved to another window, the pipeline starts afresh.
    this->ReleaseGraphicsResources(this->LastWindow);
    window->MakeCurrent();
    ++this->WindowChanges;
  }
  // (a renderer of another window: a move, once; back and forth, sharing)
  const bool shared = moved ? this->WindowChanges > 1
                            : this->LastRenderer && this->LastRenderer != renderer;
  if (shared && !this->WarnedSharedPipeline)
  {
    vtkWarningMacro("This vtkFXPipelinePass renders for more than one renderer: its buffers "
                    "follow the last one, so each render reallocates them. Give each renderer "
                    "a pipeline of its own.");
    this->WarnedSharedPipeline = true;
  }
  this->LastRenderer = renderer;
  this->LastWindow = window;
  const bool selecting = s->GetRenderer()->GetSelector() != nullptr;
  if (selecting)
  {
    this->ScheduleSelectionFrame();
  }
  else
  {
    // VTK decides the lighting complexity while it updates the lights; the
    // channels the composite reads depend on it, so this comes first.
    this->LightsPass->Render(s);
    this->LastScene = this->AnalyzeScene(s);
    this->WarnAboutNonFiniteLights(this->LastScene);
    this->ScheduleDeferredFrame(this->LastScene, s->GetRenderer()->GetRenderWindow());
  }
  UpdateCameraStereo(renderer);
  this->CameraPass->Render(s);
  this->NumberOfRenderedProps = this->CameraPass->GetNumberOfRenderedProps();
  this->LastPasses.clear();
  for (const std::string& name : this->Sequence->GetPassesThatRan())
  {
    this->LastPasses.push_back(name);
    if (name == "hdr-target")
    {
      // What ran inside the HDR target follows it.
      for (const std::string& inner : this->HDRSequence->GetPassesThatRan())
      {
        this->LastPasses.push_back(inner);
      }
    }
  }
  if (!selecting)
  {
    // The lights were updated before the camera pass, outside the sequence.
    this->LastPasses.insert(this->LastPasses.begin(), "lights");
  }
}

int vtkFXPipelinePass::GetNumberOfPassesThatRan() const
{
  return static_cast<int>(this->LastPasses.size());
}

const char* vtkFXPipelinePass::GetPassThatRan(int i) const
{
  if (i < 0 || i >= static_cast<int>(this->LastPasses.size()))
  {
    return nullptr;
  }
  return this->LastPasses[i].c_str();
}

double vtkFXPipelinePass::GetPassMilliseconds(const char* name)
{
  // Ask the sequence that ran the pass in the last frame: a pass moves into
  // the HDR target's sequence and back as post-process effects come and go.
  const auto& inner = this->HDRSequence->GetPassesThatRan();
  const bool insideTarget =
    this->HDRTargetRan && name && std::find(inner.begin(), inner.end(), name) != inner.end();
  return (insideTarget ? this->HDRSequence : this->Sequence)->GetPassMilliseconds(name);
}

int vtkFXPipelinePass::GetGBufferBytesPerPixel() const
{
  return this->GBufferRan ? this->GBufferPass->GetBytesPerPixel() : 0;
}

int vtkFXPipelinePass::GetHDRTargetBytesPerPixel() const
{
  return this->HDRTargetRan ? this->HDRTargetPass->GetBytesPerPixel() : 0;
}

unsigned int vtkFXPipelinePass::GetGBufferChannels() const
{
  return this->GBufferRan ? this->GBufferPass->GetAllocatedChannels() : 0u;
}

void vtkFXPipelinePass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Release(w, false);
}

void vtkFXPipelinePass::ReleaseEffect(vtkFXEffectPass* effect)
{
  // In the context of the window it drew in, as Release does (called from
  // an application's controls, another window's context may be current);
  // a window whose context is gone took the effect's objects with it.
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(this->LastWindow);
  if (!window)
  {
    return;
  }
  window->PushContext();
  if (window->IsCurrent())
  {
    effect->ReleaseGraphicsResources(window);
  }
  else
  {
    // (no context now, say a Qt window outside its paint: freed at the
    // next frame, or with the pipeline's resources)
    this->PendingReleases.push_back(effect);
  }
  window->PopContext();
}

void vtkFXPipelinePass::ReleasePendingEffects(vtkWindow* window)
{
  for (vtkFXEffectPass* effect : this->PendingReleases)
  {
    effect->ReleaseGraphicsResources(window);
  }
  this->PendingReleases.clear();
}

void vtkFXPipelinePass::Release(vtkWindow* w, bool keepSharedEffects)
{
  // GL deletes names in whichever context is current: called with another
  // window's current (an application with several windows releasing one),
  // the passes below would delete that window's textures and buffers of the
  // same names, and it would crash drawing with them later. (X windows get
  // the other context back; VTK's generic, EGL and OSMesa windows have no
  // context stack and leave this one current.)
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(w);
  if (window)
  {
    window->PushContext();
    if (keepSharedEffects && !window->IsCurrent())
    {
      // (a deleted pipeline whose window has lost its context, Finalize
      // called: nothing of it is left to free, and GL calls would reach
      // another context or none)
      window->PopContext();
      return;
    }
  }
  this->ReleasePendingEffects(w);
  // The sequence only holds the passes of the last frame: release them all.
  this->CameraPass->ReleaseGraphicsResources(w);
  this->LightsPass->ReleaseGraphicsResources(w);
  this->GBufferPass->ReleaseGraphicsResources(w);
  this->CompositePass->ReleaseGraphicsResources(w);
  this->HDRTargetPass->ReleaseGraphicsResources(w);
  this->TranslucentPass->ReleaseGraphicsResources(w);
  this->VolumetricPass->ReleaseGraphicsResources(w);
  this->OverlayPass->ReleaseGraphicsResources(w);
  this->AntiAliasingPass->ReleaseGraphicsResources(w);
  this->AntiAliasingRan = false;
  for (EffectSlot& slot : this->Effects)
  {
    if (!keepSharedEffects || slot.Effect->GetReferenceCount() <= this->OwnReferences(slot.Effect))
    {
      slot.Effect->ReleaseGraphicsResources(w);
    }
    slot.Active = false;
  }
  if (window)
  {
    window->PopContext();
  }
}

void vtkFXPipelinePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DebugChannel: " << this->DebugChannel << "\n";
  os << indent << "MultisampleFXAA: " << this->MultisampleFXAA << "\n";
  os << indent << "AmbientOcclusion: " << this->AmbientOcclusion << "\n";
  os << indent << "DirectionalOcclusion: " << this->DirectionalOcclusion << "\n";
  os << indent << "AmbientOcclusionQuality: " << this->AmbientOcclusionQuality << "\n";
  os << indent << "Effects: " << this->Effects.size() << "\n";
  for (const EffectSlot& slot : this->Effects)
  {
    os << indent.GetNextIndent() << slot.Name << ": " << slot.Effect->GetClassName() << ", "
       << vtkFXEffectPass::GetStageName(slot.Effect->GetStage()) << " stage, "
       << (slot.Effect->GetEnabled() ? "enabled" : "disabled")
       << (slot.Active ? ", ran in the last frame" : "") << "\n";
    for (int i = 0; i < slot.Effect->GetNumberOfInputs(); ++i)
    {
      const char* input = slot.Effect->GetInputName(i);
      const char* connection = slot.Effect->GetInputConnection(input);
      os << indent.GetNextIndent().GetNextIndent() << "input " << input << " <- "
         << (connection && *connection ? connection : "(not connected)") << "\n";
    }
  }
  os << indent << "ScheduleProblems: "
     << (this->ScheduleProblems.empty() ? "none" : this->ScheduleProblems) << "\n";
  os << indent << "Passes that ran:";
  for (const auto& name : this->LastPasses)
  {
    os << " " << name;
  }
  os << "\n";
  os << indent << "GBufferBytesPerPixel: " << this->GetGBufferBytesPerPixel() << "\n";
  os << indent << "HDRTargetBytesPerPixel: " << this->GetHDRTargetBytesPerPixel() << "\n";
}
