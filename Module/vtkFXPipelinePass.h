/**
 * @class   vtkFXPipelinePass
 * @brief   The one pass a VTK application installs: renderer->SetPass(pipeline).
 *
 * Each frame it
 * 1. updates VTK's lights, then analyses the scene on the CPU into a
 *    vtkFXSceneInfo (opaque, forward-opaque, translucent, volume, overlay
 *    and emissive props; lights; material terms),
 * 2. decides which effects run (enabled, given work by the scene, inputs
 *    available) and orders them by their stage and by the dependencies of
 *    their named inputs, reporting a missing input or a cycle,
 * 3. sets up the camera (an internal vtkCameraPass) and runs the frame:
 *
 *      light-space effects          (shadow maps; with or without opaque props)
 *      G-buffer                     (opaque props; only the channels read)
 *      after-G-buffer effects       (occlusion, blur)
 *    [ HDR target, RGBA16F          (only while a post-process effect runs)
 *      composite                    (VTK's light model + effects' hook code)
 *      forward-opaque, translucent, volumes   (VTK's own steps)
 *      post-process effects ]       (glow, lines)
 *      overlay                      (2D props)
 *
 * Passes with no work in the current scene are left out (no opaque props:
 * no G-buffer, no composite; no post-process effect: no HDR target). While a
 * vtkHardwareSelector renders (picking), it lets the selector draw the props
 * as VTK's forward renderer does (vtkFXSelectionPass), so picking keeps
 * working.
 *
 * Reads the renderer's props and lights; writes the renderer's framebuffer,
 * depth-tested against what it holds (layered renderers that preserve the
 * depth buffer keep what the layers below drew). One pipeline serves one
 * renderer: its buffers follow the renderer it last drew, so a pipeline
 * shared by two renderers reallocates them at every render (it warns once),
 * and one moved to another window releases its GL objects first.
 * Per-pass GPU times (vtkOpenGLRenderTimer, results a frame or more late)
 * and the list of passes that ran are exposed for benchmarks and tests.
 *
 * Cost: the scene analysis is one loop over the props per frame; the rest
 * is the cost of the passes it schedules, and nothing for those it leaves
 * out.
 *
 * With no effect the image matches VTK's own forward render (PSNR >= 50 dB
 * on the test scenes, apart from multisample anti-aliasing, which the
 * G-buffer does not do: compare in windows with SetMultiSamples(0)). In a
 * multisampled window FXAA stands in for it (MultisampleFXAA).
 */
#ifndef vtkFXPipelinePass_h
#define vtkFXPipelinePass_h

#include "vtkFXGBufferPass.h" // for the channel count
#include "vtkFXModule.h"
#include "vtkFXSceneInfo.h" // for GetLastSceneInfo
#include "vtkRenderPass.h"
#include "vtkSmartPointer.h"
#include "vtkWeakPointer.h"

#include <string>
#include <utility>
#include <vector>

class vtkCameraPass;
class vtkFXBilateralBlurPass;
class vtkFXDirectionalOcclusionPass;
class vtkFXSSAOPass;
class vtkFXCompositePass;
class vtkFXEffectPass;
class vtkFXHDRTargetPass;
class vtkFXTimedSequencePass;
class vtkFXTranslucentPass;
class vtkLightsPass;
class vtkOpaquePass;
class vtkRenderer;
class vtkOverlayPass;
class vtkHiddenLineRemovalPass;
class vtkFXAntiAliasingPass;
class vtkFXVolumePass;
class vtkWindow;

class VTKFX_EXPORT vtkFXPipelinePass : public vtkRenderPass
{
public:
  static vtkFXPipelinePass* New();
  vtkTypeMacro(vtkFXPipelinePass, vtkRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * What the scene analysis found in the last frame (its prop and light
   * pointers are valid during that frame only).
   */
  const vtkFXSceneInfo& GetLastSceneInfo() const { return this->LastScene; }

  /**
   * G-buffer channel to show on screen instead of the lit image (a
   * vtkFXGBufferPass::Channel), or -1 (default) for the lit image.
   */
  vtkSetClampMacro(DebugChannel, int, -1, vtkFXGBufferPass::NumberOfChannels - 1);
  vtkGetMacro(DebugChannel, int);

  /**
   * In a multisampled framebuffer (VTK's default window asks for 8
   * samples), smooth the image with VTK's FXAA filter, as the renderer's
   * UseFXAA does, in frames that draw a G-buffer (default on). The G-buffer
   * holds one sample per pixel, so its props' edges would otherwise be
   * aliased where VTK's forward render blends their samples (scene:spheres
   * against VTK's multisampled image: 35.4 dB without, 39.7 dB with). Off,
   * the deferred edges stay as drawn; the renderer's UseFXAA
   * applies either way. Costs the filter's copy and pass (see
   * vtkFXAntiAliasingPass).
   */
  vtkSetMacro(MultisampleFXAA, bool);
  vtkGetMacro(MultisampleFXAA, bool);
  vtkBooleanMacro(MultisampleFXAA, bool);

  ///@{
  /**
   * Names of the passes that ran in the last frame, in order: "lights",
   * light-space effects by name, "gbuffer", after-G-buffer effects,
   * "hdr-target" when post-process effects run (the passes inside it
   * follow), "composite", "forward-opaque", "translucent", "volumes",
   * post-process effects, "overlay"; or
   * "selection-lights", "selection" while a hardware selector renders.
   */
  int GetNumberOfPassesThatRan() const;
  const char* GetPassThatRan(int i) const;
  ///@}

  /**
   * Most recent completed GPU time of a pass by name, in milliseconds, or -1
   * when no measurement has completed yet.
   */
  double GetPassMilliseconds(const char* name);

  /**
   * Bytes per pixel of the G-buffer textures allocated in the last frame
   * (0 when the G-buffer did not run).
   */
  int GetGBufferBytesPerPixel() const;

  /**
   * Bytes per pixel of the HDR target in the last frame (0 when no
   * post-process effect ran, and then none is allocated).
   */
  int GetHDRTargetBytesPerPixel() const;

  /**
   * Channels the G-buffer allocated in the last frame (a mask of
   * vtkFXGBufferPass::ChannelBit()).
   */
  unsigned int GetGBufferChannels() const;

  ///@{
  /**
   * Ambient occlusion (turns directional occlusion off): adds a vtkFXSSAOPass ("ssao") and a
   * vtkFXBilateralBlurPass ("ssao-blur") to the effects, connected as
   * ssao-blur.source <- ssao.occlusion and ssao.denoised <-
   * ssao-blur.blurred (the SSAO's composite code reads the blurred result
   * while the blur runs). Off by default; while off, neither runs and their
   * textures and G-buffer channels are released.
   */
  virtual void SetAmbientOcclusion(bool enabled);
  vtkGetMacro(AmbientOcclusion, bool);
  vtkBooleanMacro(AmbientOcclusion, bool);
  vtkFXSSAOPass* GetSSAOPass();
  vtkFXBilateralBlurPass* GetOcclusionBlurPass();
  ///@}

  ///@{
  /**
   * Directional occlusion (normal-mapped screen-space occlusion, seed
   * 000): adds a vtkFXDirectionalOcclusionPass ("do") and a
   * vtkFXBilateralBlurPass ("do-blur", Gaussian of radius 4 at half
   * resolution: the seed's 17-texel blur), connected as ssao/ssao-blur
   * are, and, while its Bleeding is above 0, a second blur
   * ("do-bleed-blur") of its output "bleeding" into its input
   * "bleeding-denoised". It replaces ambient occlusion: the pipeline runs one of the two,
   * so turning either on turns the other off. Off by default. The falloff
   * (SetAmbientOcclusionFalloff) applies to both.
   */
  virtual void SetDirectionalOcclusion(bool enabled);
  vtkGetMacro(DirectionalOcclusion, bool);
  vtkBooleanMacro(DirectionalOcclusion, bool);
  vtkFXDirectionalOcclusionPass* GetDirectionalOcclusionPass();
  vtkFXBilateralBlurPass* GetDirectionalOcclusionBlurPass();
  ///@}

  enum AmbientOcclusionQualityLevel
  {
    Low = 0,
    Medium,
    High
  };

  ///@{
  /**
   * Ambient-occlusion presets that set the estimator, its samples, its
   * resolution and the blur together, for the falloff (definition) in use;
   * measured with vtkfx-bench ao at 640x480 against the ray-traced
   * reference of the same definition:
   *
   *   preset        Binary (default)              CubeRoot
   *   Low           hemisphere 8, half, blur 4    hemisphere 8, half, blur 4
   *   Medium (def.) horizon 16, half, blur 4      horizon 8, half, blur 4
   *   High          horizon 16, full, box 2       hemisphere 16, half, blur 4
   *
   * (blur N: Gaussian of radius N; box 2: vtkFXBilateralBlurPass::Box.)
   *
   * Medium is ahead of every vtkSSAOPass setting on PSNR at a lower cost on
   * the bench scenes; Low costs about the same (cheaper on some scenes) and,
   * with Binary, is the more accurate on scene:corner, behind elsewhere; High keeps more fine
   * structure (Binary, at about 3x Medium's cost) or is the most accurate
   * on some scenes (CubeRoot). Setting the quality or the falloff applies
   * the preset at once, blur included (it enables the blur pass); the SSAO
   * and blur parameters can be tuned after it. vtkFXSSAOPass's own
   * defaults are the Binary Medium row.
   */
  virtual void SetAmbientOcclusionQuality(int quality);
  vtkGetMacro(AmbientOcclusionQuality, int);
  virtual void SetAmbientOcclusionFalloff(int falloff); // a vtkFXSSAOPass::Falloff
  int GetAmbientOcclusionFalloff();
  ///@}

  ///@{
  /**
   * Effects. An effect runs under `name` (its name in timings, in the
   * passes that ran and in input connections "name.output") when it is
   * enabled and the scene gives it work, at its stage
   * (vtkFXEffectPass::Stage), after the producers of its inputs; ties keep
   * the order of adding. Its composite code goes into the composite, and
   * the G-buffer holds the channels it reads. A required input that names
   * no effect or output, an input from a later stage, or a cycle keeps the
   * effects concerned out and is reported (GetScheduleProblems); an input
   * whose producer has no work this frame keeps its consumer out silently.
   * Adding a name again replaces the effect of that name.
   */
  void AddEffect(const char* name, vtkFXEffectPass* effect);
  void RemoveEffect(const char* name);
  vtkFXEffectPass* GetEffect(const char* name);
  int GetNumberOfEffects() const;
  const char* GetEffectName(int i) const;
  ///@}

  /**
   * Why effects were left out of the last frame although enabled (missing
   * inputs, stage order, cycles), one line each; "" when none. Reported
   * with vtkErrorMacro when it changes.
   */
  const char* GetScheduleProblems() const { return this->ScheduleProblems.c_str(); }

  /**
   * The passes it composes, for applications that tune them.
   */
  vtkFXGBufferPass* GetGBufferPass();
  vtkFXCompositePass* GetCompositePass();
  vtkFXHDRTargetPass* GetHDRTargetPass();

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkFXPipelinePass();
  ~vtkFXPipelinePass() override;

  // ReleaseGraphicsResources, in w's context; with keepSharedEffects the
  // effects that another owner still holds keep theirs.
  void Release(vtkWindow* w, bool keepSharedEffects);
  // An effect leaving the pipeline (removed or replaced) frees its GL
  // objects in the context of the window it last drew in, or, where that
  // context cannot be made current now, at the next frame (or release).
  void ReleaseEffect(vtkFXEffectPass* effect);
  void ReleasePendingEffects(vtkWindow* window);
  std::vector<vtkSmartPointer<vtkFXEffectPass>> PendingReleases;
  // The references to `effect` this pipeline holds (its slots, its own
  // occlusion passes).
  int OwnReferences(vtkFXEffectPass* effect) const;
  vtkFXSceneInfo AnalyzeScene(const vtkRenderState* s) const;
  // Says which lights have a number that is not finite (the composite and
  // the shadows leave them out), when that set changes.
  void WarnAboutNonFiniteLights(const vtkFXSceneInfo& scene);
  void ScheduleDeferredFrame(const vtkFXSceneInfo& scene, vtkWindow* window);
  void ScheduleSelectionFrame();
  // Gives the camera the window's stereo state (see Render).
  static void UpdateCameraStereo(vtkRenderer* renderer);

  struct EffectSlot
  {
    std::string Name;
    vtkSmartPointer<vtkFXEffectPass> Effect;
    bool Active = false; // ran in the last deferred frame
    int Stage = -1;      // the stage it was scheduled at then
  };
  struct Connection; // an input resolved to a slot
  std::vector<size_t> OrderEffects(const vtkFXSceneInfo& scene, bool deferred);
  bool ResolveInputs(size_t consumer, std::vector<Connection>& connections);
  bool ReachesItself(size_t start, const std::vector<std::vector<Connection>>& inputs,
    const std::vector<bool>& candidate, const std::vector<bool>& placed) const;
  void ActivateEffects(const std::vector<size_t>& order, vtkWindow* window);
  void AddEffectPasses(vtkFXTimedSequencePass* sequence, const std::vector<size_t>& order, int stage);

  int DebugChannel = -1;
  bool MultisampleFXAA = true;
  bool AmbientOcclusion = false;
  bool DirectionalOcclusion = false;
  vtkSmartPointer<vtkFXDirectionalOcclusionPass> DirectionalOcclusionPass;
  vtkSmartPointer<vtkFXBilateralBlurPass> DirectionalOcclusionBlurPass;
  vtkSmartPointer<vtkFXBilateralBlurPass> BleedingBlurPass;
  int AmbientOcclusionQuality = Medium;
  void ApplyAmbientOcclusionPreset();
  // Adds (enabled) or removes effects under their names.
  void SetEffectGroup(
    bool enabled, const std::vector<std::pair<const char*, vtkFXEffectPass*>>& group);
  std::vector<EffectSlot> Effects;
  vtkSmartPointer<vtkFXSSAOPass> SSAOPass;
  vtkSmartPointer<vtkFXBilateralBlurPass> OcclusionBlurPass;
  vtkWeakPointer<vtkWindow> LastWindow; // to release effects removed between frames
  vtkWeakPointer<vtkRenderer> LastRenderer; // one renderer per pipeline (warned otherwise)
  bool WarnedSharedPipeline = false;
  std::vector<int> NonFiniteLights; // the last frame's (warned about)
  int WindowChanges = 0; // windows it moved to
  vtkFXSceneInfo LastScene;
  std::vector<std::string> LastPasses;
  std::string ScheduleProblems;
  bool GBufferRan = false;
  bool HDRTargetRan = false;

  vtkSmartPointer<vtkCameraPass> CameraPass;
  vtkSmartPointer<vtkFXTimedSequencePass> Sequence;
  vtkSmartPointer<vtkFXTimedSequencePass> HDRSequence; // inside the HDR target
  vtkSmartPointer<vtkFXHDRTargetPass> HDRTargetPass;
  vtkSmartPointer<vtkLightsPass> LightsPass;
  vtkSmartPointer<vtkOpaquePass> OpaquePass;
  // The G-buffer's draw while the renderer's UseHiddenLineRemoval meets a
  // wireframe prop (VTK's own pass: surfaces into depth, then the lines).
  vtkSmartPointer<vtkHiddenLineRemovalPass> HiddenLinePass;
  vtkSmartPointer<vtkFXGBufferPass> GBufferPass;
  vtkSmartPointer<vtkFXCompositePass> CompositePass;
  vtkSmartPointer<vtkFXTranslucentPass> TranslucentPass;
  vtkSmartPointer<vtkFXVolumePass> VolumetricPass;
  vtkSmartPointer<vtkOverlayPass> OverlayPass;
  vtkSmartPointer<vtkFXAntiAliasingPass> AntiAliasingPass;
  bool AntiAliasingRan = false;
  vtkSmartPointer<vtkRenderPass> SelectionPass;
  vtkSmartPointer<vtkRenderPass> ForwardOpaquePass;

private:
  vtkFXPipelinePass(const vtkFXPipelinePass&) = delete;
  void operator=(const vtkFXPipelinePass&) = delete;
};

#endif
