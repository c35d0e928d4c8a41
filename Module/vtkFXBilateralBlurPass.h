/**
 * @class   vtkFXBilateralBlurPass
 * @brief   Depth- and normal-aware separable blur, with joint-bilateral upsampling.
 *
 * Reads the output texture of its input effect (SetInputEffect, e.g. a
 * vtkFXSSAOPass) with 1 to 4 values per pixel, at the G-buffer's resolution
 * or half of it, and the G-buffer's linear depth and normal channels as
 * guides. Writes a texture of the same number of values at the G-buffer's
 * full resolution (GetOutputTexture): a horizontal and a vertical pass of
 * 2 x Radius + 1 taps weighted by a Gaussian of the distance, a Cauchy
 * weight of the relative depth difference (DepthSigma, a fraction of the
 * depth, so the result does not depend on the scene's scale) and the normal
 * agreement (NormalPower),
 * then, for half-resolution input, a joint-bilateral upsample (4 taps).
 *
 * A one-value input that carries its linear depth in its second channel
 * (what vtkFXSSAOPass writes) is blurred by depth alone, one fetch per tap;
 * other inputs first get a guide texture (normal and depth per input pixel).
 *
 * Cost: 2 x (2 Radius + 1) taps per input pixel, plus 4 taps per output
 * pixel when upsampling, plus the guide pass for multi-value inputs.
 *
 * Half-resolution inputs follow vtkFXSSAOPass's layout: input texel i
 * holds the value of G-buffer texel 2 i.
 */
#ifndef vtkFXBilateralBlurPass_h
#define vtkFXBilateralBlurPass_h

#include "vtkFXEffectPass.h"
#include "vtkFXModule.h"
#include "vtkSmartPointer.h"

#include <memory>
#include <string>

class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;

class VTKFX_EXPORT vtkFXBilateralBlurPass : public vtkFXEffectPass
{
public:
  static vtkFXBilateralBlurPass* New();
  vtkTypeMacro(vtkFXBilateralBlurPass, vtkFXEffectPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Taps on each side of a pixel, per pass (1..16, default 4; the seeds'
   * 17-tap filter is 8).
   */
  vtkSetClampMacro(Radius, int, 1, 16);
  vtkGetMacro(Radius, int);

  /**
   * Depth tolerance as a fraction of the pixel's depth (0.0001..1, default
   * 0.05): taps whose depth differs by this much weigh exp(-1/2).
   */
  vtkSetClampMacro(DepthSigma, double, 1e-4, 1.0);
  vtkGetMacro(DepthSigma, double);

  /**
   * Integer exponent of the normal agreement max(0, n . n0) (0..32,
   * default 8; compiled into the shader).
   */
  vtkSetClampMacro(NormalPower, int, 0, 32);
  vtkGetMacro(NormalPower, int);

  /**
   * Values per pixel, 1..4 (default 1); 3 serves the directional occlusion
   * of later effects.
   */
  vtkSetClampMacro(NumberOfComponents, int, 1, 4);
  vtkGetMacro(NumberOfComponents, int);

  /**
   * Upsample a half-resolution input to full resolution (default on). Off,
   * a one-value input that carries its depth (see above) stays at its
   * resolution with the depth in the output's second channel, for a
   * consumer that upsamples inline (vtkFXCompositePass does: it saves a
   * full-resolution pass); other inputs are always upsampled.
   */
  vtkSetMacro(Upsample, bool);
  vtkGetMacro(Upsample, bool);
  vtkBooleanMacro(Upsample, bool);

  unsigned int GetRequiredChannels() override;
  vtkTextureObject* GetOutputTexture() override;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkFXBilateralBlurPass();
  ~vtkFXBilateralBlurPass() override;

  void RunStage(int mode, vtkOpenGLRenderWindow* window, vtkTextureObject* input,
    vtkTextureObject* output, int step, bool packed);
  int TextureFormat() const;

  int Radius = 4;
  double DepthSigma = 0.05;
  int NormalPower = 8;
  int NumberOfComponents = 1;
  bool Upsample = true;

  vtkSmartPointer<vtkTextureObject> GuideTexture; // (normal, depth), RGBA32F, input resolution
  vtkSmartPointer<vtkTextureObject> Horizontal;
  vtkSmartPointer<vtkTextureObject> Blurred;
  vtkSmartPointer<vtkTextureObject> Upsampled;
  vtkTextureObject* Output = nullptr;
  static constexpr int NumberOfModes = 4; // horizontal, vertical, upsample, guide
  vtkSmartPointer<vtkOpenGLFramebufferObject> FrameBuffers[NumberOfModes];
  std::unique_ptr<vtkOpenGLQuadHelper> Quads[NumberOfModes];
  std::string QuadSources[NumberOfModes];

private:
  vtkFXBilateralBlurPass(const vtkFXBilateralBlurPass&) = delete;
  void operator=(const vtkFXBilateralBlurPass&) = delete;
};

#endif
