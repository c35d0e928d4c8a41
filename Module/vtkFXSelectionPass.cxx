#include "vtkFXSelectionPass.h"

#include "vtkHardwareSelector.h"
#include "vtkObjectFactory.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"

vtkStandardNewMacro(vtkFXSelectionPass);

void vtkFXSelectionPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  vtkRenderer* ren = s->GetRenderer();
  vtkHardwareSelector* selector = ren->GetSelector();
  if (selector && s->GetPropArrayCount() > 0)
  {
    // What vtkRenderer::UpdateGeometry does while a selector renders.
    this->NumberOfRenderedProps =
      selector->Render(ren, s->GetPropArray(), s->GetPropArrayCount());
  }
}
