/**
 * @class   vtkFXVolumePass
 * @brief   VTK's volume step, with the volumes' viewport taken from GL.
 *
 * Runs VTK's vtkVolumetricPass over the render state's props, with this
 * pass in the RenderPasses key of each volume drawn (vtkVolume props, the
 * volume parts of assemblies, vtkLODProp3D) while it runs. VTK's GPU
 * ray-cast mapper then reads its window corner and size from the GL
 * viewport (as it does under vtkDualDepthPeelingPass) instead of the
 * renderer's place in the window: inside vtkFXPipelinePass's HDR target,
 * whose viewport starts at (0, 0), a renderer whose viewport is offset in
 * the window copied its depth from outside the target and cast its rays
 * from the wrong texels (the volume cut off or wrongly hidden). In the
 * window's own framebuffer the two agree. The pass changes no shader.
 * Reads and writes the current framebuffer; costs nothing of its own.
 */
#ifndef vtkFXVolumePass_h
#define vtkFXVolumePass_h

#include "vtkFXModule.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkSmartPointer.h" // for the delegate

class vtkVolumetricPass;

class VTKFX_EXPORT vtkFXVolumePass : public vtkOpenGLRenderPass
{
public:
  static vtkFXVolumePass* New();
  vtkTypeMacro(vtkFXVolumePass, vtkOpenGLRenderPass);

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkFXVolumePass();
  ~vtkFXVolumePass() override;

private:
  vtkSmartPointer<vtkVolumetricPass> Volumes;

  vtkFXVolumePass(const vtkFXVolumePass&) = delete;
  void operator=(const vtkFXVolumePass&) = delete;
};

#endif
