/**
 * @class   vtkFXDirectionalOcclusionPass
 * @brief   Screen-space occlusion per third of the hemisphere, resolved with the shading normal.
 *
 * Vizerie's "normal mapped screen space diffuse occlusion" (2009, seed 000):
 * instead of one occlusion value per pixel it estimates three, one for
 * each third of the hemisphere around the geometric normal (the three
 * directions of Half-Life 2's radiosity normal-mapping basis,
 * vtkFXOcclusionBasis.glsl), blurs each, and in the composite weights them
 * by the shading normal's squared clamped cosines with the basis. A bump
 * (vtkFXGBufferPass::SetBump) then shows in the ambient term: a facet
 * turned towards an occluder reads darker than one turned away, detail a
 * single occlusion value per pixel cannot hold.
 *
 * Reads the G-buffer's linear depth, its geometric normals (the basis:
 * vtkFXGBufferPass::GetGeometricNormalTexture; the pipeline allocates the
 * GeometricNormal channel while a visible prop has a bump or a normal
 * texture) and, in the composite, the shading normal (`n`). Writes the
 * output "occlusion" (RGBA32F, the three channels' visibility, 1 = open,
 * packed with the normal and depth that guide the blur:
 * vtkFXEffectPass::Output::Packing) at full or half resolution. In the
 * composite it scales the ambient visibility by the resolved value, read
 * from its optional input "denoised" (vtkFXBilateralBlurPass with three
 * components, which reads the packing in one fetch per tap) when that ran,
 * upsampled by depth as vtkFXSSAOPass::DepthAwareUpsample says (at a
 * crease, the one full-resolution pixel between two half-resolution texels
 * still blends channels of two bases).
 *
 * Method Hemisphere (the default, the seed's estimator): vtkFXSSAOPass's
 * hemisphere sampling (the seed's
 * cosine-weighted rays; lengths u^3 R under the CubeRoot falloff, R under
 * Binary) with each sample's occlusion split over the channels by its
 * direction's weights against the basis, which sum to 1 for every
 * direction. Each channel is scaled by 3 / samples, so the mean of the
 * three channels is vtkFXSSAOPass's one-channel estimate from the same
 * samples (exactly, unless a channel's occlusion passes 1 and is clamped
 * at 0 on its own, where the mean reads brighter than the one channel);
 * and with no bump the shading normal is the geometric one,
 * whose weights are 1/3 each: the result is that mean, plain ambient
 * occlusion. NumberOfSamples is rounded up to a multiple of 3 (at most 63),
 * so that the stratified azimuths split evenly over the three basis
 * directions. The per-pixel rotation repeats over the seed's 8x8 pattern
 * (vtkFXSSAOPass: 4x4; the two measured alike).
 *
 * Method Horizon: vtkFXSSAOPass's horizon search (GTAO, the same slices
 * and steps), and per slice, for each basis vector b_k, the integral of
 * the unclamped cosine b_k . w over the visible arc and over the open one
 * down to the geometric tangent line (XeGTAO's arc formula, linear in the
 * vector); a channel is its visible part of its open integral, stored as
 * (v + 0.5) / 2 (the unclamped lobes take -0.37..1.37). The cosine around a
 * shading normal s is sum_k (b_k . s)(b_k . w) for the orthonormal basis,
 * so the resolve weights the channels by b_k . s normalised to sum 1
 * (linear, not the seed's squares; negative weights dropped, which keeps
 * it exact within 35 degrees of n and a mix of the channels beyond); with
 * s = n they are 1/3 and the result
 * is plain horizon-based AO (TestDirectionalOcclusion: within 0.012 per
 * band). Measured with vtkfx-bench do (640x480, 16 samples, against
 * hemisphere DO at its default 15): 0.9 to 3.3 dB closer to the reference
 * on the bunny, scene:terrain and scene:normalmap, 2.3 and 1.9 dB further
 * on scene:bumps and scene:corner (as plain horizon AO against plain
 * hemisphere AO there); 32 samples add 1 to 3 dB. The detail score is
 * higher on the bunny, terrain and normalmap, lower on the corner. Diffuse bleeding needs the
 * hemisphere's samples: with Bleeding above 0 the pass uses Hemisphere.
 * NumberOfSamples sets the steps as for vtkFXSSAOPass.
 *
 * Cost: vtkFXSSAOPass's hemisphere pass (the same fetches; three weights
 * per occluded sample), a blur of three values (two passes of one
 * RGBA32F fetch per tap), four texel reads in the composite (its
 * depth-aware upsample; one with DepthAwareUpsample off), and while a
 * visible prop perturbs its normal the geometric-normal channel (4 bytes
 * per pixel, written by the G-buffer, read by the composite).
 */
#ifndef vtkFXDirectionalOcclusionPass_h
#define vtkFXDirectionalOcclusionPass_h

#include "vtkFXModule.h"
#include "vtkFXSetGet.h" // for vtkFXSetClampMacro
#include "vtkFXSSAOPass.h"

class VTKFX_EXPORT vtkFXDirectionalOcclusionPass : public vtkFXSSAOPass
{
public:
  static vtkFXDirectionalOcclusionPass* New();
  vtkTypeMacro(vtkFXDirectionalOcclusionPass, vtkFXSSAOPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Diffuse bleeding, the seed's extra (0..10, default 0: off, its texture
   * freed): light the occluders within R reflect onto the surface, one
   * bounce. Each blocked sample adds its occluder's albedo times the
   * occluder's unshadowed direct diffuse light (VTK's light model, the
   * first 8 lights), and the mean over the samples is the irradiance from
   * that bounce in the units of VTK's diffuse light, written to the output
   * "bleeding" (RGBA16F; blurred like the channels when the pipeline runs
   * it, input "bleeding-denoised"). The composite adds Bleeding x the
   * surface's albedo x that to lit pixels: 1 is the physical one bounce
   * within R under the Binary falloff. Under CubeRoot the samples lie at
   * u^3 R, so a bounce from distance t counts with the falloff's weight
   * 1 - (t/R)^(1/3), as occlusion does (nearer occluders reflect more);
   * vtkfx-bench do's reference is the unweighted one bounce.
   * Costs two more fetches per blocked sample and a second blur.
   */
  vtkFXSetClampMacro(Bleeding, double, 0.0, 10.0);
  vtkGetMacro(Bleeding, double);

  /**
   * For inspection: the composite's ambient visibility becomes the three
   * channels as red, green and blue instead of their resolve (with
   * vtkFXCompositePass::DebugOcclusion, an image of the channels). Default
   * off.
   */
  vtkSetMacro(ShowChannels, bool);
  vtkGetMacro(ShowChannels, bool);
  vtkBooleanMacro(ShowChannels, bool);

  unsigned int GetRequiredChannels() override;
  Output GetOutput(const char* name) override;
  std::string GetCompositeCode(int hook) override;
  void BindCompositeResources(vtkShaderProgram* program, const std::string& prefix) override;
  void UnbindCompositeResources() override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  int GetEffectiveMethod() const override;
  vtkFXDirectionalOcclusionPass();
  ~vtkFXDirectionalOcclusionPass() override;

  vtkTextureObject* GeometricNormalChannel() const;
  vtkTextureObject* BleedingToShow();
  // What the composite reads of the bleeding (the denoised input, else
  // this pass's output).
  Output BleedingSource();
  // The composite upsamples the bleeding by depth, with the occlusion's
  // (it lies beside it, at its size, with no depth of its own).
  bool BleedingUpsamplesByDepth();
  std::string ChannelsReadCode();

  // vtkFXSSAOPass's hooks: the bleeding's shader code, target and inputs.
  std::string GetExtensionDefines(vtkRenderer* ren) override;
  std::string GetExtensionCode(vtkRenderer* ren) override;
  void AddExtensionTargets(
    vtkRenderer* ren, int width, int height, std::vector<vtkTextureObject*>& targets) override;
  void BindExtensionInputs(vtkShaderProgram* program, vtkRenderer* ren) override;
  void UnbindExtensionInputs() override;
  // The lights the bleeding lights occluders with (0: no bleeding).
  int BleedingLights(vtkRenderer* ren);

  bool ShowChannels = false;
  double Bleeding = 0.0;
  bool WarnedLights = false;
  vtkTextureObject* GeometricNormalBound = nullptr;
  vtkTextureObject* BleedingBound = nullptr;
  vtkSmartPointer<vtkTextureObject> BleedingTexture;
  std::vector<vtkTextureObject*> ExtensionBound;

private:
  vtkFXDirectionalOcclusionPass(const vtkFXDirectionalOcclusionPass&) = delete;
  void operator=(const vtkFXDirectionalOcclusionPass&) = delete;
};

#endif
