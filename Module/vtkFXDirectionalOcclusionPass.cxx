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

bool vtkFXDirectionalOcclusionPass::HasWork(const vtkFXSceneInfo& scene)
{
  this->SetReadShadingNormals(scene.AnyBump);
  return this->Superclass::HasWork(scene);
}

unsigned int vtkFXDirectionalOcclusionPass::GetRequiredChannels()
{
  return this->Superclass::GetRequiredChannels() |
    (this->ReadShadingNormals ? GB::ChannelBit(GB::ShadingNormal) : 0u);
}

vtkTextureObject* vtkFXDirectionalOcclusionPass::ShadingNormalTexture() const
{
  return this->ReadShadingNormals && this->GBuffer
    ? this->GBuffer->GetChannelTexture(GB::ShadingNormal)
    : nullptr;
}

std::string vtkFXDirectionalOcclusionPass::GetCompositeCode(int hook)
{
  const bool shading = this->ShadingNormalTexture() != nullptr;
  switch (hook)
  {
    case Declarations:
      // The occlusion texture's layout is vtkFXSSAOPass's (see there).
      return std::string("uniform sampler2D @occlusion;\nuniform vec2 @scale;\nuniform vec2 @offset;\n") +
        (shading ? "uniform sampler2D @shading;\n" : "") + vtkFXOcclusionBasis;
    case Ambient:
    {
      if (this->ShowChannels)
      {
        return "    ambientVisibility *= clamp(texture(@occlusion, texCoord * @scale + @offset).rgb, "
               "0.0, 1.0);";
      }
      // The seed's resolve: the channels weighted by the shading normal's
      // squared clamped cosines with the basis of the geometric normal n.
      // Pixels whose shading normal is missing (unlit) use n: the mean.
      std::string code = "    {\n"
                         "      vec3 channels = texture(@occlusion, texCoord * @scale + @offset).rgb;\n"
                         "      vec3 s = n;\n";
      if (shading)
      {
        code += "      vec2 encoded = texture(@shading, texCoord).rg;\n"
                "      if (!fxIsUnlit(encoded)) { s = fxDecodeNormal(encoded); }\n";
      }
      code += "      float resolved = dot(fxResolveWeights(n, s), channels);\n"
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
  if (vtkTextureObject* shading = this->ShadingNormalTexture())
  {
    shading->Activate();
    this->ShadingNormalBound = shading;
    program->SetUniformi((prefix + "shading").c_str(), shading->GetTextureUnit());
  }
}

void vtkFXDirectionalOcclusionPass::UnbindCompositeResources()
{
  this->Superclass::UnbindCompositeResources();
  if (this->ShadingNormalBound)
  {
    this->ShadingNormalBound->Deactivate();
    this->ShadingNormalBound = nullptr;
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
  os << indent << "ReadShadingNormals: " << this->ReadShadingNormals << "\n";
  os << indent << "ShowChannels: " << this->ShowChannels << "\n";
  os << indent << "Samples used: " << this->GetEffectiveNumberOfSamples() << "\n";
}
