/**
 * @class   vtkFXGBufferPass
 * @brief   Renders the opaque props of its delegate into a G-buffer.
 *
 * Reads: the props its delegate renders (usually a vtkOpaquePass), through
 * VTK's shader-replacement hooks, so every vtkOpenGLPolyDataMapper subclass
 * (composite, glyph, point-gaussian, sphere/stick imposters) keeps its own
 * colouring, texturing, normals and depth.
 *
 * Writes, each as its own texture at the renderer's viewport size, and only
 * for the channels some consumer requested (SetRequiredChannels):
 * - Albedo       RGBA8   VTK's diffuse colour after scalar colouring and
 *                        texturing; alpha = opacity. Unlit fragments, and
 *                        PBR ones (pre-lit: the composite keeps VTK's
 *                        colour), store their final colour here (a PBR
 *                        prop's EMISSIVE_COLOR added, which the composite
 *                        keeps out of the occlusion where the emission
 *                        channel holds it too).
 * - Normal       RG16F   view-space shading normal, octahedral encoding
 *                        (Cigolle et al. 2014, "A Survey of Efficient
 *                        Representations for Independent Unit Vectors"): the
 *                        normal VTK lights with (a property's normal texture
 *                        applies, as VTK 9.1 applies it when the mesh has
 *                        tangents), tilted by the prop's bump (SetBump);
 *                        unlit fragments and uncovered pixels carry a
 *                        sentinel outside [-1,1]; pre-lit ones their
 *                        normal's code with x moved up by 3
 *                        (vtkFXNormalCoding.glsl: fxIsPrelit).
 * - LinearDepth  R32F    -z in view coordinates (world units), 0 = no surface.
 * - Specular     RGBA8   specular colour x intensity; alpha = sqrt(power / 128).
 * - Ambient      RGBA8   VTK's ambient term (ambient intensity x colour).
 *                        Albedo, Specular and Ambient are RGBA16F with
 *                        HDRMaterial on, for colours above 1.
 * - Emission     RGBA8   light-independent colour: the colour of unlit
 *                        fragments; for lit ones the prop's EMISSIVE_COLOR
 *                        (0 without). RGBA16F with HDREmission on, so that
 *                        emission above 1 (a glow's source) is kept.
 * - GeometricNormal RG16F the interpolated mesh normal before any normal
 *                        texture or bump, encoded as Normal: the surface's
 *                        own orientation, for effects that sample the
 *                        geometry around a pixel (occlusion hemispheres,
 *                        blur guides: vtkFXEffectPass::GetReadsGeometricNormal).
 *                        vtkFXPipelinePass allocates it only while such an
 *                        effect runs and a visible prop perturbs its normal
 *                        (PerturbsNormal); otherwise it equals Normal and
 *                        GetGeometricNormalTexture() returns Normal's.
 * plus a hardware depth texture (the renderer's depth format) that is
 * always allocated.
 *
 * Cost: one geometry pass with up to 7 render targets; memory is
 * GetBytesPerPixel() x viewport pixels. The mappers rebuild their shaders
 * only when the set of channels changes.
 *
 * Only props whose mappers call the render-pass hooks can be captured
 * (CanCapture: vtkActor and assemblies of actors); the pass leaves the others
 * out, and vtkFXPipelinePass draws them forward after the composite.
 * Limitation: the G-buffer does not blend, so soft (Gaussian) point splats
 * drawn in the opaque pass lose their blended fringe.
 *
 * Used alone (as the delegate of a vtkCameraPass) it only fills its
 * textures; vtkFXPipelinePass pairs it with vtkFXCompositePass.
 */
#ifndef vtkFXGBufferPass_h
#define vtkFXGBufferPass_h

#include "vtkFXModule.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkSmartPointer.h"

#include <string>
#include <unordered_map>
#include <vector>

class vtkActor;
class vtkInformationDoubleKey;
class vtkInformationDoubleVectorKey;
class vtkInformationStringKey;
class vtkOpenGLFramebufferObject;
class vtkProp;
class vtkOpenGLRenderWindow;
class vtkTextureObject;

class VTKFX_EXPORT vtkFXGBufferPass : public vtkOpenGLRenderPass
{
public:
  static vtkFXGBufferPass* New();
  vtkTypeMacro(vtkFXGBufferPass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Channels, in attachment order. Albedo comes first: the mapper's own
   * "discard if alpha <= 0" test, which runs after the channel writes, then
   * reads the opacity, and a draw that bypasses the hooks leaves its colour
   * there.
   */
  enum Channel
  {
    Albedo = 0,
    Normal,
    LinearDepth,
    Specular,
    Ambient,
    Emission,
    GeometricNormal,
    NumberOfChannels
  };

  /**
   * Bit of a channel in a channel mask.
   */
  static unsigned int ChannelBit(int channel) { return 1u << channel; }

  /**
   * Name of a channel ("normal", "depth", "albedo", "specular", "ambient",
   * "emission", "geometric-normal"), and the channel of a name (-1 if
   * unknown).
   */
  static const char* GetChannelName(int channel);
  static int GetChannelFromName(const char* name);

  /**
   * Channels to render, as a mask of ChannelBit(). Channels not in the mask
   * are not allocated and their textures are released. Default: all.
   */
  vtkSetMacro(RequiredChannels, unsigned int);
  vtkGetMacro(RequiredChannels, unsigned int);

  /**
   * Channels allocated by the last Render() (a subset of RequiredChannels).
   */
  vtkGetMacro(AllocatedChannels, unsigned int);

  /**
   * Texture of a channel after Render(), or nullptr if it is not allocated.
   */
  vtkTextureObject* GetChannelTexture(int channel);

  /**
   * The geometric normals: the GeometricNormal channel when allocated,
   * else the Normal channel (no prop perturbs its normal, so both agree).
   */
  vtkTextureObject* GetGeometricNormalTexture();

  /**
   * The hardware depth texture (1.0 = no surface), in the depth format of
   * the framebuffer the renderer draws into (VTK 9.1's window: 32-bit fixed
   * point), so that one blit copies it there.
   */
  vtkTextureObject* GetDepthTexture();

  /**
   * Bytes per pixel of the textures allocated by the last Render(),
   * including the hardware depth.
   */
  int GetBytesPerPixel() const;

  /**
   * Texture format of a channel (a vtkFXRenderUtilities::TextureFormat),
   * as the next Render() allocates it.
   */
  int GetChannelFormat(int channel) const;

  /**
   * Keep the emission channel in 16-bit floats (RGBA16F, 8 bytes) instead
   * of RGBA8, for emission above 1 (default off). vtkFXPipelinePass turns it
   * on while some prop's EMISSIVE_COLOR exceeds 1.
   */
  vtkSetMacro(HDREmission, bool);
  vtkGetMacro(HDREmission, bool);
  vtkBooleanMacro(HDREmission, bool);

  /**
   * Keep the material channels (Albedo, Specular, Ambient) in 16-bit floats
   * (RGBA16F, 8 bytes each) instead of RGBA8, for colours above 1 (default
   * off; vtkProperty does not clamp them and VTK's shaders use them as
   * given). vtkFXPipelinePass turns it on while some visible prop has one.
   */
  vtkSetMacro(HDRMaterial, bool);
  vtkGetMacro(HDRMaterial, bool);
  vtkBooleanMacro(HDRMaterial, bool);

  /**
   * Light a prop emits of its own, linear RGB (may exceed 1), set in the
   * prop's property keys (vtkProp::SetPropertyKeys): written to the
   * emission channel for its lit fragments and added to its lit colour by
   * the composite. Unlit props need none: their colour is their emission.
   * NaN, infinite and negative components count as 0; values above 65504
   * (the largest half float) as 65504.
   */
  static vtkInformationDoubleVectorKey* EMISSIVE_COLOR();

  /**
   * The prop's EMISSIVE_COLOR, or false when it has none (or it is black).
   */
  static bool GetEmissiveColor(vtkProp* prop, double color[3]);

  ///@{
  /**
   * Bump from a point-data scalar array (elevation, density, ...): the
   * shading normal (Normal channel) of the prop's surface tilts as if the surface were
   * displaced along its normal by BUMP_SCALE x the scalar (world units per
   * scalar unit), by the surface gradient of Mikkelsen ("Bump Mapping
   * Unparametrized Surfaces on the GPU", 2010) from screen-space
   * derivatives: no tangents or texture coordinates needed. The scalar is
   * interpolated linearly across each triangle, so the bump is constant
   * per triangle: a mesh shows the detail its vertices sample.
   * SetBump sets both keys on the actor and maps the array onto the
   * vertex attribute the G-buffer reads (its mapper must be a
   * vtkOpenGLPolyDataMapper, not a vtkCompositePolyDataMapper2, whose
   * blocks never receive the attribute in VTK 9.1: a warning, no bump; an
   * array of more than one component uses its first). The lights and every effect shade with the bumped normal;
   * occlusion samples around the unbumped one (GeometricNormal). Props
   * drawn with a geometry shader (wide lines, point sprites) keep their
   * normal.
   * nullptr or an empty name removes the bump.
   */
  static vtkInformationStringKey* BUMP_ARRAY();
  static vtkInformationDoubleKey* BUMP_SCALE();
  static void SetBump(vtkActor* actor, const char* arrayName, double scale);
  ///@}

  /**
   * Whether a prop has a bump (BUMP_ARRAY set, non-zero finite BUMP_SCALE).
   */
  static bool HasBump(vtkProp* prop);

  /**
   * Whether a prop's shading normal differs from its mesh normal: a bump,
   * or a normal texture (vtkProperty::SetNormalTexture) on a mesh with
   * tangents and texture coordinates, which VTK 9.1 then applies in its
   * own lighting (vtkPolyDataTangents computes tangents).
   */
  static bool PerturbsNormal(vtkProp* prop);

  /**
   * Whether the G-buffer can capture a prop: its mappers must call VTK's
   * render-pass shader hooks (the vtkOpenGLPolyDataMapper family, reached
   * through vtkActor). Image slices, 3D text and other props cannot; nor
   * actors VTK would draw otherwise than their stored surface shows: a sky
   * box, an actor whose shader property colours it after the lighting, one
   * with no mapper of its own (vtkPolarAxesActor, vtkCubeAxesActor, which
   * draw through inner actors), one forced opaque with alpha below 1 (VTK
   * blends it over what its opaque step drew before).
   */
  static bool CanCapture(vtkProp* prop);

  /**
   * The pass that renders the props (usually a vtkOpaquePass).
   */
  vtkGetObjectMacro(DelegatePass, vtkRenderPass);
  virtual void SetDelegatePass(vtkRenderPass* delegatePass);

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  /**
   * Whether the last Render() could make the G-buffer. When OpenGL cannot
   * (say, no memory for its channels at a huge size), an error says so once,
   * the opaque props are drawn forward into the renderer's target (VTK's
   * own shading, so the scene still shows), and vtkFXPipelinePass leaves
   * out the composite and the effects that read G-buffer channels.
   */
  bool GetFrameComplete() const { return this->FrameComplete; }

  ///@{
  /**
   * vtkOpenGLRenderPass shader hooks: tag the mapper's fragment shader, then
   * write the channels; set the draw buffers per draw.
   */
  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;
  vtkMTimeType GetShaderStageMTime() override;
  ///@}

protected:
  vtkFXGBufferPass();
  ~vtkFXGBufferPass() override;

  // False when the framebuffer cannot be made (FrameBufferComplete).
  bool UpdateTargets(vtkOpenGLRenderWindow* window, int width, int height);
  // The G-buffer's framebuffer, bound, is complete (virtual: a test
  // simulates a driver that cannot make it).
  virtual bool FrameBufferComplete();
  // The captured props drawn the way VTK draws them, into `s`'s target.
  void RenderForward(const vtkRenderState* s, std::vector<vtkProp*>& props);
  // The props of `s` whose shaders the hooks can extend.
  static std::vector<vtkProp*> CapturedProps(const vtkRenderState* s);
  void ClearTargets();
  // How VTK lights a fragment: not at all, with the Phong model the
  // composite reproduces, or with one it keeps VTK's colour of (PBR).
  enum FragmentLighting
  {
    Unlit,
    Phong,
    Prelit
  };
  // `unlitEmits`: an unlit fragment's colour is its emission (a prop with
  // Lighting off); else (a lit prop's unlit primitives: lines or points
  // without normals) it emits only its emissive colour.
  std::string ChannelWritesGLSL(
    FragmentLighting lighting, bool unlitEmits, const char* linearDepth) const;

  vtkRenderPass* DelegatePass = nullptr;
  bool HDREmission = false;
  bool HDRMaterial = false;
  unsigned int RequiredChannels;
  unsigned int AllocatedChannels = 0;
  bool WarnedIncomplete = false; // the framebuffer could not be made (said once)
  bool FrameComplete = true;     // the last frame's framebuffer was made
  int DepthFormat = -1; // a vtkFXRenderUtilities::TextureFormat
  unsigned int NumberOfTargets = 0;
  vtkSmartPointer<vtkTextureObject> Textures[NumberOfChannels];
  vtkSmartPointer<vtkTextureObject> DepthTexture;
  vtkSmartPointer<vtkOpenGLFramebufferObject> FrameBuffer;
  vtkTimeStamp ShaderStageTime;
  float ProjectionZ[4] = { 0.f, 0.f, 0.f, 1.f };
  // Whether a program writes every channel (SetShaderParameters), per frame.
  std::unordered_map<vtkShaderProgram*, bool> HookedPrograms;

private:
  vtkFXGBufferPass(const vtkFXGBufferPass&) = delete;
  void operator=(const vtkFXGBufferPass&) = delete;
};

#endif
