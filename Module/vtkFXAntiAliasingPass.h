/**
 * @class   vtkFXAntiAliasingPass
 * @brief   The renderer's FXAA (vtkRenderer::UseFXAA) in vtkFXPipelinePass's frame.
 *
 * VTK's own filter (vtkOpenGLFXAAFilter, configured by the renderer's
 * vtkFXAAOptions when it has them), as vtkOpenGLRenderer runs it in its
 * own frame. vtkFXPipelinePass runs this pass while the renderer's
 * UseFXAA is on, and in a multisampled framebuffer's frames with a
 * G-buffer (vtkFXPipelinePass::MultisampleFXAA), on the displayable
 * image: after its lit steps and the
 * HDR target's write-back (the filter copies the framebuffer into an
 * 8-bit texture, which would clamp HDR values), before the overlay, which
 * VTK also leaves unfiltered. VTK filters before its volume step; here
 * volumes and post-process effects (glow, feature lines) are filtered too.
 * Reads and writes the current framebuffer in the renderer's viewport.
 * A multisampled framebuffer (VTK's default window asks for 8 samples) is
 * first resolved into a single-sampled copy, which the filter reads: it
 * copies its input with glCopyTexSubImage2D, which OpenGL refuses from a
 * multisampled framebuffer (VTK 9.1's own FXAA then shows a black image).
 * Cost: VTK's: a copy of the viewport into an RGBA8 texture (4 bytes per
 * pixel, kept while FXAA runs) and one full-screen pass; in a
 * multisampled framebuffer a resolving blit into an RGBA8 copy (4 bytes
 * per pixel up to the viewport's far corner) first.
 */
#ifndef vtkFXAntiAliasingPass_h
#define vtkFXAntiAliasingPass_h

#include "vtkFXModule.h"
#include "vtkRenderPass.h"
#include "vtkSmartPointer.h" // for the filter

class vtkOpenGLFXAAFilter;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkTextureObject;

class VTKFX_EXPORT vtkFXAntiAliasingPass : public vtkRenderPass
{
public:
  static vtkFXAntiAliasingPass* New();
  vtkTypeMacro(vtkFXAntiAliasingPass, vtkRenderPass);

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkFXAntiAliasingPass();
  ~vtkFXAntiAliasingPass() override;

private:
  // Resolves the multisampled draw framebuffer's viewport into Resolved
  // and binds that for reading; false (nothing bound) where the draw
  // framebuffer is not multisampled or the copy cannot be made.
  bool ResolveForReading(vtkRenderer* renderer, vtkOpenGLRenderWindow* window);

  vtkSmartPointer<vtkOpenGLFXAAFilter> Filter;
  vtkSmartPointer<vtkTextureObject> Resolved;
  vtkSmartPointer<vtkOpenGLFramebufferObject> ResolveFrameBuffer;
  bool WarnedEarlierError = false; // a GL error pending before the resolve (said once)

  vtkFXAntiAliasingPass(const vtkFXAntiAliasingPass&) = delete;
  void operator=(const vtkFXAntiAliasingPass&) = delete;
};

#endif
