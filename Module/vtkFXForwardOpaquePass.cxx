#include "vtkFXForwardOpaquePass.h"

#include "vtkFXGBufferPass.h"

#include "vtkObjectFactory.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"

vtkStandardNewMacro(vtkFXForwardOpaquePass);

void vtkFXForwardOpaquePass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    if (!vtkFXGBufferPass::CanCapture(prop))
    {
      this->NumberOfRenderedProps += prop->RenderOpaqueGeometry(s->GetRenderer());
    }
  }
}
