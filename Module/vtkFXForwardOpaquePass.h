/**
 * @class   vtkFXForwardOpaquePass
 * @brief   Draws, forward, the opaque props a vtkFXGBufferPass cannot capture.
 *
 * Image slices, 3D text and other props whose mappers do not call VTK's
 * render-pass hooks (see vtkFXGBufferPass::CanCapture) are drawn here with
 * their own shading, depth-tested against the G-buffer depth that
 * vtkFXCompositePass wrote, exactly as VTK's opaque step would draw them.
 * Reads the render state's props; writes the current framebuffer.
 * Cost: VTK's own for those props; nothing when there are none.
 */
#ifndef vtkFXForwardOpaquePass_h
#define vtkFXForwardOpaquePass_h

#include "vtkFXModule.h"
#include "vtkRenderPass.h"

class VTKFX_EXPORT vtkFXForwardOpaquePass : public vtkRenderPass
{
public:
  static vtkFXForwardOpaquePass* New();
  vtkTypeMacro(vtkFXForwardOpaquePass, vtkRenderPass);

  void Render(const vtkRenderState* s) override;

protected:
  vtkFXForwardOpaquePass() = default;
  ~vtkFXForwardOpaquePass() override = default;

private:
  vtkFXForwardOpaquePass(const vtkFXForwardOpaquePass&) = delete;
  void operator=(const vtkFXForwardOpaquePass&) = delete;
};

#endif
