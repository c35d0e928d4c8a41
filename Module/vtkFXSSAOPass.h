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
 * What it estimates (Falloff): the cosine-weighted visibility within the
 * radius R, a ray hitting anything before R counting as blocked (Binary,
 * default: the ray-traced AO users know from OSPRay, ParaView and Blender),
 * or with hits weighted by 1 - (t/R)^(1/3) (CubeRoot, after Vizerie's 2009
 * demo). Two estimators (Method): horizon-based integration (GTAO,
 * default), exact for a height field in the limit of many steps, and a
 * normal-oriented hemisphere of
 * NumberOfSamples points, cosine-distributed, at distance R (Binary) or at
 * lengths u^3 R (CubeRoot), unbiased for a height field. Both are rotated
 * per pixel by a 4x4 tile; vtkfx-bench's ray-traced reference computes the
 * same definition.
 *
 * Radius is in world units; 0 (default) means 0.1 x the diagonal of the
 * visible props' bounds, so any dataset scale works unchanged. Bias is a
 * fraction of the radius. Pair it with vtkFXBilateralBlurPass to remove the
 * noise of the rotated kernel (the blur can also upsample a half-resolution
 * result; the pipeline leaves that to the composite: DepthAwareUpsample);
 * vtkFXPipelinePass does so with SetAmbientOcclusion(true).
 *
 * Cost: one full-screen pass (a quarter of the pixels at half resolution)
 * with NumberOfSamples depth fetches per pixel, and in the composite two
 * gathers per pixel (one bilinear read with DepthAwareUpsample off). The pixels without a surface are left out
 * before the shader runs (SkipBackground): by the G-buffer's depth test at
 * full resolution, at half by a mask pass of one fetch per texel into a
 * Depth32F image of the pass's size (not with bleeding's second target).
 */
#ifndef vtkFXSSAOPass_h
#define vtkFXSSAOPass_h

#include "vtkFXEffectPass.h"
#include "vtkFXModule.h"
#include "vtkFXSetGet.h" // for vtkFXSetClampMacro
#include "vtkFXRenderUtilities.h" // for the full-screen quads
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkRenderer;

class VTKFX_EXPORT vtkFXSSAOPass : public vtkFXEffectPass
{
public:
  static vtkFXSSAOPass* New();
  vtkTypeMacro(vtkFXSSAOPass, vtkFXEffectPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Occlusion radius in world units (0..1e30); 0 (default) = RadiusFraction
   * x the diagonal of the visible props' bounds. The radius used is kept
   * within 1e-30..1e30, where the shaders' single precision holds it.
   */
  vtkFXSetClampMacro(Radius, double, 0.0, 1e30);
  vtkGetMacro(Radius, double);

  /**
   * Fraction of the visible bounds' diagonal used when Radius is 0
   * (dimensionless, default 0.1).
   */
  vtkFXSetClampMacro(RadiusFraction, double, 1e-6, 10.0);
  vtkGetMacro(RadiusFraction, double);

  /**
   * Depth fetches per pixel (1..64, default 16, vtkFXPipelinePass's Medium
   * preset for the Binary falloff). Hemisphere: one per sample point;
   * Horizon: 2 slices with NumberOfSamples / 4 steps on each side.
   */
  vtkSetClampMacro(NumberOfSamples, int, 1, 64);
  vtkGetMacro(NumberOfSamples, int);

  /**
   * Hemisphere method only: how far the sample kernel's centre is lifted
   * along the normal, as a fraction of the radius (0..0.5, default 0.02),
   * so that a surface does not occlude itself. The horizon method needs
   * none: it measures each step's elevation above the receiver's tangent
   * plane, on which the receiver's own surface lies.
   */
  vtkFXSetClampMacro(Bias, double, 0.0, 0.5);
  vtkGetMacro(Bias, double);

  enum Falloff
  {
    Binary = 0, // visibility within R: OSPRay's aoDistance, Blender's AO distance
    CubeRoot    // near-weighted 1 - (t/R)^(1/3) (Vizerie 2009)
  };

  /**
   * Which occlusion the estimator targets (default Binary). A ray from the
   * surface that hits something at distance t < R occludes
   * - Binary: fully (the ray-traced ambient occlusion users know: OSPRay's
   *   aoDistance, ParaView's ray tracing, Blender's AO distance);
   * - CubeRoot: by 1 - (t/R)^(1/3), nearer hits counting more (the
   *   "sampling importance for close occluders" of Vizerie's demo).
   * The visibility is the cosine-weighted mean over the hemisphere of one
   * minus that. Hemisphere sampling places its samples at distance R
   * (Binary) or at lengths u^3 R (CubeRoot), unbiased for a height field;
   * Horizon counts horizons fully within R (Binary) or fades them over the
   * last 61.5% of R (CubeRoot, XeGTAO's fade: an approximation of that
   * falloff). vtkfx-bench's ray-traced reference traces the same definition.
   */
  vtkSetClampMacro(Falloff, int, Binary, CubeRoot);
  vtkGetMacro(Falloff, int);

  enum Method
  {
    Hemisphere = 0, // normal-oriented hemisphere samples (Vizerie 2009)
    Horizon         // horizon-based, cosine-weighted (GTAO, Jimenez et al. 2016)
  };

  /**
   * Estimator (default Horizon). Measured with vtkfx-bench ao (640x480, half
   * resolution, blur radius 4, against the ray-traced reference of the same
   * falloff; see vtkFXPipelinePass::SetAmbientOcclusionQuality):
   * - Binary: Horizon with 16 fetches is 2.3 to 4.6 dB ahead of the best
   *   vtkSSAOPass setting on the four bench scenes (README); Hemisphere
   *   with 8 (samples at distance R) is more accurate on scene:corner, but
   *   behind Horizon on the other three.
   * - CubeRoot: Horizon with 8 fetches is 1.0 to 5.1 dB ahead of Hemisphere
   *   with 8; more horizon steps move away from this definition (they find
   *   higher horizons, which its falloff discounts).
   * Horizon divides its slices' visible arcs by their open arcs (GTAO
   * divides by the number of slices, right only on average over the noise
   * tile's directions), so an open surface reads 1 at every pixel before
   * any blur: a plane seen from 70 to 4 degrees above it reads 0.99 or
   * more raw (TestSSAO). Its steps land on the texels of the output's grid
   * (every second one at half resolution), each measured within its
   * slice after a slide along the receiver's tangent plane. On the crease of a floor and a wall (TestSSAO,
   * which states the measured errors and its bounds), the Binary horizon
   * estimate is biased open by a few hundredths; the Hemisphere estimate
   * follows the exact visibility within about 0.02 in every band.
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
   * How far behind a surface it sees the horizon method takes it to be
   * solid, as a fraction of the radius (default HeightField; see
   * UsesThinOccluders). A horizon sample then hides the directions between its own
   * elevation and that of the point this far behind it (the visibility
   * bitmask of Therrien et al. 2023, 32 sectors per side of a slice), so
   * rays pass behind thin things (atoms, struts, branches, points) as
   * the ray-traced reference's do. HeightField (the maximum) is GTAO's
   * assumption, everything behind a visible surface solid, which darkens
   * the floor under a molecule and the atoms behind others. The CubeRoot
   * falloff and vtkFXDirectionalOcclusionPass use the height field
   * whatever this is. vtkfx-bench ao (Medium's 16 fetches): 0.5 on the
   * ball-and-stick 1crn gains 1.6 dB and detail, on solid meshes (the
   * bunny, the fandisk, scene:corner) loses 2.3 to 3.2 dB; it costs the
   * SSAO pass about 40% more. (Python: GetOccluderThicknessMaxValue() is
   * HeightField.)
   */
  vtkFXSetClampMacro(OccluderThickness, double, 1e-3, HeightField);
  vtkGetMacro(OccluderThickness, double);
  static constexpr double HeightField = 1e30;
  /**
   * Whether the estimator takes occluders of OccluderThickness: below
   * HeightField, with the horizon method, the Binary falloff and one
   * channel.
   */
  bool UsesThinOccluders() const;

  /**
   * Leave the pixels without a surface out before the shader runs (default
   * on; a software rasteriser otherwise runs the shader on every background
   * block): by the G-buffer's depth test at full resolution, at half by a
   * mask of the pass's size. The result is the same either way, but for
   * fragments at the far plane itself (window depth 1, as when far / near
   * passes about 1e7), which the full-resolution test counts as background
   * as the composite's depth pre-pass does; off is for comparison. A mask
   * that cannot be drawn is reported once, and every pixel runs.
   */
  vtkSetMacro(SkipBackground, bool);
  vtkGetMacro(SkipBackground, bool);
  vtkBooleanMacro(SkipBackground, bool);
  /** Whether the last frame left the background out (see SkipBackground). */
  bool GetSkippedBackground() const { return this->SkippedSurfaces != nullptr; }

  /**
   * How the composite reads a reduced-resolution occlusion that carries its
   * depth (this pass's, blurred or not): on (default), a joint-bilateral
   * upsample (four texels weighted by their depth's agreement with the
   * pixel's tangent plane, vtkFXJointUpsample.glsl, tolerance
   * vtkFXBilateralBlurPass::DefaultDepthSigma of the depth), so occlusion
   * does not bleed across depth edges or creases; off, one bilinear read.
   * (vtkFXDirectionalOcclusionPass's three channels too, once blurred,
   * against the plane of the geometric normal.)
   */
  vtkSetMacro(DepthAwareUpsample, bool);
  vtkGetMacro(DepthAwareUpsample, bool);
  vtkBooleanMacro(DepthAwareUpsample, bool);

  /**
   * The depth fetches the estimator takes per pixel: NumberOfSamples with
   * the hemisphere method, rounded up to a multiple of 3 (at most 63) by
   * vtkFXDirectionalOcclusionPass; with the horizon method a multiple of 4
   * (2 slices, steps on both sides), NumberOfSamples rounded down, 4 at
   * the least.
   */
  int GetEffectiveNumberOfSamples() const;

  /**
   * The radius used in the last Render(), in world units.
   */
  vtkGetMacro(EffectiveRadius, double);

  unsigned int GetRequiredChannels() override;
  /**
   * Some opaque prop and some light on: the occlusion darkens light (the
   * ambient and, by a strength, the diffuse term), so without any there is
   * nothing to darken and the pass, its blur and its channels are left out.
   */
  bool HasWork(const vtkFXSceneInfo& scene) override;
  bool GetReadsGeometricNormal() override { return true; }
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
  // Sets the uniforms `scale` and `offset`, which map the composite's
  // texCoord to `source`'s texture (full or reduced resolution, in
  // vtkFXSSAOPass's layout).
  void SetReadUniforms(vtkShaderProgram* program, const std::string& scale,
    const std::string& offset, const Output& source);
  // What the subclass vtkFXDirectionalOcclusionPass changes: three channels
  // (a method of its own choosing: bleeding needs the hemisphere), an 8x8
  // tile.
  virtual int GetEffectiveMethod() const;
  int GetOcclusionFormat() const;

  ///@{
  // Hooks around Render's one full-screen pass, for subclasses that compute
  // more in it (default: nothing): defines and code for the shader's
  // FXExtension tags, further render targets (colour attachments 1, ...),
  // and the inputs that code reads.
  virtual std::string GetExtensionDefines(vtkRenderer*) { return std::string(); }
  virtual std::string GetExtensionCode(vtkRenderer*) { return std::string(); }
  virtual void AddExtensionTargets(vtkRenderer*, int, int, std::vector<vtkTextureObject*>&) {}
  virtual void BindExtensionInputs(vtkShaderProgram*, vtkRenderer*) {}
  virtual void UnbindExtensionInputs() {}
  ///@}
  void SetKernelUniforms(vtkShaderProgram* program) const;
  void SetHemisphereKernel(vtkShaderProgram* program) const;

  double Radius = 0.0;
  double RadiusFraction = 0.1;
  int NumberOfSamples = 16;
  int Method = Horizon;
  int Falloff = Binary;
  double Bias = 0.02;
  bool HalfResolution = true;
  double OccluderThickness = HeightField;
  bool SkipBackground = true;
  bool DepthAwareUpsample = true;
  // What the composite reads (the denoised input, else this pass's output).
  Output CompositeSource();
  // The composite upsamples `source` by depth (see DepthAwareUpsample).
  bool UpsamplesByDepth(const Output& source) const;
  vtkTextureObject* SkippedSurfaces = nullptr; // the depth the last frame was tested against
  double EffectiveRadius = 0.0;
  bool WarnedIncomplete = false; // the occlusion texture could not be made (said once)
  bool WarnedNoChannels = false; // the G-buffer lacks normal or depth (said once)
  // The mask could not be drawn at this size (0 x 0: it could): not
  // retried until the size changes.
  int SurfaceMaskFailedSize[2] = { 0, 0 };
  int Channels = 1; // values the estimator writes per texel: 1 or 3
  int TileSize = 4; // side of the tile of per-pixel rotations: 4 or 8

  vtkSmartPointer<vtkTextureObject> Occlusion;
  vtkTextureObject* BoundInComposite = nullptr;
  vtkSmartPointer<vtkOpenGLFramebufferObject> FrameBuffer;
  vtkFXRenderUtilities::FullScreenQuad Quad;
  // At half resolution, Depth32F: 0 where a texel holds a surface (SkipBackground)
  vtkFXRenderUtilities::DepthMask SurfaceMask;
  bool MakeSurfaceMask(vtkOpenGLRenderWindow* window, vtkTextureObject* depth, int step);
  /** Steps on each side of a horizon slice: NumberOfSamples / 4, at least 1. */
  int GetHorizonSteps() const;
  /** What the shader writes where there is no surface. */
  void GetOpenValue(float value[4]) const;

private:
  vtkFXSSAOPass(const vtkFXSSAOPass&) = delete;
  void operator=(const vtkFXSSAOPass&) = delete;
};

#endif
