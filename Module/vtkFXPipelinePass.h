/**
 * @class   vtkFXPipelinePass
 * @brief   The one pass a VTK application installs: renderer->SetPass(pipeline).
 *
 * Each frame it
 * 1. analyses the scene on the CPU (opaque, translucent, volume and overlay
 *    props; whether any lit prop has ambient or specular terms; how many
 *    lights are on),
 * 2. updates VTK's lights and sets up the camera (an internal vtkCameraPass),
 * 3. renders the opaque props into a vtkFXGBufferPass that allocates only
 *    the channels the active passes read,
 * 4. lights them with vtkFXCompositePass (VTK's light model, deferred),
 *    then draws forward the opaque props the G-buffer cannot capture,
 * 5. lets VTK draw translucent props (its own depth peeling / OIT choice),
 *    volumes and 2D overlays, depth-tested against the G-buffer depth.
 * Passes with no work in the current scene are left out (no opaque props:
 * no G-buffer at all). While a vtkHardwareSelector renders (picking), it
 * lets the selector draw the props as VTK's forward renderer does
 * (vtkFXSelectionPass), so picking keeps working.
 *
 * Reads the renderer's props and lights; writes the renderer's framebuffer.
 * Per-pass GPU times (vtkOpenGLRenderTimer, results a frame or more late)
 * and the list of passes that ran are exposed for benchmarks and tests.
 *
 * Cost: the scene analysis is one loop over the props per frame; the rest
 * is the cost of the passes it schedules, and nothing for those it leaves
 * out.
 *
 * Effects (vtkFXEffectPass subclasses) plug in by name with AddEffect and
 * run at their stage when enabled and given work; with none the image
 * matches VTK's own forward render (PSNR >= 40 dB on the test scenes, apart
 * from multisample anti-aliasing, which the G-buffer does not do: render
 * windows should use SetMultiSamples(0)).
 */
#ifndef vtkFXPipelinePass_h
#define vtkFXPipelinePass_h

#include "vtkFXGBufferPass.h" // for the channel count
#include "vtkFXModule.h"
#include "vtkRenderPass.h"
#include "vtkSmartPointer.h"
#include "vtkWeakPointer.h"

#include <string>
#include <vector>

class vtkCameraPass;
class vtkFXBilateralBlurPass;
class vtkFXSSAOPass;
class vtkFXCompositePass;
class vtkFXEffectPass;
class vtkFXTimedSequencePass;
class vtkLightsPass;
class vtkOpaquePass;
class vtkOverlayPass;
class vtkVolumetricPass;
class vtkWindow;

class VTKFX_EXPORT vtkFXPipelinePass : public vtkRenderPass
{
public:
  static vtkFXPipelinePass* New();
  vtkTypeMacro(vtkFXPipelinePass, vtkRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * What the scene analysis found in the last frame.
   */
  struct SceneInfo
  {
    int OpaqueProps = 0;        // captured by the G-buffer
    int ForwardOpaqueProps = 0; // opaque, drawn forward (vtkFXForwardOpaquePass)
    int TranslucentProps = 0;
    int VolumeProps = 0;
    int OverlayProps = 0;
    bool AnyAmbient = false;  // a lit captured prop with an ambient term
    bool AnySpecular = false; // a lit captured prop with a specular term
    int LightsOn = 0;
    int LightingComplexity = 0; // vtkOpenGLRenderer's, 0 when no light is on
  };
  const SceneInfo& GetLastSceneInfo() const { return this->LastScene; }

  /**
   * G-buffer channel to show on screen instead of the lit image (a
   * vtkFXGBufferPass::Channel), or -1 (default) for the lit image.
   */
  vtkSetClampMacro(DebugChannel, int, -1, vtkFXGBufferPass::NumberOfChannels - 1);
  vtkGetMacro(DebugChannel, int);

  ///@{
  /**
   * Names of the passes that ran in the last frame, in order: "lights",
   * "gbuffer", effects by name, "composite", "forward-opaque",
   * "translucent", "volumes", "overlay"; or
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
   * Channels the G-buffer allocated in the last frame (a mask of
   * vtkFXGBufferPass::ChannelBit()).
   */
  unsigned int GetGBufferChannels() const;

  ///@{
  /**
   * Ambient occlusion: a vtkFXSSAOPass ("ssao") followed by a
   * vtkFXBilateralBlurPass ("ssao-blur", which also upsamples the
   * half-resolution result) in the effect slots, feeding the composite
   * (vtkFXCompositePass::SetOcclusionEffect). Off by default; while off,
   * neither runs and their textures and G-buffer channels are released.
   */
  virtual void SetAmbientOcclusion(bool enabled);
  vtkGetMacro(AmbientOcclusion, bool);
  vtkBooleanMacro(AmbientOcclusion, bool);
  vtkFXSSAOPass* GetSSAOPass();
  vtkFXBilateralBlurPass* GetOcclusionBlurPass();
  ///@}

  ///@{
  /**
   * Effect slots. An effect runs at its stage (vtkFXEffectPass::Stage), in
   * the order added, under `name` (its name in timings and in the passes that
   * ran), when it is enabled and the scene gives it work, and, if it reads
   * another effect's output (vtkFXEffectPass::SetInputEffect), when that one
   * runs before it; the G-buffer then also holds the channels it reads.
   * Adding a name again replaces the effect of that name.
   */
  void AddEffect(const char* name, vtkFXEffectPass* effect);
  void RemoveEffect(const char* name);
  vtkFXEffectPass* GetEffect(const char* name);
  int GetNumberOfEffects() const;
  ///@}

  /**
   * The passes it composes, for applications that tune them.
   */
  vtkFXGBufferPass* GetGBufferPass();
  vtkFXCompositePass* GetCompositePass();

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkFXPipelinePass();
  ~vtkFXPipelinePass() override;

  SceneInfo AnalyzeScene(const vtkRenderState* s) const;
  void ScheduleDeferredFrame(const SceneInfo& scene, vtkWindow* window);
  void ScheduleSelectionFrame();

  struct EffectSlot
  {
    std::string Name;
    vtkSmartPointer<vtkFXEffectPass> Effect;
    bool Active = false; // ran in the last deferred frame
  };
  void ScheduleEffects(int stage);
  bool RanEffect(vtkFXEffectPass* effect) const;

  int DebugChannel = -1;
  bool AmbientOcclusion = false;
  std::vector<EffectSlot> Effects;
  vtkSmartPointer<vtkFXSSAOPass> SSAOPass;
  vtkSmartPointer<vtkFXBilateralBlurPass> OcclusionBlurPass;
  vtkWeakPointer<vtkWindow> LastWindow; // to release effects removed between frames
  SceneInfo LastScene;
  std::vector<std::string> LastPasses;
  bool GBufferRan = false;

  vtkSmartPointer<vtkCameraPass> CameraPass;
  vtkSmartPointer<vtkFXTimedSequencePass> Sequence;
  vtkSmartPointer<vtkLightsPass> LightsPass;
  vtkSmartPointer<vtkOpaquePass> OpaquePass;
  vtkSmartPointer<vtkFXGBufferPass> GBufferPass;
  vtkSmartPointer<vtkFXCompositePass> CompositePass;
  vtkSmartPointer<vtkRenderPass> TranslucentPass;
  vtkSmartPointer<vtkVolumetricPass> VolumetricPass;
  vtkSmartPointer<vtkOverlayPass> OverlayPass;
  vtkSmartPointer<vtkRenderPass> SelectionPass;
  vtkSmartPointer<vtkRenderPass> ForwardOpaquePass;

private:
  vtkFXPipelinePass(const vtkFXPipelinePass&) = delete;
  void operator=(const vtkFXPipelinePass&) = delete;
};

#endif
