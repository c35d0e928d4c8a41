#include "vtkFXCompositePass.h"

#include "vtkFXCompositeFS.h"
#include "vtkFXEffectPass.h"
#include "vtkFXLightingFS.h"
#include "vtkFXGBufferPass.h"
#include "vtkFXNormalCoding.h"
#include "vtkFXRenderUtilities.h"

#include "vtkCamera.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkRenderState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <sstream>

vtkStandardNewMacro(vtkFXCompositePass);

namespace
{
using GB = vtkFXGBufferPass;

// Calls of vtkFXLightingFS.glsl's functions, one per light that is on, with
// VTK's per-light uniform names (vtkOpenGLRenderer::GetLightingUniforms).
std::string LightCallsGLSL(int complexity, int lightCount)
{
  std::ostringstream s;
  for (int i = 0; i < lightCount && complexity > 0; ++i)
  {
    switch (complexity)
    {
      case 1:
        s << "fxHeadlight(n, lightColor0, specularPower, diffuseLight, specularLight);\n";
        return s.str(); // a headlight is the only light by definition
      case 2:
        s << "    fxDirectionalLight(n, view, lightDirectionVC" << i << ", lightColor" << i
          << ", specularPower, diffuseLight, specularLight);\n";
        break;
      default:
        s << "    fxPositionalLight(n, position, view, lightPositional" << i
          << ", lightDirectionVC" << i << ", lightPositionVC" << i << ", lightAttenuation" << i
          << ", lightConeAngle" << i << ", lightExponent" << i << ", lightColor" << i
          << ", specularPower, diffuseLight, specularLight);\n";
        break;
    }
  }
  return s.str();
}

// Binds `texture` to a free unit and points `sampler` at it.
void BindSampler(vtkShaderProgram* program, const char* sampler, vtkTextureObject* texture)
{
  if (texture && program->IsUniformUsed(sampler))
  {
    texture->Activate();
    program->SetUniformi(sampler, texture->GetTextureUnit());
  }
}
}

vtkFXCompositePass::vtkFXCompositePass() = default;

vtkFXCompositePass::~vtkFXCompositePass()
{
  this->SetGBuffer(nullptr);
  this->SetOcclusionEffect(nullptr);
}

vtkCxxSetObjectMacro(vtkFXCompositePass, GBuffer, vtkFXGBufferPass);
vtkCxxSetObjectMacro(vtkFXCompositePass, OcclusionEffect, vtkFXEffectPass);

unsigned int vtkFXCompositePass::GetRequiredChannels(int lightingComplexity) const
{
  unsigned int mask = GB::ChannelBit(GB::Albedo);
  if (lightingComplexity > 0)
  {
    mask |= GB::ChannelBit(GB::Normal);
    if (this->UseSpecular)
    {
      mask |= GB::ChannelBit(GB::Specular);
    }
    if (this->UseAmbient)
    {
      mask |= GB::ChannelBit(GB::Ambient);
    }
    // Positions enter VTK's model through the view vector of specular
    // highlights (complexity >= 2) and the light vector of positional lights.
    if ((lightingComplexity >= 2 && this->UseSpecular) || lightingComplexity == 3)
    {
      mask |= GB::ChannelBit(GB::LinearDepth);
    }
  }
  if (this->DebugChannel >= 0)
  {
    mask |= GB::ChannelBit(this->DebugChannel);
  }
  return mask;
}

std::string vtkFXCompositePass::BuildFragmentShader(vtkOpenGLRenderer* ren)
{
  vtkFXGBufferPass* gb = this->GBuffer;
  const int lightCount = ren->GetLightingCount();
  const int complexity =
    (lightCount == 0 || !gb->GetChannelTexture(GB::Normal)) ? 0 : ren->GetLightingComplexity();
  const bool hasDepth = gb->GetChannelTexture(GB::LinearDepth) != nullptr;
  bool hasSpecular = gb->GetChannelTexture(GB::Specular) != nullptr && complexity > 0;
  if (complexity >= 2 && hasSpecular && !hasDepth)
  {
    if (!this->WarnedMissingDepth)
    {
      vtkWarningMacro("Specular highlights need the G-buffer's linear depth "
                      "(see GetRequiredChannels); they are left out.");
      this->WarnedMissingDepth = true;
    }
    hasSpecular = false;
  }
  if (complexity == 3 && !hasDepth)
  {
    return std::string(); // Render() reports it
  }
  const bool needsPosition = complexity == 3 || (complexity == 2 && hasSpecular);

  std::ostringstream defines;
  defines << "//VTK::System::Dec\n"
          << "#define FX_LIGHTING " << complexity << "\n"
          << "#define FX_HAS_SPECULAR " << (hasSpecular ? 1 : 0) << "\n"
          << "#define FX_HAS_AMBIENT " << (gb->GetChannelTexture(GB::Ambient) ? 1 : 0) << "\n"
          << "#define FX_NEEDS_POSITION " << (needsPosition ? 1 : 0) << "\n"
          << "#define FX_HAS_OCCLUSION " << (this->OcclusionTexture() && complexity > 0 ? 1 : 0)
          << "\n"
          << "#define FX_CHANNEL_NORMAL " << GB::Normal << "\n"
          << "#define FX_CHANNEL_DEPTH " << GB::LinearDepth << "\n"
          << "#define FX_DEBUG_OCCLUSION " << (this->DebugOcclusion ? 1 : 0) << "\n"
          << "#define FX_DEBUG_CHANNEL "
          << (gb->GetChannelTexture(this->DebugChannel) ? this->DebugChannel : -1) << "\n";

  std::string fs = vtkFXCompositeFS;
  vtkShaderProgram::Substitute(fs, "//VTK::System::Dec", defines.str(), false);
  vtkShaderProgram::Substitute(fs, "//VTK::FXNormalCoding::Dec", vtkFXNormalCoding, false);
  vtkShaderProgram::Substitute(fs, "//VTK::FXLighting::Dec", vtkFXLightingFS, false);
  vtkShaderProgram::Substitute(
    fs, "//VTK::Light::Dec", complexity > 0 ? ren->GetLightingUniforms() : "", false);
  vtkShaderProgram::Substitute(
    fs, "//VTK::FXLight::Impl", LightCallsGLSL(complexity, lightCount), false);
  return fs;
}

void vtkFXCompositePass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  vtkOpenGLRenderer* ren = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  if (!ren || !this->GBuffer || !this->GBuffer->GetDepthTexture() ||
    !this->GBuffer->GetChannelTexture(GB::Albedo))
  {
    vtkErrorMacro("vtkFXCompositePass needs a rendered G-buffer with an albedo channel.");
    return;
  }
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  vtkOpenGLState* state = window->GetState();

  const std::string fragmentShader = this->BuildFragmentShader(ren);
  if (fragmentShader.empty())
  {
    if (!this->WarnedMissingDepth)
    {
      vtkErrorMacro("Positional lights need the G-buffer's linear depth channel "
                    "(see GetRequiredChannels); the opaque props are not drawn.");
      this->WarnedMissingDepth = true;
    }
    return;
  }
  vtkShaderProgram* program =
    vtkFXRenderUtilities::ReadyQuad(this->Quad, this->QuadSource, window, fragmentShader);
  if (!program)
  {
    return;
  }

  vtkFXGBufferPass* gb = this->GBuffer;
  BindSampler(program, "fxHardwareDepth", gb->GetDepthTexture());
  BindSampler(program, "fxAlbedo", gb->GetChannelTexture(GB::Albedo));
  BindSampler(program, "fxNormal", gb->GetChannelTexture(GB::Normal));
  BindSampler(program, "fxSpecular", gb->GetChannelTexture(GB::Specular));
  BindSampler(program, "fxAmbient", gb->GetChannelTexture(GB::Ambient));
  BindSampler(program, "fxLinearDepth", gb->GetChannelTexture(GB::LinearDepth));
  BindSampler(program, "fxDebugTexture", gb->GetChannelTexture(this->DebugChannel));
  BindSampler(program, "fxOcclusion", this->OcclusionTexture());
  if (vtkTextureObject* occlusion = this->OcclusionTexture())
  {
    // Pixel p (texture coordinate (p + 0.5) / W) reads occlusion texel
    // p / step, i.e. coordinate (p / step + 0.5) / lowSize.
    vtkTextureObject* reference = gb->GetChannelTexture(GB::Albedo);
    float scale[2], offset[2];
    const int full[2] = { static_cast<int>(reference->GetWidth()),
      static_cast<int>(reference->GetHeight()) };
    const int low[2] = { static_cast<int>(occlusion->GetWidth()),
      static_cast<int>(occlusion->GetHeight()) };
    for (int i = 0; i < 2; ++i)
    {
      const double step = low[i] < full[i] ? 2.0 : 1.0;
      scale[i] = static_cast<float>(full[i] / (step * low[i]));
      offset[i] = static_cast<float>((0.5 - 0.5 / step) / low[i]);
    }
    if (program->IsUniformUsed("fxOcclusionScale"))
    {
      program->SetUniform2f("fxOcclusionScale", scale);
      program->SetUniform2f("fxOcclusionOffset", offset);
    }
  }
  if (program->IsUniformUsed("fxOcclusionDiffuseStrength"))
  {
    program->SetUniformf(
      "fxOcclusionDiffuseStrength", static_cast<float>(this->OcclusionDiffuseStrength));
  }
  vtkFXRenderUtilities::SetFrustumRayUniforms(program, ren);
  if (program->IsUniformUsed("fxDepthRange"))
  {
    double range[2];
    ren->GetActiveCamera()->GetClippingRange(range);
    const float r[2] = { static_cast<float>(range[0]), static_cast<float>(range[1]) };
    program->SetUniform2f("fxDepthRange", r);
  }
  // VTK's own light uniforms, exactly as its mappers receive them.
  ren->UpdateLightingUniforms(program);

  {
    vtkOpenGLState::ScopedglEnableDisable depthTestSaver(state, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(state);
    vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
    vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
    vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(state);
    // Write the G-buffer depth for every covered pixel, whatever was there.
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglDepthFunc(GL_ALWAYS);
    state->vtkglDepthMask(GL_TRUE);
    // Blend like VTK's opaque pass, so that opacity < 1 forced opaque
    // (vtkActor::ForceOpaque) shows the background as it does forward.
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    this->Quad->Render();
  }

  for (int c = 0; c < GB::NumberOfChannels; ++c)
  {
    if (vtkTextureObject* t = gb->GetChannelTexture(c))
    {
      t->Deactivate();
    }
  }
  gb->GetDepthTexture()->Deactivate();
  if (vtkTextureObject* occlusion = this->OcclusionTexture())
  {
    occlusion->Deactivate();
  }
}

vtkTextureObject* vtkFXCompositePass::OcclusionTexture() const
{
  return this->OcclusionEffect ? this->OcclusionEffect->GetOutputTexture() : nullptr;
}

void vtkFXCompositePass::ReleaseGraphicsResources(vtkWindow* w)
{
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(w);
    this->Quad.reset();
  }
  this->QuadSource.clear();
}

void vtkFXCompositePass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "GBuffer: " << this->GBuffer << "\n";
  os << indent << "DebugChannel: " << this->DebugChannel << "\n";
  os << indent << "DebugOcclusion: " << this->DebugOcclusion << "\n";
  os << indent << "OcclusionDiffuseStrength: " << this->OcclusionDiffuseStrength << "\n";
  os << indent << "UseSpecular: " << this->UseSpecular << "\n";
  os << indent << "UseAmbient: " << this->UseAmbient << "\n";
}
