/**
 * @class   vtkFXSelectionPass
 * @brief   Renders the props for the renderer's vtkHardwareSelector.
 *
 * While a vtkHardwareSelector (vtkPropPicker, area picking) renders, VTK's
 * forward renderer hands the props to the selector, which draws prop, cell
 * and point ids instead of colours. Render passes do not, so picking breaks
 * under a custom pass; vtkFXPipelinePass runs this pass instead of its
 * effects during selection so that picking keeps working.
 *
 * Reads the render state's props; writes ids into the current framebuffer.
 * Does nothing when no selector is rendering. Cost: VTK's own selection
 * rendering, only while picking. Limitation: a pick restricted
 * to a prop list (vtkPicker's PickFromList) considers all visible props,
 * because the list is not public in vtkRenderer.
 */
#ifndef vtkFXSelectionPass_h
#define vtkFXSelectionPass_h

#include "vtkFXModule.h"
#include "vtkRenderPass.h"

class VTKFX_EXPORT vtkFXSelectionPass : public vtkRenderPass
{
public:
  static vtkFXSelectionPass* New();
  vtkTypeMacro(vtkFXSelectionPass, vtkRenderPass);

  void Render(const vtkRenderState* s) override;

protected:
  vtkFXSelectionPass() = default;
  ~vtkFXSelectionPass() override = default;

private:
  vtkFXSelectionPass(const vtkFXSelectionPass&) = delete;
  void operator=(const vtkFXSelectionPass&) = delete;
};

#endif
