/**
 * @class   vtkFXSSAOPass
 * @brief   Screen-space ambient occlusion from the vtkFX G-buffer.
 *
 * Reads the G-buffer's normal and linear depth channels; writes the output
 * "occlusion" (RG32F: R = occlusion, 1 = open, 0 = fully occluded; G = the
 * texel's linear depth, the guide of vtkFXBilateralBlurPass; 32-bit
 * because a 16-bit float overflows at 65504 world units) at
 * full or half resolution. In the composite it scales the ambient
 * visibility by its occlusion, or, when its optional input "denoised" is
 * connected to an effect that ran (the blur of its output), by that one.
 * Normal-oriented hemisphere of NumberOfSamples points, cosine-distributed
 * with lengths u^3 (Vizerie 2009, "Normal mapped screen space diffuse
 * occlusion" demo),
 * rotated per pixel by a 4x4 tile, with a range check: with solid occluders
 * its expectation over that distribution is the cosine-weighted obscurance
 * with falloff 1 - (t/R)^(1/3) (see vtkFXSSAOFS.glsl) that vtkfx-bench's
 * ray-traced reference computes; the fixed low-discrepancy set (only the
 * azimuth is rotated per pixel) approximates that expectation.
 *
 * Radius is in world units; 0 (default) means 0.1 x the diagonal of the
 * visible props' bounds, so any dataset scale works unchanged. Bias is a
 * fraction of the radius. Pair it with vtkFXBilateralBlurPass to remove the
 * noise of the rotated kernel (and to upsample a half-resolution result);
 * vtkFXPipelinePass does so with SetAmbientOcclusion(true).
 *
 * Cost: one full-screen pass (a quarter of the pixels at half resolution)
 * with NumberOfSamples depth fetches per pixel.
 */
#ifndef vtkFXSSAOPass_h
#define vtkFXSSAOPass_h

#include "vtkFXEffectPass.h"
#include "vtkFXModule.h"
#include "vtkSmartPointer.h"

#include <memory>
#include <string>

class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkRenderer;

class VTKFX_EXPORT vtkFXSSAOPass : public vtkFXEffectPass
{
public:
  static vtkFXSSAOPass* New();
  vtkTypeMacro(vtkFXSSAOPass, vtkFXEffectPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Occlusion radius in world units; 0 (default) = RadiusFraction x the
   * diagonal of the visible props' bounds.
   */
  vtkSetClampMacro(Radius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Radius, double);

  /**
   * Fraction of the visible bounds' diagonal used when Radius is 0
   * (dimensionless, default 0.1).
   */
  vtkSetClampMacro(RadiusFraction, double, 1e-6, 10.0);
  vtkGetMacro(RadiusFraction, double);

  /**
   * Samples per pixel (1..64, default 8: with the blur, within 1.5 dB of 32
   * samples against the ray-traced reference on the bench scenes, at about
   * a third of the cost; see vtkfx-bench ao).
   */
  vtkSetClampMacro(NumberOfSamples, int, 1, 64);
  vtkGetMacro(NumberOfSamples, int);

  /**
   * Offset along the normal and depth tolerance, as a fraction of the
   * radius (0..0.5, default 0.02): keeps a surface from occluding itself.
   */
  vtkSetClampMacro(Bias, double, 0.0, 0.5);
  vtkGetMacro(Bias, double);

  enum Method
  {
    Hemisphere = 0, // normal-oriented hemisphere samples (Vizerie 2009)
    Horizon         // horizon-based, cosine-weighted (GTAO, Jimenez et al. 2016)
  };

  /**
   * Estimator (default Hemisphere). Horizon spends the same
   * NumberOfSamples depth fetches on 2 screen-space slices with
   * NumberOfSamples / 4 steps on each side of the pixel. Measured with
   * vtkfx-bench ao at 8 fetches, half resolution, blurred: 0.6 to 2.2 dB
   * closer to the ray-traced reference than Hemisphere on the bunny, the
   * fandisk, scene:corner and 1crn, at a similar cost; but its falloff is
   * not the reference's (it fades horizons from 0.385 R to R), its crease
   * reads 0.63 instead of 0.5, two slices per pixel leave a tilted open
   * plane at 0.93 to 1 after the blur, and more steps (16 fetches) move it
   * away from the reference (its falloff darkens more), so it is not the
   * default. Its raw
   * per-pixel values are unclamped (they exceed 1 on tilted open surfaces
   * and average to the visibility over the noise tile).
   */
  vtkSetClampMacro(Method, int, Hemisphere, Horizon);
  vtkGetMacro(Method, int);

  /**
   * Compute occlusion at half the viewport's resolution (default on).
   */
  vtkSetMacro(HalfResolution, bool);
  vtkGetMacro(HalfResolution, bool);
  vtkBooleanMacro(HalfResolution, bool);

  /**
   * The radius used in the last Render(), in world units.
   */
  vtkGetMacro(EffectiveRadius, double);

  unsigned int GetRequiredChannels() override;
  Output GetOutput(const char* name) override;
  std::string GetCompositeCode(int hook) override;
  void BindCompositeResources(vtkShaderProgram* program, const std::string& prefix) override;
  void UnbindCompositeResources() override;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkFXSSAOPass();
  ~vtkFXSSAOPass() override;

  double ComputeRadius(vtkRenderer* ren) const;
  void SetKernelUniforms(vtkShaderProgram* program) const;
  void SetHemisphereKernel(vtkShaderProgram* program) const;

  double Radius = 0.0;
  double RadiusFraction = 0.1;
  int NumberOfSamples = 8;
  int Method = Hemisphere;
  double Bias = 0.02;
  bool HalfResolution = true;
  double EffectiveRadius = 0.0;

  vtkSmartPointer<vtkTextureObject> Occlusion;
  vtkTextureObject* BoundInComposite = nullptr;
  vtkSmartPointer<vtkOpenGLFramebufferObject> FrameBuffer;
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  std::string QuadSource;

private:
  vtkFXSSAOPass(const vtkFXSSAOPass&) = delete;
  void operator=(const vtkFXSSAOPass&) = delete;
};

#endif
