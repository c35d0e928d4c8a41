#include "vtkFXTranslucentPass.h"

#include "vtkFXEffectPass.h"

#include "vtkObjectFactory.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"

vtkStandardNewMacro(vtkFXTranslucentPass);

void vtkFXTranslucentPass::AddForwardShadingEffect(vtkFXEffectPass* effect)
{
  if (effect)
  {
    this->ForwardShadingEffects.emplace_back(effect);
  }
}

void vtkFXTranslucentPass::RemoveAllForwardShadingEffects()
{
  this->ForwardShadingEffects.clear();
}

void vtkFXTranslucentPass::Render(const vtkRenderState* s)
{
  for (const auto& effect : this->ForwardShadingEffects)
  {
    if (effect)
    {
      effect->BeginForwardShading(s);
    }
  }
  vtkRenderer* ren = s->GetRenderer();
  const int before = ren->GetNumberOfPropsRendered();
  ren->DeviceRenderTranslucentPolygonalGeometry(s->GetFrameBuffer());
  this->NumberOfRenderedProps = ren->GetNumberOfPropsRendered() - before;
  for (const auto& effect : this->ForwardShadingEffects)
  {
    if (effect)
    {
      effect->EndForwardShading(s);
    }
  }
}
