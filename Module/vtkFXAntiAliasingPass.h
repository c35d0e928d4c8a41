/**
 * @class   vtkFXAntiAliasingPass
 * @brief   The renderer's FXAA (vtkRenderer::UseFXAA) in vtkFXPipelinePass's frame.
 *
 * VTK's own filter (vtkOpenGLFXAAFilter, configured by the renderer's
 * vtkFXAAOptions when it has them), as vtkOpenGLRenderer runs it in its
 * own frame. vtkFXPipelinePass runs this pass, while the renderer's
 * UseFXAA is on, on the displayable image: after its lit steps and the
 * HDR target's write-back (the filter copies the framebuffer into an
 * 8-bit texture, which would clamp HDR values), before the overlay, which
 * VTK also leaves unfiltered. VTK filters before its volume step; here
 * volumes and post-process effects (glow, feature lines) are filtered too.
 * Reads and writes the current framebuffer in the renderer's viewport.
 * Cost: VTK's: a copy of the viewport into an RGBA8 texture (4 bytes per
 * pixel, kept while FXAA runs) and one full-screen pass.
 */
#ifndef vtkFXAntiAliasingPass_h
#define vtkFXAntiAliasingPass_h

#include "vtkFXModule.h"
#include "vtkRenderPass.h"
#include "vtkSmartPointer.h" // for the filter

class vtkOpenGLFXAAFilter;

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
  vtkSmartPointer<vtkOpenGLFXAAFilter> Filter;

  vtkFXAntiAliasingPass(const vtkFXAntiAliasingPass&) = delete;
  void operator=(const vtkFXAntiAliasingPass&) = delete;
};

#endif
