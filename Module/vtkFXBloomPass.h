/**
 * @class   vtkFXBloomPass
 * @brief   Glow around emissive props (and, optionally, bright light) on the HDR image.
 *
 * Reads the G-buffer's emission channel (the EMISSIVE_COLOR of lit props,
 * see vtkFXGBufferPass, and the colour of unlit ones) and, with a
 * threshold set, the lit HDR image's light above it (soft knee). Builds a
 * pyramid by repeated 13-tap downsampling (Jimenez 2014), the first step
 * from full resolution a 4x4 box of four bilinear taps (firefly
 * suppression by Karis averaging there), climbs back with 3x3
 * tent upsampling, each level adding an equal share, and adds Intensity
 * times the result onto the pipeline's HDR target (the last step, to full
 * resolution, reads bilinearly; it also composites the glow's coverage, its
 * largest component up to 1, over the target's alpha, as VTK blends a
 * translucent surface's, so over a transparent background an RGBA
 * screenshot keeps the halo). Each filter is
 * normalised, so the glow's total equals Intensity times the total of the
 * source (the emission plus the light above the threshold), with
 * FireflySuppression off (it deliberately takes energy from isolated
 * bright pixels). Each level's texel covers exactly 2 x 2 of the level
 * above, at odd sizes too, and the filters read the levels mirrored at
 * the image's own edges (not the levels' texture edges, which lie up to
 * half a texel past it at odd sizes), so light near a border weighs about
 * what it weighs elsewhere (TestBloom: inside the image within 0.3%; at
 * the bottom and left edges 0.3%; at the top and right edges of odd sizes,
 * where the pyramid's texels straddle the edge, up to 1.4%, and 3% in the
 * corner where both are odd).
 *
 * The glow reaches about Radius x the height the renderer covers in the
 * image (its viewport's, or in a scaled screenshot, which
 * vtkWindowToImageFilter renders in tiles of the window's size, its
 * viewport's height in the whole scaled window; the glow does not cross the
 * tiles' seams): the pyramid has
 * the levels below full resolution up to the one whose blur
 * (GetLevelSigma) is nearest that reach (at least 1, at most 10, fewer
 * when a level would be under 2 pixels).
 *
 * NaN and infinite sources never spread: NaN counts as 0 and anything
 * above 65504 (the largest half float) as 65504; with FireflySuppression
 * on, such a pixel adds about what one pixel of value 1 adds.
 *
 * Emission hidden by what is drawn in front of its surface (opaque props
 * the G-buffer does not capture, drawn forward; the depth of the layers
 * below) does not glow: where such props or layers are in the frame, the
 * prefilter compares the G-buffer's depth with the target's. Translucent
 * props and volumes drawn over an emitter dim its glow as they dim the
 * emitter, by the fraction T of its light they let through: the composite
 * marks the lit surfaces' alpha, which the translucent and volume steps'
 * blending scales by T, and the prefilter reads T back (exact for VTK's
 * volumes and depth peeling, within 0.001 for its order-independent
 * transparency; see vtkFXCompositePass::SetMarksTransmittance). Only when
 * such a prop's screen rectangle meets the emitters' (GetReadsTransmittance).
 * Cost then: the HDR target and the prefilter (one full-resolution pass
 * over the glow's rectangle, two texel reads).
 *
 * Stage PostProcess; vtkFXPipelinePass keeps its HDR target while it runs
 * with a threshold, or with emission that may be hidden or dimmed
 * (GetNeedsHDRTarget).
 * Work: when a visible prop is emissive (vtkFXSceneInfo::EmissiveProps) or
 * a threshold is set; otherwise the pass, its textures and the emission
 * channel are left out and the image is exactly the one without bloom. The
 * emission channel is read (and allocated) only while some visible prop
 * emits.
 * Cost: one pass per level down and up, drawn only over the part of the
 * image the glow can reach (the screen rectangle of what the emissive props
 * draw, splats whole, widened by 4 deviations of the widest level; the whole
 * image with a threshold, or points or lines wider than a pixel), the first at half resolution with
 * 4 bilinear source reads per texel, the next with 13, each next one
 * at a quarter of the texels of the one before, 4 bilinear reads per
 * texel up; one full-resolution pass of 1 bilinear read, blended. With a
 * threshold, first a full-resolution pass of one texel read (two when some
 * prop emits: colour and emission) applies it per texel, before any
 * averaging, into an RGBA16F image the first step reads (8 bytes per
 * pixel, kept only while a threshold is set). Memory: two RGBA16F textures per level
 * (about 2 x 8 / 3 bytes per full-resolution pixel).
 */
#ifndef vtkFXBloomPass_h
#define vtkFXBloomPass_h

#include "vtkFXEffectPass.h"
#include "vtkFXModule.h"
#include "vtkFXSetGet.h" // for vtkFXSetClampMacro
#include "vtkFXRenderUtilities.h" // for the full-screen quads
#include "vtkSmartPointer.h"
#include "vtkWeakPointer.h" // for the sampler's window

#include <memory>
#include <string>
#include <vector>

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkTextureObject;

class VTKFX_EXPORT vtkFXBloomPass : public vtkFXEffectPass
{
public:
  static vtkFXBloomPass* New();
  vtkTypeMacro(vtkFXBloomPass, vtkFXEffectPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Total glow as a fraction of the total source light (0..100, default
   * 0.5).
   */
  vtkFXSetClampMacro(Intensity, double, 0.0, 100.0);
  vtkGetMacro(Intensity, double);

  /**
   * How far the glow reaches, as a fraction of the image's height (the
   * viewport's, or a scaled screenshot's) (0.001..1, default 0.05).
   */
  vtkFXSetClampMacro(Radius, double, 0.001, 1.0);
  vtkGetMacro(Radius, double);

  /**
   * Glow from the emission channel (default on).
   */
  vtkSetMacro(UseEmission, bool);
  vtkGetMacro(UseEmission, bool);
  vtkBooleanMacro(UseEmission, bool);

  /**
   * Glow also from lit light brighter than Threshold (linear units, as in
   * the HDR image; 0..65504). A negative value (default -1) turns this
   * off. The threshold applies to the light the surfaces reflect: the
   * emission channel's light is taken out of the lit image first, as it
   * glows in full anyway (counted once).
   */
  vtkFXSetClampMacro(Threshold, double, -1.0, 65504.0);
  vtkGetMacro(Threshold, double);

  /**
   * Width of the soft knee below the threshold, as a fraction of it
   * (0..1, default 0.5): light from Threshold x (1 - Knee) up glows
   * partly. NaN is refused with an error.
   */
  virtual void SetKnee(double knee);
  vtkGetMacro(Knee, double);

  /**
   * Karis averaging on the first step (default on): isolated very bright
   * pixels (fireflies, or a 1e30 emission) do not grow into squares.
   */
  vtkSetMacro(FireflySuppression, bool);
  vtkGetMacro(FireflySuppression, bool);
  vtkBooleanMacro(FireflySuppression, bool);

  /**
   * Levels below full resolution for a viewport of width x height, in an
   * image of `imageRows` rows (a scaled screenshot's, which
   * vtkWindowToImageFilter renders in tiles of the viewport's size; 0: the
   * viewport's own), whose height the glow's reach is a fraction of.
   */
  int GetNumberOfLevels(int width, int height, int imageRows = 0) const;

  /**
   * Standard deviation, in full-resolution pixels per axis, of the blur
   * that level k (1 = half resolution) receives on its way down and up:
   * the sum of the variances of its filters. Down, a 13-tap step from a
   * level of texel size 2^j pixels adds 1.75 x 4^j (its taps' spread, 1.5
   * texels^2, plus their 2x2 bilinear boxes, 0.25), the first step's 4x4
   * box 1.25 (spread 1, boxes 0.25); up, a tent step from a
   * level of texel size 2^m adds 0.4375 x 4^m (at twice the resolution the
   * four half-texel taps weigh the coarse texels 1/8, 4/8, 3/8 per axis,
   * a quarter of a texel off centre: variance 7/16), and the last step,
   * to full resolution, one bilinear read a quarter of a texel off centre
   * (weights 3/4, 1/4: variance 3/16), 0.75. So level k's glow is
   * close to a Gaussian of that deviation (1.4, 4.0, 8.5, 17.2, 34.5, ...
   * pixels), and the whole glow close to the mean of those Gaussians: the
   * reference vtkfx-bench bloom compares with.
   */
  static double GetLevelSigma(int k);

  /**
   * Blurred glow of the last frame, at half resolution, before Intensity:
   * what the final step spreads over the image (for tests and debugging;
   * nullptr before the first frame).
   */
  vtkTextureObject* GetGlowTexture();

  bool HasWork(const vtkFXSceneInfo& scene) override;

  /**
   * Only with a threshold: it reads the lit HDR image then. Glow from the
   * emission channel alone (which keeps values above 1 by itself) is added
   * onto whatever image the pipeline draws: on an 8-bit one,
   * min(1, min(1, lit) + glow) = min(1, lit + glow) for a non-negative
   * glow, so the result is the same and the HDR target's copy in and
   * write-back are saved.
   */
  bool GetNeedsHDRTarget() override
  {
    return this->Threshold >= 0.0 || this->MasksHiddenEmission || this->DimsEmissionByCoverage;
  }
  unsigned int GetRequiredChannels() override;

  /**
   * Whether translucent props or volumes may be drawn over an emitter
   * this frame (from HasWork): the glow then reads the emitters'
   * transmittance.
   */
  bool GetReadsTransmittance() override { return this->DimsEmissionByCoverage; }

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkFXBloomPass();
  ~vtkFXBloomPass() override;

  struct Level;
  // (`targetDepth`: the depth of the target the glow goes onto, where
  // the emission of hidden surfaces must be left out; else nullptr)
  // (`coverage`: the target's colour, whose alpha is 1024 T + f over the
  // emitters when something may be drawn over them, see
  // vtkFXCompositePass::SetMarksTransmittance; else nullptr)
  bool Downsample(vtkOpenGLRenderWindow* window, vtkTextureObject* color,
    vtkTextureObject* targetDepth, vtkTextureObject* coverage, int levels);
  /**
   * With a threshold, or emission to mask by depth: the glow's source per
   * full-resolution texel, into Prefiltered (`color` with a threshold,
   * `targetDepth` to mask, else nullptr).
   */
  bool Prefilter(vtkOpenGLRenderWindow* window, vtkTextureObject* color,
    vtkTextureObject* emission, vtkTextureObject* targetDepth, vtkTextureObject* coverage);
  void ReleasePrefilter(vtkWindow* window);
  bool Upsample(vtkOpenGLRenderWindow* window, int levels);
  void AddGlow(vtkOpenGLRenderWindow* window); // adds GetGlowTexture()
  vtkShaderProgram* ReadyProgram(int which, vtkOpenGLRenderWindow* window, const std::string& fs);
  void ComputeGlowRect(vtkRenderer* ren, int width, int height, int levels);
  // The normalized device coordinates `bounds` cover in the renderer's
  // view; false when they reach the camera's plane (anywhere on screen).
  static bool ProjectToScreen(
    vtkRenderer* ren, const double bounds[6], double ndcMin[3], double ndcMax[3]);
  // Whether a translucent prop or a volume may be drawn over an emitter:
  // their screen rectangles meet (or one cannot be told). From HasWork,
  // after EmissiveBounds.
  bool MayCoverEmitters(const vtkFXSceneInfo& scene) const;
  void LevelRect(int k, int rect[4]) const;
  void LevelRect(int k, const int size[2], int rect[4]) const; // level k of `size` texels
  static std::string WithMirror(const char* shader, const std::string& defines);

  double Intensity = 0.5;
  double Radius = 0.05;
  bool UseEmission = true;
  double Threshold = -1.0;
  double Knee = 0.5;
  bool FireflySuppression = true;
  bool ReadsEmission = true; // this frame: UseEmission and some prop emits (HasWork)
  bool MasksHiddenEmission = false; // this frame: something may hide an emitter (HasWork)
  bool DimsEmissionByCoverage = false; // this frame: something may be drawn over an emitter
  bool WarnedNoLitImage = false; // a threshold without an HDR target (said once)

  std::vector<std::unique_ptr<Level>> Levels;
  // With a threshold: the emission plus the lit light above the threshold,
  // full resolution (RGBA16F), what the first step down reads.
  vtkSmartPointer<vtkTextureObject> Prefiltered;
  vtkSmartPointer<vtkOpenGLFramebufferObject> PrefilterTarget;
  // World bounds of the emissive props (from HasWork), and the pixels of
  // the viewport the glow can reach, x0 y0 x1 y1 (ends excluded): the
  // pyramid and the final add draw there only.
  double EmissiveBounds[6] = { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 };
  int GlowRect[4] = { 0, 0, 0, 0 };
  // The full-resolution image the pyramid is built from, in pixels; and
  // sets uniform `name` to its extent in the texels of level k (-1: full
  // resolution), where the filters mirror (vtkFXBloomMirror.glsl).
  int FullSize[2] = { 1, 1 };
  void SetLevelExtent(vtkShaderProgram* program, const char* name, int k) const;
  unsigned int LinearSampler = 0; // GL sampler for reading the G-buffer's emission bilinearly
  vtkWeakPointer<vtkOpenGLRenderWindow> SamplerWindow; // whose context made it
  void ReleaseSampler();
  enum
  {
    FirstDown = 0,
    Down,
    PrefilterProgram,
    Up,
    Final,
    NumberOfPrograms
  };
  vtkFXRenderUtilities::FullScreenQuad Quads[NumberOfPrograms];

private:
  vtkFXBloomPass(const vtkFXBloomPass&) = delete;
  void operator=(const vtkFXBloomPass&) = delete;
};

#endif
