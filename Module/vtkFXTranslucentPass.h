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
 * Effects that shade translucent props (vtkFXEffectPass::GetShadesForward,
 * e.g. shadows cast on them) are told before and after the step.
 */
#ifndef vtkFXTranslucentPass_h
#define vtkFXTranslucentPass_h

#include "vtkFXModule.h"
#include "vtkRenderPass.h"
#include "vtkWeakPointer.h" // for the effects

#include <vector>

class vtkFXEffectPass;

class VTKFX_EXPORT vtkFXTranslucentPass : public vtkRenderPass
{
public:
  static vtkFXTranslucentPass* New();
  vtkTypeMacro(vtkFXTranslucentPass, vtkRenderPass);

  void Render(const vtkRenderState* s) override;

  ///@{
  /**
   * Effects told before and after the step (see vtkFXEffectPass::
   * BeginForwardShading); vtkFXPipelinePass sets them every frame.
   */
  void AddForwardShadingEffect(vtkFXEffectPass* effect);
  void RemoveAllForwardShadingEffects();
  ///@}

protected:
  vtkFXTranslucentPass() = default;
  ~vtkFXTranslucentPass() override = default;

  std::vector<vtkWeakPointer<vtkFXEffectPass>> ForwardShadingEffects;

private:
  vtkFXTranslucentPass(const vtkFXTranslucentPass&) = delete;
  void operator=(const vtkFXTranslucentPass&) = delete;
};

#endif
