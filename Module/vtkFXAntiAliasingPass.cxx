#include "vtkFXAntiAliasingPass.h"

#include "vtkFXOpenGL.h"
#include "vtkFXRenderUtilities.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFXAAFilter.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLState.h"
#include "vtkRenderState.h"
#include "vtkTextureObject.h"

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
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  vtkOpenGLState* state = window->GetState();
  state->PushReadFramebufferBinding();
  if (!this->ResolveForReading(renderer, window))
  {
    vtkFXRenderUtilities::Release(this->Resolved, window);
    vtkFXRenderUtilities::Release(this->ResolveFrameBuffer, window);
  }
  this->Filter->Execute(renderer);
  state->PopReadFramebufferBinding();
}

bool vtkFXAntiAliasingPass::ResolveForReading(vtkRenderer* renderer, vtkOpenGLRenderWindow* window)
{
  GLint sampleBuffers = 0, source = 0;
  glGetIntegerv(GL_SAMPLE_BUFFERS, &sampleBuffers);
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &source);
  if (sampleBuffers == 0)
  {
    return false;
  }
  // The filter reads its input at the viewport's place: the copy reaches
  // to the viewport's far corner, and the blit keeps every pixel where it is.
  int size[2], origin[2];
  renderer->GetTiledSizeAndOrigin(&size[0], &size[1], &origin[0], &origin[1]);
  const int corner[2] = { origin[0] + size[0], origin[1] + size[1] };
  vtkFXRenderUtilities::EnsureTexture(
    this->Resolved, window, corner[0], corner[1], vtkFXRenderUtilities::RGBA8);
  // (what earlier steps left is not the blit's refusal)
  vtkFXRenderUtilities::ClearPendingErrors(this, "vtkFX's FXAA resolve", this->WarnedEarlierError);
  {
    vtkFXRenderUtilities::RenderTargetScope target(window, this->ResolveFrameBuffer, this->Resolved);
    if (!target.IsComplete())
    {
      return false;
    }
    window->GetState()->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(source));
    glBlitFramebuffer(origin[0], origin[1], corner[0], corner[1], origin[0], origin[1], corner[0],
      corner[1], GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  if (glGetError() != GL_NO_ERROR)
  {
    return false;
  }
  this->ResolveFrameBuffer->Bind(GL_READ_FRAMEBUFFER);
  this->ResolveFrameBuffer->ActivateReadBuffer(0);
  return true;
}

void vtkFXAntiAliasingPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Filter->ReleaseGraphicsResources();
  vtkFXRenderUtilities::Release(this->Resolved, w);
  vtkFXRenderUtilities::Release(this->ResolveFrameBuffer, w);
}
