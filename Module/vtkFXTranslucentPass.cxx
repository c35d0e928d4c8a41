#include "vtkFXTranslucentPass.h"

#include "vtkObjectFactory.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"

vtkStandardNewMacro(vtkFXTranslucentPass);

void vtkFXTranslucentPass::Render(const vtkRenderState* s)
{
  vtkRenderer* ren = s->GetRenderer();
  const int before = ren->GetNumberOfPropsRendered();
  ren->DeviceRenderTranslucentPolygonalGeometry(s->GetFrameBuffer());
  this->NumberOfRenderedProps = ren->GetNumberOfPropsRendered() - before;
}
