#include "vtkFXDirectionalOcclusionPass.h"

#include "vtkFXBilateralBlurPass.h"
#include "vtkFXCompositePass.h"
#include "vtkFXGBufferPass.h"
#include "vtkFXJointUpsample.h"
#include "vtkFXLightingFS.h"
#include "vtkFXOcclusionBasis.h"
#include "vtkFXRenderUtilities.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

vtkStandardNewMacro(vtkFXDirectionalOcclusionPass);

namespace
{
using GB = vtkFXGBufferPass;
}

vtkFXDirectionalOcclusionPass::vtkFXDirectionalOcclusionPass()
{
  this->Channels = 3;
  this->TileSize = 8;
  this->Method = Hemisphere;
  this->NumberOfSamples = 15;
  this->DeclareOutput("bleeding");
  this->DeclareInput("bleeding-denoised", true, true);
}

int vtkFXDirectionalOcclusionPass::GetEffectiveMethod() const
{
  // Bleeding reads each blocked sample's occluder: hemisphere samples.
  return this->Bleeding > 0.0 ? Hemisphere : this->Method;
}

unsigned int vtkFXDirectionalOcclusionPass::GetRequiredChannels()
{
  return this->Superclass::GetRequiredChannels() |
    (this->Bleeding > 0.0 ? GB::ChannelBit(GB::Albedo) : 0u);
}

vtkFXEffectPass::Output vtkFXDirectionalOcclusionPass::GetOutput(const char* name)
{
  if (name && std::string(name) == "bleeding")
  {
    Output output;
    // (only beside this frame's occlusion: a bleeding texture left from a
    // frame whose occlusion target could not be made is stale)
    if (this->Bleeding > 0.0 && this->BleedingTexture &&
      this->Superclass::GetOutput("occlusion").Texture)
    {
      output.Texture = this->BleedingTexture;
      output.Step = this->HalfResolution ? 2 : 1;
      output.Components = 3;
      output.Format = vtkFXRenderUtilities::RGBA16F;
    }
    return output;
  }
  return this->Superclass::GetOutput(name);
}

int vtkFXDirectionalOcclusionPass::BleedingLights(vtkRenderer* ren)
{
  auto* glRenderer = vtkOpenGLRenderer::SafeDownCast(ren);
  const int count = this->Bleeding > 0.0 && glRenderer && glRenderer->GetLightingComplexity() > 0
    ? glRenderer->GetLightingCount()
    : 0;
  const int cap = 8;
  if (count > cap && !this->WarnedLights)
  {
    vtkWarningMacro("Diffuse bleeding lights occluders with the first " << cap << " of the "
                                                                        << count << " lights.");
    this->WarnedLights = true;
  }
  return std::min(count, cap);
}

std::string vtkFXDirectionalOcclusionPass::GetExtensionDefines(vtkRenderer* ren)
{
  return this->BleedingLights(ren) > 0 ? "#define FX_BLEED 1\n" : std::string();
}

std::string vtkFXDirectionalOcclusionPass::GetExtensionCode(vtkRenderer* ren)
{
  const int lights = this->BleedingLights(ren);
  if (lights == 0)
  {
    return std::string();
  }
  auto* glRenderer = vtkOpenGLRenderer::SafeDownCast(ren);
  // The occluder is the surface the G-buffer shows at the blocked sample's
  // texel; it reflects albedo x its direct diffuse light, computed with the
  // composite's own light calls (no highlights, no shadows); a pre-lit
  // (PBR) one, whose albedo the G-buffer does not hold, none.
  return std::string("uniform sampler2D fxAlbedo;\nuniform sampler2D fxShadingNormal;\n") +
    glRenderer->GetLightingUniforms() +
    "\n#define FX_HAS_SPECULAR 0\nfloat fxDiffuseResponse(float df) { return df; }\n" +
    vtkFXLightingFS +
    "\nvec3 fxBleed = vec3(0.0);\n"
    "vec3 fxOccluderLight(ivec2 q, float d)\n{\n"
    "  vec2 code = texelFetch(fxShadingNormal, q, 0).rg;\n"
    "  if (fxIsUnlit(code) || fxIsPrelit(code)) { return vec3(0.0); }\n"
    "  vec3 n = fxDecodeNormal(code);\n"
    "  vec3 rayOrigin, rayDirection;\n"
    "  fxTexelRay(q, rayOrigin, rayDirection);\n"
    "  vec3 position = rayOrigin + d * rayDirection;\n"
    "  vec3 view = normalize(-position);\n"
    "  float specularPower = 1.0;\n"
    "  vec3 diffuseLight = vec3(0.0);\n"
    "  vec3 specularLight = vec3(0.0);\n" +
    vtkFXCompositePass::GetUniformLightCalls(glRenderer->GetLightingComplexity(), lights) +
    "  // (VTK's attenuation can make a light infinite; a half float ends at\n"
    "  // 65504: keep the blur's sums finite)\n"
    "  vec3 light = texelFetch(fxAlbedo, q, 0).rgb * diffuseLight;\n"
    "  light = mix(light, vec3(0.0), bvec3(isnan(light.x), isnan(light.y), isnan(light.z)));\n"
    "  return clamp(light, 0.0, 65504.0 / float(FX_SAMPLES));\n}\n";
}

void vtkFXDirectionalOcclusionPass::AddExtensionTargets(
  vtkRenderer* ren, int width, int height, std::vector<vtkTextureObject*>& targets)
{
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (this->BleedingLights(ren) == 0)
  {
    if (this->BleedingTexture)
    {
      // (the framebuffer still has it attached: start a new one)
      vtkFXRenderUtilities::Release(this->BleedingTexture, window);
      vtkFXRenderUtilities::Release(this->FrameBuffer, window);
    }
    return;
  }
  vtkFXRenderUtilities::EnsureTexture(
    this->BleedingTexture, window, width, height, vtkFXRenderUtilities::RGBA16F);
  this->BleedingTexture->SetMinificationFilter(vtkTextureObject::Linear);
  this->BleedingTexture->SetMagnificationFilter(vtkTextureObject::Linear);
  targets.push_back(this->BleedingTexture);
}

void vtkFXDirectionalOcclusionPass::BindExtensionInputs(vtkShaderProgram* program, vtkRenderer* ren)
{
  if (!program->IsUniformUsed("fxAlbedo"))
  {
    return;
  }
  vtkTextureObject* albedo = this->GBuffer->GetChannelTexture(GB::Albedo);
  vtkTextureObject* shading = this->GBuffer->GetChannelTexture(GB::Normal);
  if (!albedo || !shading)
  {
    vtkErrorMacro("Diffuse bleeding needs the G-buffer's albedo and normal channels.");
    return;
  }
  for (auto* texture : { albedo, shading })
  {
    texture->Activate();
    this->ExtensionBound.push_back(texture);
  }
  program->SetUniformi("fxAlbedo", albedo->GetTextureUnit());
  program->SetUniformi("fxShadingNormal", shading->GetTextureUnit());
  vtkOpenGLRenderer::SafeDownCast(ren)->UpdateLightingUniforms(program);
  // (lights with NaN or infinite numbers bleed no light, as they light nothing)
  vtkFXRenderUtilities::DarkenNonFiniteLights(ren, program);
}

void vtkFXDirectionalOcclusionPass::UnbindExtensionInputs()
{
  for (auto* texture : this->ExtensionBound)
  {
    texture->Deactivate();
  }
  this->ExtensionBound.clear();
}

std::string vtkFXDirectionalOcclusionPass::ChannelsReadCode()
{
  // The blurred channels are plain values (bilinear); this pass's own
  // output, when no blur ran, is packed (vtkFXEffectPass::Output::Packing):
  // read the nearest texel and unpack it. The horizon method's channels
  // are stored as (v + 0.5) / 2 (vtkFXSSAOFS.glsl): decoded here, for
  // every reader.
  // Blurred and at half resolution: upsampled by depth (DepthAwareUpsample)
  // against the tangent plane of the geometric normal g, as the blur judged
  // its taps.
  const bool byDepth = this->UpsamplesByDepth(this->CompositeSource());
  const std::string read = byDepth
    ? "  vec3 stored = fxJointUpsample(@occlusion, true, @occlusion, 3, textureSize(@occlusion, "
      "0), @step, ivec2(texCoord * vec2(@fullSize)), fxPixelDepth, " +
      vtkFXRenderUtilities::GLSLFloat(vtkFXBilateralBlurPass::DefaultDepthSigma) +
      ", g, @fullSize, vec4(1.0)).rgb;\n"
    : this->GetInput("denoised").Texture
    ? "  vec3 stored = texture(@occlusion, texCoord * @scale + @offset).rgb;\n"
    : "  ivec2 size = textureSize(@occlusion, 0);\n"
      "  ivec2 t = clamp(ivec2((texCoord * @scale + @offset) * vec2(size)), ivec2(0), size - 1);\n"
      "  vec4 texel = texelFetch(@occlusion, t, 0);\n"
      "  vec3 stored = vec3(fxUnpack12(texel.r), texel.g);\n";
  return std::string(byDepth ? vtkFXJointUpsample : "") + "vec3 @channels(float fxPixelDepth, vec3 g)\n{\n" + read +
    (this->GetEffectiveMethod() == Horizon ? "  return 2.0 * stored - 0.5;\n}\n"
                                           : "  return stored;\n}\n");
}

vtkFXEffectPass::Output vtkFXDirectionalOcclusionPass::BleedingSource()
{
  // (as GetOutput("bleeding"): only beside this frame's occlusion)
  Output own = this->GetOutput("bleeding");
  if (!own.Texture)
  {
    return own;
  }
  Output denoised = this->GetInput("bleeding-denoised");
  return denoised.Texture ? denoised : own;
}

vtkTextureObject* vtkFXDirectionalOcclusionPass::BleedingToShow()
{
  return this->BleedingSource().Texture;
}

bool vtkFXDirectionalOcclusionPass::BleedingUpsamplesByDepth()
{
  const Output occlusion = this->CompositeSource();
  const Output bleeding = this->BleedingSource();
  return bleeding.Texture && this->UpsamplesByDepth(occlusion) && bleeding.Step == occlusion.Step &&
    bleeding.Texture->GetWidth() == occlusion.Texture->GetWidth() &&
    bleeding.Texture->GetHeight() == occlusion.Texture->GetHeight();
}

vtkFXDirectionalOcclusionPass::~vtkFXDirectionalOcclusionPass() = default;

vtkTextureObject* vtkFXDirectionalOcclusionPass::GeometricNormalChannel() const
{
  return this->GBuffer ? this->GBuffer->GetChannelTexture(GB::GeometricNormal) : nullptr;
}

std::string vtkFXDirectionalOcclusionPass::GetCompositeCode(int hook)
{
  const bool geometric = this->GeometricNormalChannel() != nullptr;
  const bool bleeding = this->BleedingToShow() != nullptr;
  switch (hook)
  {
    case Declarations:
      // The occlusion texture's layout is vtkFXSSAOPass's (see there).
    {
      // @geometricNormal: the geometric normal of a pixel of shading
      // normal n. Without a GeometricNormal channel no prop perturbs its
      // normal: n.
      std::string code =
        std::string("uniform sampler2D @occlusion;\nuniform vec2 @scale;\nuniform vec2 @offset;\n"
                    "uniform int @written;\nuniform ivec2 @fullSize;\nuniform int @step;\n") +
        this->ChannelsReadCode() + (geometric ? "uniform sampler2D @geometric;\n" : "") +
        "vec3 @geometricNormal(vec3 n)\n{\n";
      if (geometric)
      {
        code += "  vec2 encoded = texture(@geometric, texCoord).rg;\n"
                "  return fxIsUnlit(encoded) ? n : fxDecodeNormal(encoded);\n";
      }
      else
      {
        code += "  return n;\n";
      }
      return code + "}\n" +
        (bleeding ? "uniform sampler2D @bleeding;\nuniform float @bleedingStrength;\n"
                    "uniform vec2 @bleedingScale;\nuniform vec2 @bleedingOffset;\n"
                  : "") +
        vtkFXOcclusionBasis;
    }
    case Color:
    {
      if (!bleeding)
      {
        return std::string();
      }
      // One bounce off the occluders: irradiance x this surface's albedo.
      // At reduced resolution read as the occlusion is, by depth against
      // the geometric normal's plane (with the occlusion's depths: the
      // bleeding lies beside it, texel for texel), so that no light bleeds
      // across a silhouette onto what lies in front; where the four texels
      // are background, none.
      const std::string read = this->BleedingUpsamplesByDepth()
        ? "    vec3 bled = fxJointUpsample(@bleeding, false, @occlusion, 3, textureSize(@occlusion, "
          "0), @step, ivec2(texCoord * vec2(@fullSize)), fxPixelDepth, " +
          vtkFXRenderUtilities::GLSLFloat(vtkFXBilateralBlurPass::DefaultDepthSigma) +
          ", @geometricNormal(n), @fullSize, vec4(0.0)).rgb;\n"
        : "    vec3 bled = texture(@bleeding, texCoord * @bleedingScale + @bleedingOffset).rgb;\n";
      return "  if (lit)\n  {\n" + read +
        "    bled = mix(bled, vec3(0.0), bvec3(isnan(bled.x), isnan(bled.y), isnan(bled.z)));\n"
        "    color += @bleedingStrength * albedo.rgb * clamp(bled, 0.0, 65504.0);\n  }";
    }
    case Ambient:
    {
      const bool horizon = this->GetEffectiveMethod() == Horizon;
      std::string code = "    if (@written != 0)\n"
                         "    {\n"
                         "      vec3 g = @geometricNormal(n);\n";
      code += "      vec3 channels = @channels(fxPixelDepth, g);\n";
      if (this->ShowChannels)
      {
        return code + "      ambientVisibility *= clamp(channels, 0.0, 1.0);\n"
                      "    }";
      }
      // The seed's resolve: the channels weighted by the shading normal n's
      // squared clamped cosines with the basis of g (without shading
      // normals the weights are 1/3: the channels' mean).
      code += std::string("      float resolved = dot(") +
        (horizon ? "fxResolveWeightsLinear" : "fxResolveWeights") +
        "(g, n), channels);\n"
              "      ambientVisibility *= clamp(isnan(resolved) ? 1.0 : resolved, 0.0, 1.0);\n"
              "    }";
      return code;
    }
    default:
      return std::string();
  }
}

void vtkFXDirectionalOcclusionPass::BindCompositeResources(
  vtkShaderProgram* program, const std::string& prefix)
{
  this->Superclass::BindCompositeResources(program, prefix);
  if (vtkTextureObject* geometric = this->GeometricNormalChannel())
  {
    geometric->Activate();
    this->GeometricNormalBound = geometric;
    program->SetUniformi((prefix + "geometric").c_str(), geometric->GetTextureUnit());
  }
  const Output bleeding = this->BleedingSource();
  if (bleeding.Texture)
  {
    bleeding.Texture->Activate();
    this->BleedingBound = bleeding.Texture;
    program->SetUniformi((prefix + "bleeding").c_str(), bleeding.Texture->GetTextureUnit());
    program->SetUniformf((prefix + "bleedingStrength").c_str(), static_cast<float>(this->Bleeding));
    this->SetReadUniforms(program, prefix + "bleedingScale", prefix + "bleedingOffset", bleeding);
  }
}

void vtkFXDirectionalOcclusionPass::UnbindCompositeResources()
{
  this->Superclass::UnbindCompositeResources();
  if (this->GeometricNormalBound)
  {
    this->GeometricNormalBound->Deactivate();
    this->GeometricNormalBound = nullptr;
  }
  if (this->BleedingBound)
  {
    this->BleedingBound->Deactivate();
    this->BleedingBound = nullptr;
  }
}

void vtkFXDirectionalOcclusionPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->UnbindCompositeResources();
  this->UnbindExtensionInputs();
  vtkFXRenderUtilities::Release(this->BleedingTexture, w);
  this->Superclass::ReleaseGraphicsResources(w);
}

void vtkFXDirectionalOcclusionPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ShowChannels: " << this->ShowChannels << "\n";
  os << indent << "Bleeding: " << this->Bleeding << "\n";
  os << indent << "Samples used: " << this->GetEffectiveNumberOfSamples() << "\n";
}
