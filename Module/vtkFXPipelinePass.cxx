#include "vtkFXPipelinePass.h"

#include "vtkFXBilateralBlurPass.h"
#include "vtkFXCompositePass.h"
#include "vtkFXSSAOPass.h"
#include "vtkFXEffectPass.h"
#include "vtkFXForwardOpaquePass.h"
#include "vtkFXGBufferPass.h"
#include "vtkFXSelectionPass.h"
#include "vtkFXTimedSequencePass.h"
#include "vtkFXTranslucentPass.h"

#include "vtkActor.h"
#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkCameraPass.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLightsPass.h"
#include "vtkObjectFactory.h"
#include "vtkOpaquePass.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOverlayPass.h"
#include "vtkProp.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumetricPass.h"

#include <algorithm>

vtkStandardNewMacro(vtkFXPipelinePass);

namespace
{
// Records which optional material terms an actor's shaders will produce.
// Besides Ambient > 0, VTK 9.1 puts colour into the ambient term for
// surface edges (the edge colour, unscaled) and for vertices (intensity
// forced to 1), and a backface property has its own terms.
void AddMaterialTerms(vtkActor* actor, vtkFXPipelinePass::SceneInfo& scene)
{
  for (vtkProperty* p : { actor->GetProperty(), actor->GetBackfaceProperty() })
  {
    if (!p || !p->GetLighting())
    {
      continue;
    }
    if (p->GetAmbient() > 0.0 || p->GetEdgeVisibility() || p->GetVertexVisibility())
    {
      scene.AnyAmbient = true;
    }
    if (p->GetSpecular() > 0.0)
    {
      scene.AnySpecular = true;
    }
  }
}

// Adds one prop of the renderer to the scene summary.
void AnalyzeProp(vtkProp* prop, vtkFXPipelinePass::SceneInfo& scene)
{
  if (prop->IsA("vtkActor2D"))
  {
    // 2D props draw in the overlay step, but VTK calls their opaque step
    // too (text actors build their texture there): that is forward work,
    // not a reason to run the G-buffer.
    ++scene.OverlayProps;
    scene.ForwardOpaqueProps += prop->HasOpaqueGeometry() ? 1 : 0;
    return;
  }
  if (!prop->IsA("vtkActor") && !prop->IsA("vtkVolume") && !prop->IsA("vtkAssembly"))
  {
    // Widgets' representations and other props may draw overlays too.
    ++scene.OverlayProps;
  }
  if (prop->IsA("vtkVolume"))
  {
    ++scene.VolumeProps;
    return;
  }
  if (prop->HasTranslucentPolygonalGeometry())
  {
    ++scene.TranslucentProps;
  }
  if (!prop->HasOpaqueGeometry())
  {
    return;
  }
  if (!vtkFXGBufferPass::CanCapture(prop))
  {
    ++scene.ForwardOpaqueProps;
    return;
  }
  ++scene.OpaqueProps;
  // Assemblies hold their actors as paths; a plain actor is its own path.
  prop->InitPathTraversal();
  while (vtkAssemblyPath* path = prop->GetNextPath())
  {
    if (vtkActor* actor = vtkActor::SafeDownCast(path->GetLastNode()->GetViewProp()))
    {
      AddMaterialTerms(actor, scene);
    }
  }
}
}

vtkFXPipelinePass::vtkFXPipelinePass()
{
  this->CameraPass = vtkSmartPointer<vtkCameraPass>::New();
  this->Sequence = vtkSmartPointer<vtkFXTimedSequencePass>::New();
  this->LightsPass = vtkSmartPointer<vtkLightsPass>::New();
  this->OpaquePass = vtkSmartPointer<vtkOpaquePass>::New();
  this->GBufferPass = vtkSmartPointer<vtkFXGBufferPass>::New();
  this->CompositePass = vtkSmartPointer<vtkFXCompositePass>::New();
  this->TranslucentPass = vtkSmartPointer<vtkFXTranslucentPass>::New();
  this->VolumetricPass = vtkSmartPointer<vtkVolumetricPass>::New();
  this->OverlayPass = vtkSmartPointer<vtkOverlayPass>::New();
  this->ForwardOpaquePass = vtkSmartPointer<vtkFXForwardOpaquePass>::New();
  this->SelectionPass = vtkSmartPointer<vtkFXSelectionPass>::New();

  this->SSAOPass = vtkSmartPointer<vtkFXSSAOPass>::New();
  this->OcclusionBlurPass = vtkSmartPointer<vtkFXBilateralBlurPass>::New();
  this->OcclusionBlurPass->SetInputEffect(this->SSAOPass);
  // The composite samples the half-resolution occlusion bilinearly: at
  // 1280x720 that saves a full-resolution pass, and the depth-aware upsample
  // measured no better against the ray-traced reference (vtkfx-bench ao).
  this->OcclusionBlurPass->UpsampleOff();

  this->GBufferPass->SetDelegatePass(this->OpaquePass);
  this->CompositePass->SetGBuffer(this->GBufferPass);
  this->CameraPass->SetDelegatePass(this->Sequence);
}

vtkFXPipelinePass::~vtkFXPipelinePass() = default;

vtkFXGBufferPass* vtkFXPipelinePass::GetGBufferPass()
{
  return this->GBufferPass;
}

vtkFXCompositePass* vtkFXPipelinePass::GetCompositePass()
{
  return this->CompositePass;
}

vtkFXPipelinePass::SceneInfo vtkFXPipelinePass::AnalyzeScene(const vtkRenderState* s) const
{
  SceneInfo scene;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    AnalyzeProp(s->GetPropArray()[i], scene);
  }
  // The lights pass ran before the analysis: read what VTK decided.
  vtkOpenGLRenderer* ren = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  scene.LightsOn = ren ? ren->GetLightingCount() : 0;
  scene.LightingComplexity = scene.LightsOn > 0 ? ren->GetLightingComplexity() : 0;
  return scene;
}

void vtkFXPipelinePass::ScheduleDeferredFrame(const SceneInfo& scene, vtkWindow* window)
{
  this->Sequence->ClearPasses();
  const bool deferred = scene.OpaqueProps > 0;
  if (this->GBufferRan && !deferred)
  {
    // Nothing opaque any more: keep no G-buffer memory around.
    this->GBufferPass->ReleaseGraphicsResources(window);
  }
  this->GBufferRan = deferred;
  if (this->GBufferRan)
  {
    vtkFXCompositePass* composite = this->CompositePass;
    composite->SetDebugChannel(this->DebugChannel);
    composite->SetUseAmbient(scene.AnyAmbient);
    composite->SetUseSpecular(scene.AnySpecular);
    unsigned int channels = composite->GetRequiredChannels(scene.LightingComplexity);
    std::vector<bool> wasActive;
    for (EffectSlot& slot : this->Effects)
    {
      wasActive.push_back(slot.Active);
      slot.Active = false;
    }
    for (size_t i = 0; i < this->Effects.size(); ++i)
    {
      EffectSlot& slot = this->Effects[i];
      // An effect that reads another's output runs only if that one runs
      // earlier in this frame (slots run in the order they were added).
      vtkFXEffectPass* input = slot.Effect->GetInputEffect();
      const bool active = slot.Effect->GetEnabled() &&
        slot.Effect->HasWork(scene.OpaqueProps, scene.TranslucentProps) &&
        (!input || this->RanEffect(input));
      if (wasActive[i] && !active)
      {
        slot.Effect->ReleaseGraphicsResources(window);
      }
      slot.Active = active;
      if (active)
      {
        channels |= slot.Effect->GetRequiredChannels();
        slot.Effect->SetGBuffer(this->GBufferPass);
      }
    }
    this->GBufferPass->SetRequiredChannels(channels);
    // Occlusion for the composite: the blurred result when the blur runs.
    vtkFXEffectPass* occlusion = nullptr;
    if (this->AmbientOcclusion && this->RanEffect(this->SSAOPass))
    {
      occlusion = this->RanEffect(this->OcclusionBlurPass)
        ? static_cast<vtkFXEffectPass*>(this->OcclusionBlurPass)
        : this->SSAOPass;
    }
    composite->SetOcclusionEffect(occlusion);
    this->Sequence->AddPass("gbuffer", this->GBufferPass);
    this->ScheduleEffects(vtkFXEffectPass::AfterGBuffer);
    this->Sequence->AddPass("composite", composite);
    this->ScheduleEffects(vtkFXEffectPass::AfterComposite);
  }
  else
  {
    // Effects read the G-buffer: without opaque props none of them runs.
    for (EffectSlot& slot : this->Effects)
    {
      if (slot.Active)
      {
        slot.Effect->ReleaseGraphicsResources(window);
      }
      slot.Active = false;
    }
  }
  if (scene.ForwardOpaqueProps > 0)
  {
    this->Sequence->AddPass("forward-opaque", this->ForwardOpaquePass);
  }
  if (scene.TranslucentProps > 0)
  {
    this->Sequence->AddPass("translucent", this->TranslucentPass);
  }
  if (scene.VolumeProps > 0)
  {
    this->Sequence->AddPass("volumes", this->VolumetricPass);
  }
  if (scene.OverlayProps > 0)
  {
    this->Sequence->AddPass("overlay", this->OverlayPass);
  }
}

void vtkFXPipelinePass::ScheduleEffects(int stage)
{
  for (const EffectSlot& slot : this->Effects)
  {
    if (slot.Active && slot.Effect->GetStage() == stage)
    {
      this->Sequence->AddPass(slot.Name.c_str(), slot.Effect);
    }
  }
}

bool vtkFXPipelinePass::RanEffect(vtkFXEffectPass* effect) const
{
  for (const EffectSlot& slot : this->Effects)
  {
    if (slot.Effect == effect)
    {
      return slot.Active;
    }
  }
  return false;
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
    this->AddEffect("ssao", this->SSAOPass);
    this->AddEffect("ssao-blur", this->OcclusionBlurPass);
  }
  else
  {
    this->RemoveEffect("ssao");
    this->RemoveEffect("ssao-blur");
    this->CompositePass->SetOcclusionEffect(nullptr);
  }
  this->Modified();
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
      if (slot.Active && this->LastWindow && slot.Effect != effect)
      {
        slot.Effect->ReleaseGraphicsResources(this->LastWindow);
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
    if (name && slot.Name == name && slot.Active && this->LastWindow)
    {
      slot.Effect->ReleaseGraphicsResources(this->LastWindow);
    }
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

void vtkFXPipelinePass::ScheduleSelectionFrame()
{
  // What VTK's forward renderer does while a hardware selector renders:
  // lights, then the props drawn by the selector itself.
  this->Sequence->ClearPasses();
  this->Sequence->AddPass("selection-lights", this->LightsPass);
  this->Sequence->AddPass("selection", this->SelectionPass);
}

void vtkFXPipelinePass::Render(const vtkRenderState* s)
{
  this->LastWindow = s->GetRenderer()->GetRenderWindow();
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
    this->ScheduleDeferredFrame(this->LastScene, s->GetRenderer()->GetRenderWindow());
  }
  this->CameraPass->Render(s);
  this->NumberOfRenderedProps = this->CameraPass->GetNumberOfRenderedProps();
  this->LastPasses = this->Sequence->GetPassesThatRan();
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
  return this->Sequence->GetPassMilliseconds(name);
}

int vtkFXPipelinePass::GetGBufferBytesPerPixel() const
{
  return this->GBufferRan ? this->GBufferPass->GetBytesPerPixel() : 0;
}

unsigned int vtkFXPipelinePass::GetGBufferChannels() const
{
  return this->GBufferRan ? this->GBufferPass->GetAllocatedChannels() : 0u;
}

void vtkFXPipelinePass::ReleaseGraphicsResources(vtkWindow* w)
{
  // The sequence only holds the passes of the last frame: release them all.
  this->CameraPass->ReleaseGraphicsResources(w);
  this->LightsPass->ReleaseGraphicsResources(w);
  this->GBufferPass->ReleaseGraphicsResources(w);
  this->CompositePass->ReleaseGraphicsResources(w);
  this->TranslucentPass->ReleaseGraphicsResources(w);
  this->VolumetricPass->ReleaseGraphicsResources(w);
  this->OverlayPass->ReleaseGraphicsResources(w);
  for (EffectSlot& slot : this->Effects)
  {
    slot.Effect->ReleaseGraphicsResources(w);
    slot.Active = false;
  }
}

void vtkFXPipelinePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DebugChannel: " << this->DebugChannel << "\n";
  os << indent << "AmbientOcclusion: " << this->AmbientOcclusion << "\n";
  os << indent << "Passes that ran:";
  for (const auto& name : this->LastPasses)
  {
    os << " " << name;
  }
  os << "\n";
  os << indent << "GBufferBytesPerPixel: " << this->GetGBufferBytesPerPixel() << "\n";
}
