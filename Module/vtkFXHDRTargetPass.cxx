#include "vtkFXHDRTargetPass.h"

#include "vtkFXGBufferPass.h"

#include "vtkFXHDRResolveFS.h"
#include "vtkFXRenderUtilities.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkFXOpenGL.h"

#include <algorithm>

vtkStandardNewMacro(vtkFXHDRTargetPass);
vtkCxxSetObjectMacro(vtkFXHDRTargetPass, DelegatePass, vtkRenderPass);

vtkFXHDRTargetPass::vtkFXHDRTargetPass() = default;

vtkFXHDRTargetPass::~vtkFXHDRTargetPass()
{
  this->SetDelegatePass(nullptr);
}

vtkTextureObject* vtkFXHDRTargetPass::GetColorTexture()
{
  return this->Color;
}

vtkTextureObject* vtkFXHDRTargetPass::GetDepthTexture()
{
  return this->Depth;
}

int vtkFXHDRTargetPass::GetBytesPerPixel() const
{
  return (this->Color ? vtkFXRenderUtilities::GetBytesPerTexel(vtkFXRenderUtilities::RGBA16F) : 0) +
    (this->Depth ? vtkFXRenderUtilities::GetBytesPerTexel(this->DepthFormat) : 0);
}

bool vtkFXHDRTargetPass::CopyIn(
  vtkOpenGLState* state, int x, int y, int width, int height, bool depth, bool& depthCopied)
{
  // The current read framebuffer is what the renderer drew into so far.
  // Colour and depth blit separately: a refused depth blit must not cost
  // the colour.
  this->FrameBuffer->Bind(GL_DRAW_FRAMEBUFFER);
  vtkFXRenderUtilities::ClearPendingErrors(this, "vtkFX's HDR target copy", this->WarnedEarlierError);
  glBlitFramebuffer(
    x, y, x + width, y + height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  const bool colorCopied = glGetError() == GL_NO_ERROR;
  depthCopied = false;
  if (depth)
  {
    glBlitFramebuffer(
      x, y, x + width, y + height, 0, 0, width, height, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    depthCopied = glGetError() == GL_NO_ERROR;
  }
  if (!depthCopied)
  {
    vtkOpenGLState::ScopedglDepthMask depthMask(state);
    state->vtkglDepthMask(GL_TRUE); // glClearBuffer obeys the depth mask
    const GLfloat far = 1.0f;
    glClearBufferfv(GL_DEPTH, 0, &far);
  }
  return colorCopied;
}

void vtkFXHDRTargetPass::RenderWithoutTarget(const vtkRenderState* s)
{
  this->DelegatePass->Render(s);
  this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
}

bool vtkFXHDRTargetPass::BlitDepthBack(vtkOpenGLState* state, const int viewport[4])
{
  // (the formats match, GetReadDepthFormat; a multisampled framebuffer
  // refuses a single-sampled source)
  vtkFXRenderUtilities::ClearPendingErrors(
    this, "vtkFX's HDR target depth write-back", this->WarnedEarlierError);
  state->PushReadFramebufferBinding();
  this->FrameBuffer->Bind(GL_READ_FRAMEBUFFER);
  glBlitFramebuffer(0, 0, viewport[2], viewport[3], viewport[0], viewport[1],
    viewport[0] + viewport[2], viewport[1] + viewport[3], GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  const bool blitted = glGetError() == GL_NO_ERROR;
  state->PopReadFramebufferBinding();
  return blitted;
}

void vtkFXHDRTargetPass::WriteBack(vtkOpenGLRenderWindow* window, const int viewport[4])
{
  vtkOpenGLState* state = window->GetState();
  // The depth by a blit where the framebuffer takes one: a full-screen
  // pass writing gl_FragDepth costs a software rasteriser its early depth
  // path (the write-back took 5.0 ms at 1280x720 on llvmpipe with it).
  // (the program first: without one nothing is written, not the depth
  // alone)
  const auto ready = [this, window](bool writesDepth) {
    std::string fs = vtkFXHDRResolveFS;
    vtkShaderProgram::Substitute(fs, "//VTK::System::Dec",
      std::string("//VTK::System::Dec\n#define FX_WRITE_DEPTH ") + (writesDepth ? "1" : "0"),
      false);
    return vtkFXRenderUtilities::ReadyQuad(this->Quad, window, fs);
  };
  // (a framebuffer that refused the blit, multisampled, refuses it in the
  // frames after too: the pass writes the depth from then on, until the
  // resources are released)
  vtkShaderProgram* program = ready(!this->BlitsDepth);
  if (!program)
  {
    return;
  }
  const bool depthBlitted = this->BlitsDepth && this->BlitDepthBack(state, viewport);
  if (this->BlitsDepth && !depthBlitted)
  {
    this->BlitsDepth = false;
    program = ready(true);
    if (!program)
    {
      return;
    }
  }
  vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglDepthFunc depthFunc(state);
  vtkOpenGLState::ScopedglDepthMask depthMask(state);
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  // The target started as a copy of this framebuffer: replace it wholesale.
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_ALWAYS);
  state->vtkglDepthMask(depthBlitted ? GL_FALSE : GL_TRUE);
  state->vtkglDisable(GL_BLEND);
  this->Color->Activate();
  program->SetUniformi("fxColor", this->Color->GetTextureUnit());
  if (!depthBlitted)
  {
    this->Depth->Activate();
    program->SetUniformi("fxDepth", this->Depth->GetTextureUnit());
  }
  this->Quad.Helper->Render();
  this->Color->Deactivate();
  if (!depthBlitted)
  {
    this->Depth->Deactivate();
  }
}

void vtkFXHDRTargetPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  vtkRenderer* ren = s->GetRenderer();
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!window || !this->DelegatePass)
  {
    vtkErrorMacro("vtkFXHDRTargetPass needs an OpenGL render window and a delegate pass.");
    return;
  }
  vtkOpenGLState* state = window->GetState();
  // The camera pass set the viewport to the renderer's part of the framebuffer.
  GLint viewport[4];
  state->vtkglGetIntegerv(GL_VIEWPORT, viewport);
  const int width = std::max(viewport[2], 1);
  const int height = std::max(viewport[3], 1);

  const bool keepDepth = vtkFXRenderUtilities::KeepsEarlierDepth(ren) ||
    (this->GBuffer && !this->GBuffer->GetFrameComplete());
  this->DepthFormat = vtkFXRenderUtilities::GetReadDepthFormat(window);
  vtkFXRenderUtilities::EnsureTexture(
    this->Color, window, width, height, vtkFXRenderUtilities::RGBA16F);
  vtkFXRenderUtilities::EnsureTexture(this->Depth, window, width, height, this->DepthFormat);
  // (its recorded size is what VTK's translucent passes draw at)
  vtkFXRenderUtilities::FitFramebuffer(this->FrameBuffer, window, width, height);

  state->PushFramebufferBindings();
  this->FrameBuffer->Bind();
  this->FrameBuffer->AddColorAttachment(0, this->Color);
  this->FrameBuffer->AddDepthAttachment(this->Depth);
  this->FrameBuffer->ActivateDrawBuffers(1);
  const bool complete = glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  state->PopFramebufferBindings();
  if (!complete)
  {
    // (say, no memory for an RGBA16F image this large) Drawn as if there
    // were no HDR target: into the renderer's framebuffer, values clamped
    // to its range, rather than writing back an empty image.
    if (!this->WarnedIncomplete)
    {
      vtkWarningMacro("The HDR target of " << width << " x " << height
                                           << " pixels could not be made; drawing without it.");
      this->WarnedIncomplete = true;
    }
    this->RenderWithoutTarget(s);
    return;
  }
  bool colorCopied = false;
  {
    vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
    state->vtkglDisable(GL_SCISSOR_TEST);
    state->PushDrawFramebufferBinding();
    bool depthCopied = false;
    colorCopied =
      this->CopyIn(state, viewport[0], viewport[1], width, height, keepDepth, depthCopied);
    if (colorCopied && !depthCopied && keepDepth && !this->WarnedDepthFormat)
    {
      vtkWarningMacro("The framebuffer's depth cannot be copied; the depth of the layers below "
                      "is not kept in the HDR target.");
      this->WarnedDepthFormat = true;
    }
    state->PopDrawFramebufferBinding();
  }
  if (!colorCopied)
  {
    // The composite leaves background pixels alone and the write-back
    // replaces the whole image: without the framebuffer's colour (its
    // background, gradient or lower layers) the target would show what
    // the texture held there. Drawn without it, as when it cannot be made.
    if (!this->WarnedColorCopy)
    {
      vtkWarningMacro("The framebuffer's colour cannot be copied into the HDR target; drawing "
                      "without it.");
      this->WarnedColorCopy = true;
    }
    this->RenderWithoutTarget(s);
    return;
  }

  state->PushFramebufferBindings();
  this->FrameBuffer->Bind();
  {
    vtkOpenGLState::ScopedglViewport viewportSaver(state);
    vtkOpenGLState::ScopedglScissor scissorSaver(state);
    state->vtkglViewport(0, 0, width, height);
    state->vtkglScissor(0, 0, width, height);
    vtkRenderState inner(ren);
    inner.SetPropArrayAndCount(s->GetPropArray(), s->GetPropArrayCount());
    inner.SetFrameBuffer(this->FrameBuffer);
    this->DelegatePass->Render(&inner);
    this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
  }
  state->PopFramebufferBindings();
  const int written[4] = { viewport[0], viewport[1], width, height };
  this->WriteBack(window, written);
}

void vtkFXHDRTargetPass::ReleaseGraphicsResources(vtkWindow* w)
{
  if (this->DelegatePass)
  {
    this->DelegatePass->ReleaseGraphicsResources(w);
  }
  vtkFXRenderUtilities::ReleaseQuad(this->Quad, w);
  this->BlitsDepth = true;
  vtkFXRenderUtilities::Release(this->Color, w);
  vtkFXRenderUtilities::Release(this->Depth, w);
  vtkFXRenderUtilities::Release(this->FrameBuffer, w);
}

void vtkFXHDRTargetPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DelegatePass: " << this->DelegatePass << "\n";
  os << indent << "BytesPerPixel: " << this->GetBytesPerPixel() << "\n";
}
