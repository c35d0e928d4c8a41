#include "vtkFXAntiAliasingPass.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLFXAAFilter.h"
#include "vtkOpenGLRenderer.h"
#include "vtkRenderState.h"

vtkStandardNewMacro(vtkFXAntiAliasingPass);

vtkFXAntiAliasingPass::vtkFXAntiAliasingPass() = default;

vtkFXAntiAliasingPass::~vtkFXAntiAliasingPass() = default;

void vtkFXAntiAliasingPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  vtkOpenGLRenderer* renderer = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  if (!renderer)
  {
    return;
  }
  if (!this->Filter)
  {
    this->Filter = vtkSmartPointer<vtkOpenGLFXAAFilter>::New();
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
  if (this->Filter)
  {
    this->Filter->ReleaseGraphicsResources();
  }
}
