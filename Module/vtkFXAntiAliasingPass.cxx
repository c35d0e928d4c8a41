#include "vtkFXAntiAliasingPass.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLFXAAFilter.h"
#include "vtkOpenGLRenderer.h"
#include "vtkRenderState.h"

vtkStandardNewMacro(vtkFXAntiAliasingPass);

vtkFXAntiAliasingPass::vtkFXAntiAliasingPass()
  : Filter(vtkSmartPointer<vtkOpenGLFXAAFilter>::New())
{
}

vtkFXAntiAliasingPass::~vtkFXAntiAliasingPass() = default;

void vtkFXAntiAliasingPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  vtkOpenGLRenderer* renderer = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  if (!renderer)
  {
    return;
  }
  // (as vtkRenderer::UpdateGeometry configures its own filter)
  if (renderer->GetFXAAOptions())
  {
    this->Filter->UpdateConfiguration(renderer->GetFXAAOptions());
  }
  this->Filter->Execute(renderer);
}

void vtkFXAntiAliasingPass::ReleaseGraphicsResources(vtkWindow*)
{
  this->Filter->ReleaseGraphicsResources();
}
