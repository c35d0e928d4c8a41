#include "vtkFXPipelinePass.h"

#include "vtkFXCompositePass.h"
#include "vtkFXEffectPass.h"
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
double MaxComponent(const double c[3])
{
  return std::max(c[0], std::max(c[1], c[2]));
}

// Adds what one leaf prop contributes to the scene summary.
void AnalyzeLeaf(vtkProp* prop, vtkFXPipelinePass::SceneInfo& scene)
{
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
  ++scene.OpaqueProps;
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  if (!actor)
  {
    // A prop whose material we cannot read: assume it uses every term.
    scene.AnyAmbient = scene.AnySpecular = scene.AnyUnlit = true;
    return;
  }
  vtkProperty* p = actor->GetProperty();
  if (!p->GetLighting())
  {
    scene.AnyUnlit = true;
    return;
  }
  if (p->GetAmbient() > 0.0 && MaxComponent(p->GetAmbientColor()) > 0.0)
  {
    scene.AnyAmbient = true;
  }
  if (p->GetSpecular() > 0.0 && MaxComponent(p->GetSpecularColor()) > 0.0)
  {
    scene.AnySpecular = true;
  }
}

// The light complexity vtkOpenGLRenderer::UpdateLights will compute in the
// lights pass of this frame (VTK 9.1 rules: any light that is not a headlight
// or a second light on makes it 2, any positional light, even one switched
// off, makes it 3; with no light on, one is created automatically).
int PredictLightingComplexity(vtkRenderer* ren, int& lightsOn)
{
  int complexity = 0;
  lightsOn = 0;
  vtkLightCollection* lights = ren->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    if (light->GetSwitch() > 0)
    {
      ++lightsOn;
      complexity = std::max(complexity, 1);
    }
    if (complexity == 1 && (lightsOn > 1 || light->GetLightType() != VTK_LIGHT_TYPE_HEADLIGHT))
    {
      complexity = 2;
    }
    if (complexity < 3 && light->GetPositional())
    {
      complexity = 3;
    }
  }
  if (lightsOn == 0 && ren->GetAutomaticLightCreation())
  {
    lightsOn = 1;
    complexity = 1; // VTK creates a headlight
  }
  return complexity;
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
  this->SelectionPass = vtkSmartPointer<vtkFXSelectionPass>::New();

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
    vtkProp* prop = s->GetPropArray()[i];
    if (!prop->IsA("vtkActor") && !prop->IsA("vtkVolume") && !prop->IsA("vtkAssembly"))
    {
      // 2D actors, widgets' representations and other props may draw overlays.
      ++scene.OverlayProps;
    }
    // Assemblies hold their parts as paths; analyse each leaf.
    prop->InitPathTraversal();
    bool anyLeaf = false;
    while (vtkAssemblyPath* path = prop->GetNextPath())
    {
      vtkProp* leaf = path->GetLastNode()->GetViewProp();
      if (leaf && leaf != prop)
      {
        anyLeaf = true;
        AnalyzeLeaf(leaf, scene);
      }
    }
    if (!anyLeaf)
    {
      AnalyzeLeaf(prop, scene);
    }
  }
  scene.LightingComplexity = PredictLightingComplexity(s->GetRenderer(), scene.LightsOn);
  return scene;
}

void vtkFXPipelinePass::ScheduleDeferredFrame(const SceneInfo& scene, vtkWindow* window)
{
  this->Sequence->ClearPasses();
  this->Sequence->AddPass("lights", this->LightsPass);
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
    composite->SetUseEmission(false);
    unsigned int channels = composite->GetRequiredChannels(scene.LightingComplexity);
    for (EffectSlot& slot : this->Effects)
    {
      const bool active =
        slot.Effect->GetEnabled() && slot.Effect->HasWork(scene.OpaqueProps, scene.TranslucentProps);
      if (slot.Active && !active)
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
  if (s->GetRenderer()->GetSelector())
  {
    this->ScheduleSelectionFrame();
  }
  else
  {
    this->LastScene = this->AnalyzeScene(s);
    this->ScheduleDeferredFrame(this->LastScene, s->GetRenderer()->GetRenderWindow());
  }
  this->CameraPass->Render(s);
  this->NumberOfRenderedProps = this->CameraPass->GetNumberOfRenderedProps();
  this->LastPasses = this->Sequence->GetPassesThatRan();
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
  os << indent << "Passes that ran:";
  for (const auto& name : this->LastPasses)
  {
    os << " " << name;
  }
  os << "\n";
  os << indent << "GBufferBytesPerPixel: " << this->GetGBufferBytesPerPixel() << "\n";
}
