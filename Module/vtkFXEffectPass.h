/**
 * @class   vtkFXEffectPass
 * @brief   Base class of the effects that plug into vtkFXPipelinePass.
 *
 * An effect declares
 * - which G-buffer channels it reads (GetRequiredChannels) and whether the
 *   current scene gives it work (HasWork, from the frame's vtkFXSceneInfo);
 * - named inputs and outputs: an output carries what a consumer needs
 *   (texture, resolution step, values per texel, format, where a guide depth
 *   rides along); an input is connected by name to another effect's output,
 *   "effect.output" with the effect's name in the pipeline
 *   (SetInputConnection), or directly to an effect object in a hand-built
 *   chain (SetInputProducer);
 * - optional shader code for named points of the deferred composite
 *   (GetCompositeCode) and the resources that code reads
 *   (BindCompositeResources).
 *
 * The pipeline runs an enabled effect that has work at its stage, after the
 * producers of its inputs; it allocates exactly the G-buffer channels the
 * active effects read and hands each the G-buffer (SetGBuffer). Stages, in
 * frame order:
 * - LightSpace: before the G-buffer, whether or not any prop is opaque
 *   (shadow maps seen from the lights);
 * - AfterGBuffer: reads G-buffer channels, writes its outputs (occlusion);
 * - Composite: no pass of its own; contributes composite code only;
 * - PostProcess: after the lit image, forward-opaque, translucent props and
 *   volumes, before the 2D overlay; it draws into the pipeline's HDR target
 *   (RGBA16F), which the pipeline allocates only while such an effect runs
 *   and needs it (GetNeedsHDRTarget), else into the framebuffer.
 *
 * Composite hook points (CompositeHook), in the order they run per pixel:
 * - Declarations: uniforms and functions;
 * - LightVisibility: once per light, may scale `lightVisibility` (float,
 *   starts at 1) from `lightIndex`, `position` (view space), `n`;
 * - Ambient: after the lights, may scale `ambientVisibility` (vec3, starts
 *   at 1), which darkens the ambient term and, by the composite's
 *   OcclusionDiffuseStrength, the diffuse light; may also change
 *   `diffuseLight` and `specularLight`;
 * - Color: may change the final `color` (vec3) of lit and unlit pixels
 *   (`lit` tells which; false also for pre-lit ones, see below).
 * - DiffuseResponse: inside each light's computation, may reshape `df`,
 *   the light's diffuse factor (max(0, n.l) times its attenuation), before
 *   it multiplies the light's colour (toon bands); highlights keep the
 *   raw factor. It sees `df` only (a function of its own).
 * The hooks are listed in enum order; DiffuseResponse runs within the
 * lights, between LightVisibility calls.
 * Background pixels never reach a hook. LightVisibility runs for lit
 * pixels only (lighting on, no debug channel shown), Ambient for lit and
 * pre-lit ones (VTK's PBR materials, whose colour the composite keeps and
 * occludes, in linear light, as it does the diffuse light); Color runs for
 * every covered pixel. They see `texCoord`, `n` (view space; +z for unlit
 * pixels), `albedo`, `lit` and `position` (view space, when the G-buffer
 * has linear depth: request it in GetRequiredChannels; 0 otherwise).
 * Declarations come before the composite's own functions. In the code an
 * effect returns, '@' stands for a prefix the composite makes unique per
 * effect, so two effects can declare `uniform sampler2D @input;`; the same
 * prefix comes back in BindCompositeResources.
 *
 * A disabled effect, or one without work, is left out of the frame, and the
 * channels only it read are released. What an effect reads and writes and
 * what it costs is documented by each subclass.
 */
#ifndef vtkFXEffectPass_h
#define vtkFXEffectPass_h

#include "vtkFXModule.h"
#include "vtkFXSceneInfo.h" // for HasWork
#include "vtkOpenGLRenderPass.h"
#include "vtkWeakPointer.h" // for the input producers

#include <string>
#include <vector>

class vtkFXGBufferPass;
class vtkRenderer;
class vtkShaderProgram;
class vtkTextureObject;

class VTKFX_EXPORT vtkFXEffectPass : public vtkOpenGLRenderPass
{
public:
  vtkTypeMacro(vtkFXEffectPass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Stage
  {
    LightSpace = 0,
    AfterGBuffer,
    Composite,
    PostProcess,
    NumberOfStages
  };
  static const char* GetStageName(int stage);

  /**
   * Where in the frame the effect runs (default AfterGBuffer).
   */
  vtkSetClampMacro(Stage, int, LightSpace, PostProcess);
  vtkGetMacro(Stage, int);

  /**
   * Effects start enabled; a disabled effect is left out of the frame.
   */
  vtkSetMacro(Enabled, bool);
  vtkGetMacro(Enabled, bool);
  vtkBooleanMacro(Enabled, bool);

  /**
   * G-buffer channels the effect reads, as a mask of
   * vtkFXGBufferPass::ChannelBit(). An effect that reads any runs only when
   * the G-buffer does (some prop is opaque). vtkFXPipelinePass asks after
   * HasWork in the same frame, so the mask may follow the scene.
   */
  virtual unsigned int GetRequiredChannels() = 0;

  /**
   * Whether the effect samples the surfaces' own orientation (occlusion
   * hemispheres, blur guides) rather than the normal they are shaded with.
   * While such an effect runs and a visible prop perturbs its normal (a
   * bump or a normal texture), vtkFXPipelinePass allocates the G-buffer's
   * GeometricNormal channel, which the effect reads through
   * vtkFXGBufferPass::GetGeometricNormalTexture(). Default false.
   */
  virtual bool GetReadsGeometricNormal() { return false; }

  /**
   * For an effect whose DiffuseResponse hook raises a light's diffuse
   * factor (attenuation x cosine) to a level above it, as toon bands do:
   * the smallest factor it raises, from which on a light adds a whole
   * level however dim it is. The composite's light tiles then reach every
   * point where a light's factor can get there, not only where its light
   * exceeds the cutoff. Default 0: the hook (if any) never raises light.
   * The smallest positive double (denorm_min) says every positive factor
   * is raised: no light is then bounded.
   */
  virtual double GetSmallestRaisedDiffuse() { return 0.0; }

  /**
   * Whether the effect has work in this frame. Default: any prop the
   * G-buffer captures.
   */
  virtual bool HasWork(const vtkFXSceneInfo& scene);

  /**
   * Whether the effect, at the PostProcess stage, needs the pipeline's HDR
   * target (it reads the lit image or writes values above 1). Default
   * true; an effect that only blends displayable colours over the image
   * (feature lines) returns false, and when no running effect needs the
   * target the pipeline leaves it out (it costs a copy in and a full-screen
   * pass out).
   */
  virtual bool GetNeedsHDRTarget() { return true; }

  /**
   * Whether the effect, at the PostProcess stage, reads from the HDR
   * target's alpha how much of each lit surface's light the translucent
   * props and volumes drawn over it let through
   * (vtkFXCompositePass::SetMarksTransmittance; default no). Asked after
   * HasWork; such an effect needs the HDR target.
   */
  virtual bool GetReadsTransmittance() { return false; }

  ///@{
  /**
   * Effects that change how VTK's own forward step shades translucent
   * props (shadows on them) return true from GetShadesForward; the
   * pipeline then calls BeginForwardShading before its translucent step
   * and EndForwardShading after it, with that step's render state (its
   * props: the effect may extend their shaders through its
   * vtkOpenGLRenderPass hooks in between). Default: false, no-ops.
   */
  virtual bool GetShadesForward() { return false; }
  virtual void BeginForwardShading(const vtkRenderState*) {}
  virtual void EndForwardShading(const vtkRenderState*) {}
  ///@}

  /**
   * What an output holds after the effect rendered.
   */
  struct Output
  {
    vtkTextureObject* Texture = nullptr; // nullptr until the effect rendered
    int Step = 1;            // texel i covers G-buffer pixel i * Step
    int Components = 0;      // values per texel (not counting a guide depth)
    int Format = -1;         // a vtkFXRenderUtilities::TextureFormat
    int DepthComponent = -1; // component holding the texel's linear depth, or -1
    // 0: one value per component; 1: vtkFXDirectionalOcclusionPass's
    // packing of three values with their normal and depth (R = values 1
    // and 2, 12 bits each, G = value 3, B = octahedral normal, 12 bits a
    // coordinate, A = depth; vtkFXNormalCoding.glsl's fxPack12).
    int Packing = 0;
    // Where the G-buffer has no surface, when the producer left those
    // texels out: a depth texture of the output's size, 1 there
    // (RenderTargetScope::SkipWhereDepthIsOne), and the value every such
    // texel holds; nullptr when not known.
    vtkTextureObject* Surfaces = nullptr;
    float Background[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
  };

  ///@{
  /**
   * Named outputs, in declaration order.
   */
  int GetNumberOfOutputs() const;
  const char* GetOutputName(int i) const;
  bool HasOutput(const char* name) const;
  virtual Output GetOutput(const char* name);
  /** Texture of an output (the first one when name is nullptr). */
  vtkTextureObject* GetOutputTexture(const char* name = nullptr);
  ///@}

  ///@{
  /**
   * Named inputs, in declaration order. An optional input may stay
   * unconnected (the effect then does without it); a required one that is
   * not connected, or whose source does not exist, keeps the effect out of
   * the frame, and vtkFXPipelinePass reports why. An input read in the
   * composite (by the effect's hook code) only needs its producer to run
   * before the composite.
   */
  int GetNumberOfInputs() const;
  const char* GetInputName(int i) const;
  bool IsInputOptional(int i) const;
  bool IsInputReadInComposite(int i) const;
  ///@}

  /**
   * Connect input `input` to an output by name: "effect.output", or
   * "effect" for its first output, where effect is a name given to
   * vtkFXPipelinePass::AddEffect. nullptr or "" disconnects.
   */
  void SetInputConnection(const char* input, const char* source);
  const char* GetInputConnection(const char* input) const;

  /**
   * The effect and output an input reads from. vtkFXPipelinePass sets it
   * each frame from the connection names; a hand-built chain sets it
   * directly. nullptr producer unbinds.
   */
  void SetInputProducer(const char* input, vtkFXEffectPass* producer, const char* output);
  vtkFXEffectPass* GetInputProducer(const char* input) const;

  /**
   * What the producer of an input wrote (Texture nullptr when the input is
   * unbound or its producer has not rendered).
   */
  Output GetInput(const char* input) const;

  enum CompositeHook
  {
    Declarations = 0,
    LightVisibility,
    Ambient,
    Color,
    DiffuseResponse,
    NumberOfCompositeHooks
  };

  /**
   * GLSL the effect adds at a composite hook point (see the class
   * documentation); empty (the default) for none.
   */
  virtual std::string GetCompositeCode(int hook);

  /**
   * Bind what the composite code reads (textures, uniforms named with
   * `prefix` in place of '@'), and release it after the composite drew.
   */
  virtual void BindCompositeResources(vtkShaderProgram* program, const std::string& prefix);
  virtual void UnbindCompositeResources() {}

  /**
   * The G-buffer the effect reads; set by the pipeline before Render().
   */
  virtual void SetGBuffer(vtkFXGBufferPass* gbuffer);
  vtkGetObjectMacro(GBuffer, vtkFXGBufferPass);

protected:
  vtkFXEffectPass() = default;
  ~vtkFXEffectPass() override;

  void DeclareInput(const char* name, bool optional, bool readInComposite);
  void DeclareOutput(const char* name);
  // Warns, once, when the renderer's image is drawn tile by tile
  // (vtkFXRenderUtilities::IsRenderingTiles): an effect that reads beyond
  // a pixel sees only the tile. `missed`: what it cannot see across a
  // tile's border.
  void WarnIfDrawnInTiles(vtkRenderer* renderer, const char* missed);

  int Stage = AfterGBuffer;
  bool Enabled = true;
  vtkFXGBufferPass* GBuffer = nullptr;
  bool WarnedTiles = false; // an image drawn tile by tile (said once)

private:
  vtkFXEffectPass(const vtkFXEffectPass&) = delete;
  void operator=(const vtkFXEffectPass&) = delete;

  struct InputPort
  {
    std::string Name;
    bool Optional = false;
    bool ReadInComposite = false;
    std::string Connection;                  // "effect.output" or ""
    vtkWeakPointer<vtkFXEffectPass> Producer; // resolved
    std::string ProducerOutput;
  };
  const InputPort* FindInput(const char* name) const;
  InputPort* InputToChange(const char* name); // reports an unknown name
  std::vector<InputPort> Inputs;
  std::vector<std::string> Outputs;
};

#endif
