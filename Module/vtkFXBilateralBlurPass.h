/**
 * @class   vtkFXBilateralBlurPass
 * @brief   Depth- and normal-aware separable blur, with joint-bilateral upsampling.
 *
 * Reads its input "source" (another effect's output, e.g. vtkFXSSAOPass's
 * "occlusion") with 1 to 4 values per pixel, at the G-buffer's resolution
 * or a reduced one (the step the source declares), and the G-buffer's
 * linear depth and normal channels as guides. Writes the output "blurred"
 * with the same number of values, at full resolution or, with Upsample
 * off, at the source's: a horizontal and a vertical pass of
 * 2 x Radius + 1 taps weighted by a Gaussian of the distance (or a box,
 * see Kernel), a Cauchy
 * weight of the tap's depth difference from the pixel's tangent plane
 * (DepthSigma, a fraction of the depth, so the result does not depend on
 * the scene's scale; in parallel projection a fraction of the distance at
 * which a 30-degree view angle spans the view, so that it depends on
 * neither the camera's distance nor its view angle) and the normal
 * agreement (NormalPower),
 * then, for reduced-resolution input, a joint-bilateral upsample (4 taps).
 *
 * Inputs that carry their own guide are read in one fetch per tap and need
 * no guide pass: one value with its linear depth in the second channel
 * (vtkFXSSAOPass), blurred by depth alone, and three values packed with
 * their normal and depth (vtkFXDirectionalOcclusionPass:
 * vtkFXEffectPass::Output::Packing 1), blurred by normal and depth; the
 * blurred output keeps carrying the depth (RG32F, or RGBA32F with the three
 * values plain and the depth in A) until upsampled. Other inputs first get
 * a guide texture (normal and depth per input pixel).
 * Output formats: upsampled, R8 / RG8 for one or two values and RGBA16F for
 * three or four; left at a reduced resolution, as above for inputs with a
 * guide, else RGBA16F.
 *
 * Cost: 2 x (2 Radius + 1) taps per input pixel, plus 4 taps per output
 * pixel when upsampling, plus the guide pass for inputs without a guide.
 * With Separable off, one pass of (2 Radius + 1)^2 taps instead: the full
 * 2D joint-bilateral filter that the two passes approximate.
 *
 * Reduced-resolution inputs follow vtkFXSSAOPass's layout: input texel i
 * holds the value of G-buffer texel step x i (steps 1 and 2).
 */
#ifndef vtkFXBilateralBlurPass_h
#define vtkFXBilateralBlurPass_h

#include "vtkFXEffectPass.h"
#include "vtkFXModule.h"
#include "vtkFXSetGet.h" // for vtkFXSetClampMacro
#include "vtkFXRenderUtilities.h" // for the full-screen quads
#include "vtkSmartPointer.h"

#include <array>
#include <string>

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkShaderProgram;

class VTKFX_EXPORT vtkFXBilateralBlurPass : public vtkFXEffectPass
{
public:
  static vtkFXBilateralBlurPass* New();
  vtkTypeMacro(vtkFXBilateralBlurPass, vtkFXEffectPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Taps on each side of a pixel, per pass (1..16, default 4; the 17-tap
   * blur of early SSAO write-ups, e.g. gamerendering.com 2009, is 8).
   */
  vtkSetClampMacro(Radius, int, 1, 16);
  vtkGetMacro(Radius, int);

  /**
   * Weight of a tap by its distance i (in input texels) from the pixel.
   * Gaussian (default): exp(-i^2 / (2 sigma^2)), sigma = Radius / 2.
   * Box: 1, and 1/2 at i = +-Radius: the taps then hold every phase of a
   * pattern of period 2 x Radius once (up to the depth weights), so a blur
   * of radius 2 removes most of vtkFXSSAOPass's 4 x 4 noise tile while
   * smoothing much less than the default Gaussian of radius 4. On the
   * occluded floor and wall of a crease it leaves 0.56 of what a Gaussian
   * of radius 2 leaves of the tile's pattern, measured in the difference
   * from the crease's closed form (TestSSAO). The High ambient-occlusion preset uses it.
   */
  enum Kernel
  {
    Gaussian = 0,
    Box = 1
  };
  vtkSetClampMacro(Kernel, int, Gaussian, Box);
  vtkGetMacro(Kernel, int);

  /**
   * Depth tolerance as a fraction of the pixel's depth (0.0001..1, default
   * 0.02, DefaultDepthSigma, which vtkFXSSAOPass's composite upsample uses
   * too): taps whose depth differs by this much from the pixel's tangent
   * plane (its own depth where the G-buffer has no normal for it) weigh 1/2 (the Cauchy weight 1 / (1 + r^2) of the relative
   * difference r in units of it). Judged against the plane, a surface seen
   * at a grazing angle blurs much as one facing the eye (up to the
   * normals' precision and curvature), and the two sides of a crease, where
   * depth is continuous, stay apart. 0.02 against the 0.05 of a test
   * against the pixel's own depth: detail score (vtkfx-bench ao, Medium
   * preset) bunny 0.60 from 0.54, fandisk 0.67 from 0.53, corner 0.54 from
   * 0.52, 1crn 0.63 from 0.64, PSNR within 0.3 dB. A tap also agrees
   * when its depth is within the tolerance of the pixel's own
   * (fxPlaneGap: the nearer of the two), which keeps a curved surface's
   * neighbours at its silhouette.
   */
  vtkFXSetClampMacro(DepthSigma, double, 1e-4, 1.0);
  static constexpr double DefaultDepthSigma = 0.02;
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
   * Upsample a reduced-resolution input to full resolution (default on).
   * Off, the output stays at the input's resolution (with the depth after
   * the values when the input carries one), for a consumer that
   * samples it bilinearly (the composite does: it saves a full-resolution
   * pass).
   */
  vtkSetMacro(Upsample, bool);
  vtkGetMacro(Upsample, bool);
  vtkBooleanMacro(Upsample, bool);

  /**
   * Leave out the texels without a surface before the shader runs, where
   * the source says which they are and what they hold (vtkFXSSAOPass's
   * one value with its depth; Output::Surfaces), in the horizontal and
   * vertical passes: they keep that value, as the blur would (default on).
   * The result is the same either way; off is for comparison.
   */
  vtkSetMacro(SkipBackground, bool);
  vtkGetMacro(SkipBackground, bool);
  vtkBooleanMacro(SkipBackground, bool);

  /**
   * Blur in a horizontal then a vertical pass (default on), or off, in one
   * pass over the whole (2 Radius + 1)^2 square: the full 2D joint-bilateral
   * filter, every tap weighted against the pixel itself. The two passes
   * weigh a tap off the pixel's row against the tap in that row that
   * brought it, so near depth edges and creases they differ from the 2D
   * filter; on a surface of one depth and normal they are the same filter.
   * Off is the reference the separable blur is measured against (`vtkfx-bench
   * ao`, TestSSAO) and the more accurate choice at edges; it costs
   * (2 Radius + 1) / 2 times the taps (4.5 at the default radius).
   */
  vtkSetMacro(Separable, bool);
  vtkGetMacro(Separable, bool);
  vtkBooleanMacro(Separable, bool);
  /** Whether the last frame left the background out. */
  vtkGetMacro(SkippedBackground, bool);

  unsigned int GetRequiredChannels() override;
  bool GetReadsGeometricNormal() override { return true; }
  Output GetOutput(const char* name) override;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkFXBilateralBlurPass();
  ~vtkFXBilateralBlurPass() override;

  // `surfaces`, `background`: the blur passes (horizontal, vertical, 2D) leave out
  // the texels where `surfaces` is 1, which keep `background` (nullptr:
  // every texel runs).
  bool RunStage(int mode, vtkRenderer* renderer, vtkTextureObject* input,
    vtkTextureObject* output, int step, bool packed, vtkTextureObject* surfaces = nullptr,
    const float* background = nullptr);
  int OutputFormat() const;
  // The taps' distance weights, entry |i| (see fxTapWeights).
  std::array<float, 17> TapWeights() const;
  // FX_RADIUS and FX_TAP_WEIGHTS for the shader: the taps' loop then has
  // a bound and weights known at compile time.
  std::string TapDefines() const;

  int Radius = 4;
  int Kernel = Gaussian;
  double DepthSigma = DefaultDepthSigma;
  int NormalPower = 8;
  int NumberOfComponents = 1;
  bool Upsample = true;
  bool SkipBackground = true;
  bool SkippedBackground = false;
  bool Separable = true;
  bool WarnedIncomplete = false; // a stage's target could not be made (said once)
  bool WarnedMissingInput = false; // no source texture or G-buffer channel (said once)

  vtkSmartPointer<vtkTextureObject> GuideTexture; // (normal, depth), RGBA32F, input resolution
  vtkSmartPointer<vtkTextureObject> Horizontal;
  vtkSmartPointer<vtkTextureObject> Blurred;
  vtkSmartPointer<vtkTextureObject> Upsampled;
  Output Result; // what the last Render() wrote
  static constexpr int NumberOfModes = 5; // horizontal, vertical, upsample, guide, 2D
  vtkSmartPointer<vtkOpenGLFramebufferObject> FrameBuffers[NumberOfModes];
  vtkFXRenderUtilities::FullScreenQuad Quads[NumberOfModes];

private:
  vtkFXBilateralBlurPass(const vtkFXBilateralBlurPass&) = delete;
  void operator=(const vtkFXBilateralBlurPass&) = delete;
};

#endif
