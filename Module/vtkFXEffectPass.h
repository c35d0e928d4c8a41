/**
 * @class   vtkFXEffectPass
 * @brief   Base class of the effects that plug into vtkFXPipelinePass.
 *
 * An effect declares which G-buffer channels it reads
 * (GetRequiredChannels) and whether the current scene gives it work
 * (HasWork); the pipeline allocates exactly the channels that the active
 * effects and its composite read, hands each effect the G-buffer
 * (SetGBuffer) and runs it at its stage:
 * - AfterGBuffer: between the G-buffer and the composite (occlusion), reads
 *   G-buffer channels and writes its own output texture;
 * - AfterComposite: after the lit opaque image (post-processing).
 * A disabled effect, or one without work, is left out of the frame, and the
 * channels only it read are released. What an effect reads and writes and
 * what it costs is documented by each subclass.
 */
#ifndef vtkFXEffectPass_h
#define vtkFXEffectPass_h

#include "vtkFXModule.h"
#include "vtkOpenGLRenderPass.h"

class vtkFXGBufferPass;
class vtkTextureObject;

class VTKFX_EXPORT vtkFXEffectPass : public vtkOpenGLRenderPass
{
public:
  vtkTypeMacro(vtkFXEffectPass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Stage
  {
    AfterGBuffer = 0,
    AfterComposite
  };

  /**
   * Where in the frame the effect runs (default AfterGBuffer).
   */
  vtkSetClampMacro(Stage, int, AfterGBuffer, AfterComposite);
  vtkGetMacro(Stage, int);

  /**
   * Effects start enabled; a disabled effect is left out of the frame.
   */
  vtkSetMacro(Enabled, bool);
  vtkGetMacro(Enabled, bool);
  vtkBooleanMacro(Enabled, bool);

  /**
   * G-buffer channels the effect reads, as a mask of
   * vtkFXGBufferPass::ChannelBit().
   */
  virtual unsigned int GetRequiredChannels() = 0;

  /**
   * Whether the effect has work in this frame, given the number of opaque
   * and translucent props the pipeline found. Default: any opaque prop.
   */
  virtual bool HasWork(int opaqueProps, int translucentProps);

  /**
   * The texture the effect wrote in its last Render() (e.g. occlusion), or
   * nullptr for effects that write into the framebuffer.
   */
  virtual vtkTextureObject* GetOutputTexture() { return nullptr; }

  /**
   * An effect whose output texture this one reads (e.g. a blur of an
   * occlusion pass), or nullptr.
   */
  virtual void SetInputEffect(vtkFXEffectPass* input);
  vtkGetObjectMacro(InputEffect, vtkFXEffectPass);

  /**
   * The G-buffer the effect reads; set by the pipeline before Render().
   */
  virtual void SetGBuffer(vtkFXGBufferPass* gbuffer);
  vtkGetObjectMacro(GBuffer, vtkFXGBufferPass);

protected:
  vtkFXEffectPass() = default;
  ~vtkFXEffectPass() override;

  int Stage = AfterGBuffer;
  bool Enabled = true;
  vtkFXGBufferPass* GBuffer = nullptr;
  vtkFXEffectPass* InputEffect = nullptr;

private:
  vtkFXEffectPass(const vtkFXEffectPass&) = delete;
  void operator=(const vtkFXEffectPass&) = delete;
};

#endif
