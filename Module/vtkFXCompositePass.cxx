#include "vtkFXCompositePass.h"

#include "vtkFXCompositeFS.h"
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

// VTK 9.1's Phong lighting (vtkOpenGLPolyDataMapper::ReplaceShaderLight,
// non-PBR branch), same formulas and names, with the forward shader's output
// "gl_FragData[0] = vec4(ambientColor + diffuse + specular, opacity)" turned
// into "color = ambientColor + diffuse + specular".
// Without a specular channel every highlight term is zero: the highlight
// code is left out, and with it the need for positions at complexity 2.
std::string LightingGLSL(int complexity, int lightCount, bool specular)
{
  std::ostringstream s;
  switch (complexity)
  {
    case 1: // headlight: light and view along +z
      s << "float df = max(0.0,normalVCVSOutput.z);\n"
           "    vec3 diffuse = df * diffuseColor * lightColor0;\n"
           "    vec3 specular = vec3(0.0);\n";
      if (specular)
      {
        s << "    float sf = pow(df, specularPower);\n"
             "    specular = sf * specularColor * lightColor0;\n";
      }
      s << "    color = ambientColor + diffuse + specular;\n";
      break;
    case 2: // directional lights (light kit)
      s << "vec3 diffuse = vec3(0,0,0);\n"
           "    vec3 specular = vec3(0,0,0);\n"
           "    float df;\n"
           "    float sf;\n";
      for (int i = 0; i < lightCount; ++i)
      {
        s << "    df = max(0.0, dot(normalVCVSOutput, -lightDirectionVC" << i << "));\n"
          << "    diffuse += (df * lightColor" << i << ");\n";
        if (specular)
        {
          s << "    sf = sign(df)*pow(max(0.0, dot( reflect(lightDirectionVC" << i
            << ", normalVCVSOutput), normalize(-vertexVC.xyz))), specularPower);\n"
            << "    specular += (sf * lightColor" << i << ");\n";
        }
      }
      s << "    diffuse = diffuse * diffuseColor;\n"
           "    specular = specular * specularColor;\n"
           "    color = ambientColor + diffuse + specular;\n";
      break;
    case 3: // positional lights with attenuation and cones
      s << "vec3 diffuse = vec3(0,0,0);\n"
           "    vec3 specular = vec3(0,0,0);\n"
           "    vec3 vertLightDirectionVC;\n"
           "    float attenuation;\n"
           "    float df;\n"
           "    float sf;\n";
      for (int i = 0; i < lightCount; ++i)
      {
        s << "    attenuation = 1.0;\n"
          << "    if (lightPositional" << i << " == 0) {\n"
          << "      vertLightDirectionVC = lightDirectionVC" << i << "; }\n"
          << "    else {\n"
          << "      vertLightDirectionVC = vertexVC.xyz - lightPositionVC" << i << ";\n"
          << "      float distanceVC = length(vertLightDirectionVC);\n"
          << "      vertLightDirectionVC = normalize(vertLightDirectionVC);\n"
          << "      attenuation = 1.0 /\n"
          << "        (lightAttenuation" << i << ".x\n"
          << "         + lightAttenuation" << i << ".y * distanceVC\n"
          << "         + lightAttenuation" << i << ".z * distanceVC * distanceVC);\n"
          << "      if (lightConeAngle" << i << " < 90.0) {\n"
          << "        float coneDot = dot(vertLightDirectionVC, lightDirectionVC" << i << ");\n"
          << "        if (coneDot >= cos(radians(lightConeAngle" << i << "))) {\n"
          << "          attenuation = attenuation * pow(coneDot, lightExponent" << i << "); }\n"
          << "        else {\n"
          << "          attenuation = 0.0; }\n"
          << "        }\n"
          << "      }\n"
          << "    df = max(0.0,attenuation*dot(normalVCVSOutput, -vertLightDirectionVC));\n"
          << "    diffuse += (df * lightColor" << i << ");\n";
        if (specular)
        {
          s << "    sf = sign(df)*attenuation*pow( max(0.0, dot( reflect(vertLightDirectionVC, "
               "normalVCVSOutput), normalize(-vertexVC.xyz))), specularPower);\n"
            << "    specular += (sf * lightColor" << i << ");\n";
        }
      }
      s << "    diffuse = diffuse * diffuseColor;\n"
           "    specular = specular * specularColor;\n"
           "    color = ambientColor + diffuse + specular;\n";
      break;
    default: // no light on: VTK shows ambient + diffuse, stored as unlit colour
      break;
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
}

vtkCxxSetObjectMacro(vtkFXCompositePass, GBuffer, vtkFXGBufferPass);

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
  if (this->UseEmission)
  {
    mask |= GB::ChannelBit(GB::Emission);
  }
  if (this->DebugChannel >= 0)
  {
    mask |= GB::ChannelBit(this->DebugChannel);
  }
  return mask;
}

std::string vtkFXCompositePass::BuildFragmentShader(vtkOpenGLRenderer* ren) const
{
  vtkFXGBufferPass* gb = this->GBuffer;
  int complexity = ren->GetLightingComplexity();
  const int lightCount = ren->GetLightingCount();
  if (lightCount == 0 || !gb->GetChannelTexture(GB::Normal))
  {
    complexity = 0;
  }
  const bool hasDepth = gb->GetChannelTexture(GB::LinearDepth) != nullptr;
  const bool hasSpecular = gb->GetChannelTexture(GB::Specular) != nullptr;
  // Complexity >= 2 reads positions only for highlights and positional lights.
  const bool needsPosition = hasDepth && (complexity == 3 || (complexity == 2 && hasSpecular));
  if (complexity == 3 && !hasDepth)
  {
    vtkWarningMacro("Positional lights need the G-buffer's linear depth; lighting falls back "
                    "to the headlight model.");
    complexity = 1;
  }

  std::ostringstream defines;
  defines << "//VTK::System::Dec\n"
          << "#define FX_LIGHTING " << complexity << "\n"
          << "#define FX_HAS_SPECULAR " << (hasSpecular ? 1 : 0) << "\n"
          << "#define FX_HAS_AMBIENT " << (gb->GetChannelTexture(GB::Ambient) ? 1 : 0) << "\n"
          << "#define FX_HAS_EMISSION " << (gb->GetChannelTexture(GB::Emission) ? 1 : 0) << "\n"
          << "#define FX_NEEDS_POSITION " << (needsPosition ? 1 : 0) << "\n"
          << "#define FX_DEBUG_CHANNEL "
          << (gb->GetChannelTexture(this->DebugChannel) ? this->DebugChannel : -1) << "\n";

  std::string fs = vtkFXCompositeFS;
  vtkShaderProgram::Substitute(fs, "//VTK::System::Dec", defines.str(), false);
  vtkShaderProgram::Substitute(fs, "//VTK::FXNormalCoding::Dec", vtkFXNormalCoding, false);
  vtkShaderProgram::Substitute(
    fs, "//VTK::Light::Dec", complexity > 0 ? ren->GetLightingUniforms() : "", false);
  vtkShaderProgram::Substitute(
    fs, "//VTK::FXLight::Impl", LightingGLSL(complexity, lightCount, hasSpecular), false);
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

  vtkShaderProgram* program = vtkFXRenderUtilities::ReadyQuad(
    this->Quad, this->QuadSource, window, this->BuildFragmentShader(ren));
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
  BindSampler(program, "fxEmission", gb->GetChannelTexture(GB::Emission));
  BindSampler(program, "fxLinearDepth", gb->GetChannelTexture(GB::LinearDepth));
  BindSampler(program, "fxDebugTexture", gb->GetChannelTexture(this->DebugChannel));
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
  os << indent << "UseSpecular: " << this->UseSpecular << "\n";
  os << indent << "UseAmbient: " << this->UseAmbient << "\n";
  os << indent << "UseEmission: " << this->UseEmission << "\n";
}
