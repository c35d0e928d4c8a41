#include "vtkFXDirectionalOcclusionPass.h"

#include "vtkFXGBufferPass.h"
#include "vtkFXOcclusionBasis.h"

#include "vtkObjectFactory.h"
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
}

vtkFXDirectionalOcclusionPass::~vtkFXDirectionalOcclusionPass() = default;

vtkTextureObject* vtkFXDirectionalOcclusionPass::GeometricNormalChannel() const
{
  return this->GBuffer ? this->GBuffer->GetChannelTexture(GB::GeometricNormal) : nullptr;
}

std::string vtkFXDirectionalOcclusionPass::GetCompositeCode(int hook)
{
  const bool geometric = this->GeometricNormalChannel() != nullptr;
  switch (hook)
  {
    case Declarations:
      // The occlusion texture's layout is vtkFXSSAOPass's (see there).
      return std::string("uniform sampler2D @occlusion;\nuniform vec2 @scale;\nuniform vec2 @offset;\n") +
        (geometric ? "uniform sampler2D @geometric;\n" : "") + vtkFXOcclusionBasis;
    case Ambient:
    {
      if (this->ShowChannels)
      {
        return "    ambientVisibility *= clamp(texture(@occlusion, texCoord * @scale + @offset).rgb, "
               "0.0, 1.0);";
      }
      // The seed's resolve: the channels weighted by the shading normal n's
      // squared clamped cosines with the basis of the geometric normal g.
      // Without a GeometricNormal channel no prop perturbs its normal: g = n
      // and the weights are 1/3 (the channels' mean).
      std::string code = "    {\n"
                         "      vec3 channels = texture(@occlusion, texCoord * @scale + @offset).rgb;\n"
                         "      vec3 g = n;\n";
      if (geometric)
      {
        code += "      vec2 encoded = texture(@geometric, texCoord).rg;\n"
                "      if (!fxIsUnlit(encoded)) { g = fxDecodeNormal(encoded); }\n";
      }
      code += "      float resolved = dot(fxResolveWeights(g, n), channels);\n"
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
}

void vtkFXDirectionalOcclusionPass::UnbindCompositeResources()
{
  this->Superclass::UnbindCompositeResources();
  if (this->GeometricNormalBound)
  {
    this->GeometricNormalBound->Deactivate();
    this->GeometricNormalBound = nullptr;
  }
}

void vtkFXDirectionalOcclusionPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->UnbindCompositeResources();
  this->Superclass::ReleaseGraphicsResources(w);
}

void vtkFXDirectionalOcclusionPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ShowChannels: " << this->ShowChannels << "\n";
  os << indent << "Samples used: " << this->GetEffectiveNumberOfSamples() << "\n";
}
