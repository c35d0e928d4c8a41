/**
 * @class   vtkFXTranslucentPass
 * @brief   Renders translucent polygonal geometry exactly as the renderer would.
 *
 * Calls the renderer's own DeviceRenderTranslucentPolygonalGeometry, so the
 * renderer's settings decide between depth peeling and order-independent
 * transparency (VTK 9.1's only two paths), as in a VTK render without
 * passes.
 * Reads the current framebuffer's depth (the G-buffer depth written by
 * vtkFXCompositePass) and blends into its colour. Cost: VTK's own.
 */
#ifndef vtkFXTranslucentPass_h
#define vtkFXTranslucentPass_h

#include "vtkFXModule.h"
#include "vtkRenderPass.h"

class VTKFX_EXPORT vtkFXTranslucentPass : public vtkRenderPass
{
public:
  static vtkFXTranslucentPass* New();
  vtkTypeMacro(vtkFXTranslucentPass, vtkRenderPass);

  void Render(const vtkRenderState* s) override;

protected:
  vtkFXTranslucentPass() = default;
  ~vtkFXTranslucentPass() override = default;

private:
  vtkFXTranslucentPass(const vtkFXTranslucentPass&) = delete;
  void operator=(const vtkFXTranslucentPass&) = delete;
};

#endif
