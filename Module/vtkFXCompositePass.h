/**
 * @class   vtkFXCompositePass
 * @brief   Deferred lighting of a vtkFXGBufferPass with VTK's own light model.
 *
 * Reads: the G-buffer's hardware depth, albedo and, when allocated, normal,
 * linear depth, specular, ambient and emission channels; the renderer's
 * lights through vtkOpenGLRenderer::UpdateLightingUniforms, so headlights,
 * camera and scene lights, positional lights with cone and attenuation,
 * vtkLightKit and two-sided lighting give the same numbers as VTK's forward
 * shaders (same formulas, same uniforms). With more lights on than
 * MaximumUniformLights, the same light parameters come from a small float
 * texture (4 RGBA32F texels per light) that the shader loops over, so the
 * light count is a uniform: adding a light recompiles nothing. On that
 * path lights are culled per 16 x 16 pixel tile (vtkFXLightTiles): a
 * positional light counts only where its attenuated light can still add
 * LightCutoff to a colour, on the screen and in depth (TileDepthBounds),
 * so each pixel loops over the lights that reach it, not over every light
 * in the scene.
 *
 * Writes: the lit colour of every covered pixel into the current framebuffer
 * (blended like VTK's opaque pass), and the G-buffer depth into its depth
 * buffer, so VTK's translucent, volume and overlay steps that follow are
 * depth-tested as usual. Background pixels are left untouched.
 *
 * Cost: a depth pre-pass (one blit of the G-buffer's depth, or where the
 * framebuffer refuses it a full-screen pass of one texture read per
 * pixel), then a lighting pass whose depth test leaves out the background
 * before the fragment shader runs (see UseDepthPrepass), with one texture read per
 * allocated channel and a loop over the lights per surface pixel (on the
 * light-texture path, over the lights of the pixel's tile, with 3 texel
 * reads per point light (its tile entry, a copy of its row), 4 per spot
 * light, 2 per directional light (which every pixel loops over), the
 * same without culling; building the tiles' lists on the CPU, and with
 * TileDepthBounds a pass of one fetch per pixel that measures each
 * tile's depth range, read back), plus what the contributing effects'
 * code costs. The rows are sorted by kind and each kind has its own loop,
 * so no light pays for another kind's terms.
 *
 * Effects contribute code at the composite's hook points (declarations,
 * per-light visibility, ambient visibility, final colour; see
 * vtkFXEffectPass) and bind what it reads: AddContributor. The ambient
 * visibility they leave (e.g. occlusion) scales the ambient term and, by
 * OcclusionDiffuseStrength, the diffuse light.
 *
 * DebugChannel shows one G-buffer channel instead of the lit image.
 */
#ifndef vtkFXCompositePass_h
#define vtkFXCompositePass_h

#include "vtkFXGBufferPass.h" // for the channel count
#include "vtkFXLightTiles.h" // for the tiles' light entries
#include "vtkFXModule.h"
#include "vtkFXSetGet.h" // for vtkFXSetClampMacro
#include "vtkFXRenderUtilities.h" // for the full-screen quads
#include "vtkRenderPass.h"

#include "vtkSmartPointer.h" // for the contributors

#include <memory>
#include <string>
#include <vector>

class vtkFXEffectPass;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderer;
class vtkShaderProgram;
class vtkTextureObject;

class VTKFX_EXPORT vtkFXCompositePass : public vtkRenderPass
{
public:
  static vtkFXCompositePass* New();
  vtkTypeMacro(vtkFXCompositePass, vtkRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The G-buffer whose channels are lit. It must render before this pass.
   */
  virtual void SetGBuffer(vtkFXGBufferPass* gbuffer);
  vtkGetObjectMacro(GBuffer, vtkFXGBufferPass);

  /**
   * Channel to show instead of the lit image (a vtkFXGBufferPass::Channel),
   * or -1 (default) for the lit image. Normals show as 0.5 + 0.5 n, linear
   * depth as a grey ramp over the camera's clipping range (near black).
   */
  vtkSetClampMacro(DebugChannel, int, -1, vtkFXGBufferPass::NumberOfChannels - 1);
  vtkGetMacro(DebugChannel, int);

  /**
   * Show the ambient visibility the contributing effects computed (grey,
   * 1 = open, e.g. ambient occlusion) instead of the lit image (default off).
   */
  vtkSetMacro(DebugOcclusion, bool);
  vtkGetMacro(DebugOcclusion, bool);
  vtkBooleanMacro(DebugOcclusion, bool);

  ///@{
  /**
   * Material terms the scene has, decided by whoever knows the scene
   * (vtkFXPipelinePass does it per frame). Off means every fragment has zero
   * of that term, so its channel need not exist. Both on by default.
   */
  vtkSetMacro(UseSpecular, bool);
  vtkGetMacro(UseSpecular, bool);
  vtkSetMacro(UseAmbient, bool);
  vtkGetMacro(UseAmbient, bool);
  ///@}

  /**
   * Whether some lit prop emits light of its own
   * (vtkFXGBufferPass::EMISSIVE_COLOR), added to its lit colour from the
   * emission channel (default off: the channel is not read).
   */
  vtkSetMacro(UseEmission, bool);
  vtkGetMacro(UseEmission, bool);

  ///@{
  /**
   * Mark the lit surfaces' alpha so that what is drawn over them later
   * tells how much of their light it lets through (default off; the
   * pipeline turns it on, with its HDR target, while an effect asks,
   * vtkFXEffectPass::GetReadsTransmittance). The composite then blends
   * alpha with TransmittanceMark x the surface's opacity in place of its
   * opacity, so an opaque surface's pixel holds K = TransmittanceMark;
   * VTK's translucent and volume steps blend alpha as
   * a' = f + (1 - a_s) a with f in [0, 1] (f = a_s for "over", its
   * volumes' rays and depth peeling; a_s^2 for the final blend of VTK
   * 9.1's order-independent transparency), so the pixel ends at T K + f,
   * T the fraction of the surface's light that reaches the image, and
   * T = (a - 1) / (K - 1), exactly for "over" and within 1 / (K - 1)
   * for the other. An opaque prop drawn forward over it leaves 1: T = 0.
   * Colours blend as without the mark, and the HDR target's write-back
   * clamps alpha to 1, which is what an opaque surface's pixel holds
   * under "over" blending.
   */
  vtkSetMacro(MarksTransmittance, bool);
  vtkGetMacro(MarksTransmittance, bool);
  static constexpr double TransmittanceMark = 1024.0; // (exact in a half float, as is K - 1)
  ///@}

  ///@{
  /**
   * Write the depth in a pre-pass and light only the pixels that hold a
   * surface (default on): the lighting pass then draws at the far plane
   * against that depth with the test GL_GREATER, which rejects the
   * background before the fragment shader runs. On a software rasteriser
   * (llvmpipe) that saves the lighting of every background pixel, about
   * 5 ms of a 1280x720 frame of the bunny; a GPU pays one cheap pass more.
   * Used when the framebuffer's depth holds only the renderer's clear
   * value at the composite (the renderer erases and does not preserve its
   * depth buffer); otherwise, and when off, one pass lights every pixel
   * and writes the depth.
   */
  vtkSetMacro(UseDepthPrepass, bool);
  vtkGetMacro(UseDepthPrepass, bool);
  vtkBooleanMacro(UseDepthPrepass, bool);
  ///@}

  /**
   * Whether the last Render() used the depth pre-pass (see
   * UseDepthPrepass).
   */
  vtkGetMacro(UsedDepthPrepass, bool);

  ///@{
  /**
   * Write the pre-pass's depth with one blit where the framebuffer allows
   * it (default on): the G-buffer keeps the renderer's depth format, so
   * only a multisampled target refuses (then a full-screen pass writes it,
   * and the blit is not tried again for that target while it stays the
   * target: the last refusing one is remembered). The
   * result is the same either way; off is for comparison.
   */
  vtkSetMacro(UseDepthBlit, bool);
  vtkGetMacro(UseDepthBlit, bool);
  vtkBooleanMacro(UseDepthBlit, bool);
  /** Whether the last Render() wrote the depth with a blit. */
  vtkGetMacro(UsedDepthBlit, bool);
  ///@}

  /**
   * Most lights served by VTK's per-light uniforms (0..64, default 8); with
   * more lights on, they come from a light texture the shader loops over,
   * culled per tile. 0 sends every light of lighting complexity 2 and 3
   * through the light texture.
   */
  vtkSetClampMacro(MaximumUniformLights, int, 0, 64);
  vtkGetMacro(MaximumUniformLights, int);

  /**
   * GLSL that adds the first `lightCount` lights of VTK's light uniforms
   * (vtkOpenGLRenderer::GetLightingUniforms, at lighting `complexity`) into
   * `diffuseLight` and `specularLight` with vtkFXLightingFS.glsl's
   * functions, for a surface of normal `n`, view-space `position`, `view`
   * direction and `specularPower`: the composite's own light loop, for
   * other passes that light G-buffer surfaces.
   */
  static std::string GetUniformLightCalls(int complexity, int lightCount);

  /**
   * On the light-texture path, a positional light is left out of a tile
   * where, by VTK's attenuation, it can add less than LightCutoff to a
   * colour channel (linear units, 0..1, default 1/512: under half a level
   * of an 8-bit image). 0 keeps every light in every tile (no culling).
   * Directional lights reach every tile; so do positional lights VTK does
   * not attenuate (attenuation 1, 0, 0, VTK's default), unless such a
   * light is dimmer than the cutoff everywhere (then it is left out).
   * The bound is per light: a light is left out where its diffuse and its
   * specular term each add under half the cutoff (together under the
   * cutoff), so where N lights are left out at once a pixel can lose up
   * to N x LightCutoff on a shiny surface, half that on a matte one (64
   * lights all just past their range around one point: 0.125, about 32
   * levels of 8 bits at the default). For many lights gathered around the
   * same places, lower the cutoff.
   */
  vtkFXSetClampMacro(LightCutoff, double, 0.0, 1.0);
  vtkGetMacro(LightCutoff, double);

  /**
   * With LightCutoff above 0, also leave a positional light out of a tile
   * whose surfaces all lie nearer or farther than its sphere of influence
   * (default on): each tile's range of linear depth is measured from the
   * G-buffer (one pass of one fetch per pixel into a texel per tile, read
   * back to the CPU, which builds the lists). Exact: no light is left out
   * where it reaches a surface. Off: tiles are culled by the lights'
   * screen rectangles only.
   */
  vtkSetMacro(TileDepthBounds, bool);
  vtkGetMacro(TileDepthBounds, bool);
  vtkBooleanMacro(TileDepthBounds, bool);

  /**
   * Tile list entries up to which each carries a copy of its light's
   * parameters (64 bytes an entry, read straight by the lighting loop;
   * 0..2^20, default 2^20: 64 MiB); longer lists hold the lights' indices
   * (4 bytes an entry, one more texture read per light and pixel).
   */
  vtkFXSetClampMacro(MaximumTileRowEntries, vtkIdType, 0, vtkIdType(1) << 20);
  vtkGetMacro(MaximumTileRowEntries, vtkIdType);

  /**
   * The largest material colour component of the visible props (at least
   * 1, default 1): a light adds its light times that, so the culling range
   * is taken for a light that much brighter. vtkFXPipelinePass sets it
   * from the scene (colours above 1 are allowed, see
   * vtkFXGBufferPass::SetHDRMaterial).
   */
  vtkFXSetClampMacro(MaterialColorScale, double, 1.0, 65504.0);
  vtkGetMacro(MaterialColorScale, double);

  /**
   * Mean number of lights per tile in the last frame on the light-texture
   * path (0 otherwise): what each pixel loops over.
   */
  double GetMeanLightsPerTile() const;

  /**
   * The lights' texture of the last frame on the light-texture path (more
   * lights than VTK's uniforms serve), kept between frames; nullptr on
   * VTK's uniforms.
   */
  vtkTextureObject* GetLightTexture() { return this->LightTexture; }

  ///@{
  /**
   * Effects whose composite code (vtkFXEffectPass::GetCompositeCode) runs
   * in this pass, in order. vtkFXPipelinePass sets them every frame to the
   * effects that ran.
   */
  void RemoveAllContributors();
  void AddContributor(vtkFXEffectPass* effect);
  int GetNumberOfContributors() const;
  ///@}

  /**
   * How much occlusion also darkens the diffuse light (0..1, dimensionless,
   * default 1). Occlusion always scales VTK's ambient term, but VTK's
   * materials have none by default (Ambient = 0), so ambient-only occlusion
   * would be invisible in most VTK scenes: 0 is the physically ambient-only
   * choice, 1 darkens diffuse shading like vtkSSAOPass (which scales the
   * whole colour). Specular highlights are never occluded.
   */
  vtkFXSetClampMacro(OcclusionDiffuseStrength, double, 0.0, 1.0);
  vtkGetMacro(OcclusionDiffuseStrength, double);

  /**
   * Channels this pass reads when the renderer's lighting complexity is
   * `lightingComplexity` (0 = no light on, see vtkOpenGLRenderer), as a mask
   * of vtkFXGBufferPass::ChannelBit().
   */
  unsigned int GetRequiredChannels(int lightingComplexity) const;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  vtkFXCompositePass();
  ~vtkFXCompositePass() override;

  std::string BuildFragmentShader(vtkOpenGLRenderer* ren);
  std::string EffectCode(int hook) const;
  bool UsesLightTexture(vtkOpenGLRenderer* ren) const;
  int LightingComplexity(vtkOpenGLRenderer* ren) const; // 0 without lights or normals
  int UploadLightTexture(vtkOpenGLRenderer* ren); // returns the lights uploaded
  int UploadedLights = 0; // by this frame's UploadLightTexture
  void DeactivateLightTextures();
  void BuildLightTiles(vtkOpenGLRenderer* ren, const std::vector<vtkFXLightTiles::Light>& lights);
  void SetUniforms(vtkShaderProgram* program, vtkOpenGLRenderer* ren);
  void Draw(vtkOpenGLRenderer* ren);
  bool CanUseDepthPrepass(vtkOpenGLRenderer* ren);
  void DrawDepthPrepass(vtkOpenGLRenderer* ren);
  bool BlitDepth(vtkOpenGLRenderer* ren);

  vtkFXGBufferPass* GBuffer = nullptr;
  double OcclusionDiffuseStrength = 1.0;
  int DebugChannel = -1;
  int MaximumUniformLights = 8;
  double LightCutoff = 1.0 / 512.0;
  double MaterialColorScale = 1.0;
  bool DebugOcclusion = false;
  bool UseSpecular = true;
  bool UseAmbient = true;
  bool UseEmission = false;
  bool MarksTransmittance = false;

  // Each misconfiguration is reported once.
  bool WarnedSpecularWithoutDepth = false;
  bool ReportedPositionalWithoutDepth = false;
  bool ReportedTooManyLights = false;
  std::vector<vtkSmartPointer<vtkFXEffectPass>> Contributors;
  vtkSmartPointer<vtkTextureObject> LightTexture;
  std::unique_ptr<vtkFXLightTiles> LightTiles;
  bool LightTilesUsed = false;
  bool TileDepthBounds = true;
  vtkIdType MaximumTileRowEntries = vtkIdType(1) << 20;
  // The light texture's first row of a point light and of a spot light
  // (rows sorted: directional, point, spot).
  int FirstLightOfKind[2] = { 0, 0 };
  bool WarnedLightTiles = false;
  bool WarnedEarlierError = false; // a GL error pending before the depth copy (said once)
  vtkFXRenderUtilities::FullScreenQuad Quad;
  vtkFXRenderUtilities::FullScreenQuad DepthQuad; // the depth pre-pass
  bool UseDepthPrepass = true;
  bool UsedDepthPrepass = false;
  bool UseDepthBlit = true;
  bool UsedDepthBlit = false;
  int RefusingFramebuffer = -1; // the draw framebuffer that last refused the blit; -1: none
  vtkSmartPointer<vtkOpenGLFramebufferObject> DepthReadFrameBuffer; // reads the G-buffer's depth

private:
  vtkFXCompositePass(const vtkFXCompositePass&) = delete;
  void operator=(const vtkFXCompositePass&) = delete;
};

#endif
