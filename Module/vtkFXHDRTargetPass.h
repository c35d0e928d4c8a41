/**
 * @class   vtkFXHDRTargetPass
 * @brief   Renders its delegate into a 16-bit float colour target, then writes the result back.
 *
 * Reads what the current framebuffer holds in the renderer's viewport (the
 * cleared background, or what layers below drew) and copies it into its
 * own RGBA16F colour texture and depth texture; renders its delegate there
 * (the render state's framebuffer is this target, so VTK's translucent and
 * volume steps draw into it as into any framebuffer); then writes colour
 * and depth back into the framebuffer it found, with NaN turned to 0,
 * colours clamped to [0, 65504] (an 8-bit window clamps them to 1 itself;
 * a float framebuffer around the pipeline, such as vtkToneMappingPass's,
 * keeps the HDR values) and alpha to [0, 1] (vtkFXCompositePass marks
 * alpha above 1 during the frame, SetMarksTransmittance).
 *
 * Passes inside see light values above 1 and can post-process them (a glow
 * reads the colour texture, GetColorTexture, and adds onto the target).
 * vtkFXPipelinePass puts one around its composite, forward-opaque,
 * translucent and volume steps and its post-process effects, only while a
 * post-process effect runs.
 *
 * Cost: 12 bytes per pixel (colour 8, depth 4), a blit in, and out a depth
 * blit and a full-screen pass for the colour (the pass writes the depth
 * too where the framebuffer refuses the blit, as a multisampled one does;
 * the blit took the write-back from 5.0 to 4.1 ms at 1280x720 on
 * llvmpipe); the depth is copied in only when the renderer keeps the depth
 * of the layers below or of an earlier frame (PreserveDepthBuffer, or
 * Erase off on it or its window), otherwise cleared.
 *
 * The depth texture has the format of the window's depth buffer, so that
 * both blits (the copy in, and VTK's translucent pass copying the target's
 * depth into its own texture, of the format it picks from the window) find
 * the formats they need equal; a multisampled window's depth is resolved.
 *
 * The target covers the renderer's viewport from (0, 0); volumes drawn
 * into it read their corner from the GL viewport (vtkFXVolumePass), so a
 * renderer whose viewport is offset in the window draws them in place.
 *
 * Limitation: the depth of the layers below is kept only when the window's
 * depth buffer can be copied (a warning says when it cannot). An OpenGL
 * error left pending before its copies (by the application or an earlier
 * step) is reported once as a warning, not cleared silently.
 */
#ifndef vtkFXHDRTargetPass_h
#define vtkFXHDRTargetPass_h

#include "vtkFXModule.h"
#include "vtkFXRenderUtilities.h" // for the full-screen quads
#include "vtkRenderPass.h"
#include "vtkSmartPointer.h"

#include <string>

class vtkFXGBufferPass;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLState;
class vtkTextureObject;

class VTKFX_EXPORT vtkFXHDRTargetPass : public vtkRenderPass
{
public:
  static vtkFXHDRTargetPass* New();
  vtkTypeMacro(vtkFXHDRTargetPass, vtkRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The pass rendered into the target.
   */
  vtkGetObjectMacro(DelegatePass, vtkRenderPass);
  virtual void SetDelegatePass(vtkRenderPass* delegatePass);

  /**
   * The RGBA16F colour and the depth of the target while the delegate
   * renders (nullptr before the first Render()).
   */
  vtkTextureObject* GetColorTexture();
  vtkTextureObject* GetDepthTexture();

  /**
   * Bytes per pixel of the target's textures (0 when none is allocated).
   */
  int GetBytesPerPixel() const;

  /**
   * The G-buffer of the frame (not owned; nullptr: none). When it could not
   * be made (vtkFXGBufferPass::GetFrameComplete), the opaque props were
   * drawn forward into the framebuffer: the target then starts with the
   * framebuffer's depth too, so that what it draws is hidden behind them.
   */
  void SetGBuffer(vtkFXGBufferPass* gbuffer) { this->GBuffer = gbuffer; }

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkFXHDRTargetPass();
  ~vtkFXHDRTargetPass() override;

  // Copies the framebuffer's colour, and with `depth` its depth, into the
  // target; returns whether the colour was copied, and says in
  // depthCopied whether the depth was (else it is cleared to far).
  bool CopyIn(vtkOpenGLState* state, int x, int y, int width, int height, bool depth,
    bool& depthCopied);
  // The delegate drawn straight into the renderer's framebuffer.
  void RenderWithoutTarget(const vtkRenderState* s);
  // Writes the target into the framebuffer it was copied from, at the
  // renderer's viewport (x, y, width, height).
  void WriteBack(vtkOpenGLRenderWindow* window, const int viewport[4]);
  // The target's depth into that framebuffer's by a blit; false when it
  // refuses (then the write-back's shader writes it).
  bool BlitDepthBack(vtkOpenGLState* state, const int viewport[4]);

  vtkRenderPass* DelegatePass = nullptr;
  int DepthFormat = -1;
  vtkFXGBufferPass* GBuffer = nullptr;
  bool WarnedDepthFormat = false;
  bool WarnedColorCopy = false;
  bool WarnedIncomplete = false;
  bool WarnedEarlierError = false; // (an OpenGL error pending before a copy: once)
  bool BlitsDepth = true; // the framebuffer took the write-back's depth blit (see WriteBack)
  vtkSmartPointer<vtkTextureObject> Color;
  vtkSmartPointer<vtkTextureObject> Depth;
  vtkSmartPointer<vtkOpenGLFramebufferObject> FrameBuffer;
  vtkFXRenderUtilities::FullScreenQuad Quad;

private:
  vtkFXHDRTargetPass(const vtkFXHDRTargetPass&) = delete;
  void operator=(const vtkFXHDRTargetPass&) = delete;
};

#endif
