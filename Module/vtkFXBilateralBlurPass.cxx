#include "vtkFXBilateralBlurPass.h"

#include "vtkFXBilateralBlurFS.h"
#include "vtkFXGBufferPass.h"
#include "vtkFXJointUpsample.h"
#include "vtkFXNormalCoding.h"
#include "vtkFXRenderUtilities.h"
#include "vtkFXViewPosition.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkFXBilateralBlurPass);

namespace
{
using GB = vtkFXGBufferPass;
enum Mode
{
  HorizontalPass = 0,
  VerticalPass = 1,
  UpsamplePass = 2,
  Guide = 3,
  Full2DPass = 4 // Separable off
};
}

vtkFXBilateralBlurPass::vtkFXBilateralBlurPass()
{
  this->DeclareInput("source", false, false);
  this->DeclareOutput("blurred");
}

vtkFXBilateralBlurPass::~vtkFXBilateralBlurPass() = default;

unsigned int vtkFXBilateralBlurPass::GetRequiredChannels()
{
  return GB::ChannelBit(GB::Normal) | GB::ChannelBit(GB::LinearDepth);
}

vtkFXEffectPass::Output vtkFXBilateralBlurPass::GetOutput(const char* name)
{
  return (name && std::string(name) == "blurred") ? this->Result : Output();
}

std::array<float, 17> vtkFXBilateralBlurPass::TapWeights() const
{
  // A Gaussian of sigma Radius / 2 (at least 1/2), or the box whose end
  // taps weigh 1/2 (see Kernel); entry |i| for the tap i texels away.
  std::array<float, 17> weights{};
  const double sigma = std::max(0.5 * this->Radius, 0.5);
  for (int i = 0; i <= this->Radius && i < 17; ++i)
  {
    weights[i] = this->Kernel == Box ? (i == this->Radius ? 0.5f : 1.0f)
                                     : static_cast<float>(std::exp(-0.5 * i * i / (sigma * sigma)));
  }
  return weights;
}

std::string vtkFXBilateralBlurPass::TapDefines() const
{
  const std::array<float, 17> weights = this->TapWeights();
  std::string list;
  for (int i = 0; i <= this->Radius; ++i)
  {
    // (float literals: an array of floats needs them before GLSL 4.00's
    // implicit conversions in constructors on some compilers)
    list += (i ? ", " : "") + vtkFXRenderUtilities::GLSLFloat(weights[i]);
  }
  return "#define FX_RADIUS " + std::to_string(this->Radius) + "\n#define FX_TAP_WEIGHTS " + list +
    "\n";
}

int vtkFXBilateralBlurPass::OutputFormat() const
{
  switch (this->NumberOfComponents)
  {
    case 1:
      return vtkFXRenderUtilities::R8;
    case 2:
      return vtkFXRenderUtilities::RG8;
    default:
      return vtkFXRenderUtilities::RGBA16F;
  }
}

bool vtkFXBilateralBlurPass::RunStage(int mode, vtkRenderer* renderer,
  vtkTextureObject* input, vtkTextureObject* output, int step, bool packed,
  vtkTextureObject* surfaces, const float* background)
{
  // (packed: the input carries its guide; one value with its depth, or
  // three with their normal and depth)
  const bool withNormals = packed && this->NumberOfComponents == 3;
  std::string fs = vtkFXBilateralBlurFS;
  vtkShaderProgram::Substitute(fs, "//VTK::System::Dec",
    "//VTK::System::Dec\n#define FX_MODE " + std::to_string(mode) + "\n#define FX_PACKED " +
      (packed && !withNormals ? "1" : "0") + "\n#define FX_PACKED_NORMALS " +
      (withNormals ? "1" : "0") + "\n#define FX_DEPTH_COMPONENT " +
      std::to_string(this->NumberOfComponents) + "\n#define FX_NORMAL_POWER " +
      std::to_string(packed && !withNormals ? 0 : this->NormalPower) + "\n#define FX_BOX " +
      (this->Kernel == Box ? "1" : "0") + "\n" + this->TapDefines(),
    false);
  vtkShaderProgram::Substitute(fs, "//VTK::FXNormalCoding::Dec", vtkFXNormalCoding, false);
  vtkShaderProgram::Substitute(fs, "//VTK::FXJointUpsample::Dec", vtkFXJointUpsample, false);
  vtkShaderProgram::Substitute(fs, "//VTK::FXViewPosition::Dec", vtkFXViewPosition, false);

  vtkOpenGLRenderWindow* window =
    vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  // One framebuffer per stage: its attachment never changes between frames.
  vtkFXRenderUtilities::RenderTargetScope target(window, this->FrameBuffers[mode], output);
  if (!target.IsComplete())
  {
    // (say, no memory for a stage's texture at a huge size) No result:
    // consumers read the unblurred source rather than an empty texture.
    if (!this->WarnedIncomplete)
    {
      vtkErrorMacro("vtkFXBilateralBlurPass could not make its " << output->GetWidth() << " x "
                                                                  << output->GetHeight()
                                                                  << " target; nothing blurred.");
      this->WarnedIncomplete = true;
    }
    return false;
  }
  this->Quads[mode].AtFarPlane = surfaces != nullptr;
  vtkShaderProgram* program =
    vtkFXRenderUtilities::ReadyQuad(this->Quads[mode], window, fs);
  if (!program)
  {
    return false;
  }
  if (surfaces)
  {
    // Left-out texels keep what the shader would pass through there.
    vtkFXRenderUtilities::ClearTargets(1, background);
    target.SkipWhereDepthIsOne(surfaces);
  }
  vtkTextureObject* depth = this->GBuffer->GetChannelTexture(GB::LinearDepth);
  vtkTextureObject* normal = this->GBuffer->GetGeometricNormalTexture();
  input->Activate();
  depth->Activate();
  normal->Activate();
  if (mode != Guide && !packed) // the guide stage writes it; packed input has none
  {
    this->GuideTexture->Activate();
    program->SetUniformi("fxGuide", this->GuideTexture->GetTextureUnit());
  }
  program->SetUniformi("fxInput", input->GetTextureUnit());
  program->SetUniformi("fxLinearDepth", depth->GetTextureUnit());
  program->SetUniformi("fxNormal", normal->GetTextureUnit());
  const int gbufferSize[2] = { static_cast<int>(depth->GetWidth()),
    static_cast<int>(depth->GetHeight()) };
  const int inputSize[2] = { static_cast<int>(input->GetWidth()),
    static_cast<int>(input->GetHeight()) };
  program->SetUniform2i("fxGBufferSize", gbufferSize);
  program->SetUniform2i("fxInputSize", inputSize);
  program->SetUniformi("fxStep", step);
  program->SetUniformf("fxDepthSigma", static_cast<float>(this->DepthSigma));
  vtkFXRenderUtilities::SetFrustumRayUniforms(program, renderer);
  this->Quads[mode].Helper->Render();
  input->Deactivate();
  depth->Deactivate();
  normal->Deactivate();
  if (mode != Guide && !packed)
  {
    this->GuideTexture->Deactivate();
  }
  return true;
}

void vtkFXBilateralBlurPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  this->SkippedBackground = false;
  this->Result = Output();
  const Output source = this->GetInput("source");
  vtkTextureObject* input = source.Texture;
  vtkTextureObject* depth = this->GBuffer ? this->GBuffer->GetChannelTexture(GB::LinearDepth) : nullptr;
  if (!input || !depth || !this->GBuffer->GetChannelTexture(GB::Normal))
  {
    // (said once until a frame has them again: a source that could not
    // make its texture, say at a huge size, has said why, and would
    // otherwise repeat this every frame)
    if (!this->WarnedMissingInput)
    {
      vtkErrorMacro("vtkFXBilateralBlurPass needs a source that wrote a texture and a "
                    "G-buffer with normal and linear depth channels; nothing blurred.");
      this->WarnedMissingInput = true;
    }
    return;
  }
  this->WarnedMissingInput = false;
  if (source.Step != 1 && source.Step != 2)
  {
    vtkErrorMacro("vtkFXBilateralBlurPass takes sources at full or half resolution, not step "
      << source.Step << ".");
    return;
  }
  vtkOpenGLRenderWindow* window =
    vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow());
  const int width = static_cast<int>(input->GetWidth());
  const int height = static_cast<int>(input->GetHeight());
  const int fullWidth = static_cast<int>(depth->GetWidth());
  const int fullHeight = static_cast<int>(depth->GetHeight());
  const int step = source.Step;
  // Inputs that carry their guide need no guide texture: each tap is one
  // fetch. One value with its depth (vtkFXSSAOPass), or three with their
  // normal and depth (vtkFXDirectionalOcclusionPass's packing: on llvmpipe
  // at 640x480 about 2 ms against 10 for the guide texture's way).
  if (source.Packing == 1 && this->NumberOfComponents != source.Components)
  {
    // Packed values blurred as plain ones overflow and turn to NaN.
    vtkErrorMacro("vtkFXBilateralBlurPass: the source packs "
      << source.Components << " values per texel; NumberOfComponents is "
      << this->NumberOfComponents << ". Nothing blurred this frame.");
    return;
  }
  const bool packed = (this->NumberOfComponents == 1 && source.DepthComponent == 1) ||
    (this->NumberOfComponents == 3 && source.Packing == 1);
  // Intermediate stages keep full precision and values above 1 (inputs
  // other than the occlusion passes may hold them); a depth alongside
  // needs 32 bits (16-bit floats end at 65504 world units).
  const int stageFormat = !packed ? vtkFXRenderUtilities::RGBA16F
    : this->NumberOfComponents == 1 ? vtkFXRenderUtilities::RG32F
                                    : vtkFXRenderUtilities::RGBA32F;
  if (this->Separable)
  {
    vtkFXRenderUtilities::EnsureTexture(this->Horizontal, window, width, height, stageFormat);
  }
  else
  {
    // (the stage's framebuffer keeps an attached texture alive: both go)
    vtkFXRenderUtilities::Release(this->Horizontal, window);
    vtkFXRenderUtilities::Release(this->FrameBuffers[HorizontalPass], window);
  }
  vtkFXRenderUtilities::EnsureTexture(this->Blurred, window, width, height, stageFormat);
  if (packed)
  {
    vtkFXRenderUtilities::Release(this->GuideTexture, window);
    vtkFXRenderUtilities::Release(this->FrameBuffers[Guide], window);
  }
  else
  {
    vtkFXRenderUtilities::EnsureTexture(
      this->GuideTexture, window, width, height, vtkFXRenderUtilities::RGBA32F);
    if (!this->RunStage(Guide, s->GetRenderer(), input, this->GuideTexture, step, packed))
    {
      return; // no result: consumers read the unblurred source
    }
  }
  // Background texels of one packed value with its depth pass through
  // the blur unchanged (the shader's early return): where the source
  // says which they are, they are left out.
  vtkTextureObject* surfaces = this->SkipBackground && packed && this->NumberOfComponents == 1 &&
      source.Surfaces && static_cast<int>(source.Surfaces->GetWidth()) == width &&
      static_cast<int>(source.Surfaces->GetHeight()) == height
    ? source.Surfaces
    : nullptr;
  this->SkippedBackground = surfaces != nullptr;
  const bool blurred = this->Separable
    ? this->RunStage(HorizontalPass, s->GetRenderer(), input, this->Horizontal, step, packed,
        surfaces, source.Background) &&
      this->RunStage(VerticalPass, s->GetRenderer(), this->Horizontal, this->Blurred, step,
        packed, surfaces, source.Background)
    : this->RunStage(Full2DPass, s->GetRenderer(), input, this->Blurred, step, packed, surfaces,
        source.Background);
  if (!blurred)
  {
    this->SkippedBackground = false;
    return;
  }
  // Consumers that upsample inline blend neighbours with the hardware.
  this->Blurred->SetMinificationFilter(vtkTextureObject::Linear);
  this->Blurred->SetMagnificationFilter(vtkTextureObject::Linear);
  this->Result.Components = this->NumberOfComponents;
  if (step > 1 && this->Upsample)
  {
    const int format = this->OutputFormat();
    vtkFXRenderUtilities::EnsureTexture(this->Upsampled, window, fullWidth, fullHeight, format);
    if (!this->RunStage(UpsamplePass, s->GetRenderer(), this->Blurred, this->Upsampled, step, packed))
    {
      this->Result = Output();
      return;
    }
    this->Result.Texture = this->Upsampled;
    this->Result.Format = format;
  }
  else
  {
    vtkFXRenderUtilities::Release(this->Upsampled, window);
    vtkFXRenderUtilities::Release(this->FrameBuffers[UpsamplePass], window);
    this->Result.Texture = this->Blurred;
    this->Result.Step = step;
    this->Result.Format = stageFormat;
    this->Result.DepthComponent = packed ? this->NumberOfComponents : -1;
  }
}

void vtkFXBilateralBlurPass::ReleaseGraphicsResources(vtkWindow* w)
{
  for (int i = 0; i < NumberOfModes; ++i)
  {
    vtkFXRenderUtilities::ReleaseQuad(this->Quads[i], w);
  }
  for (auto* texture : { &this->GuideTexture, &this->Horizontal, &this->Blurred, &this->Upsampled })
  {
    vtkFXRenderUtilities::Release(*texture, w);
  }
  this->Result = Output();
  for (auto& framebuffer : this->FrameBuffers)
  {
    vtkFXRenderUtilities::Release(framebuffer, w);
  }
}

void vtkFXBilateralBlurPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "DepthSigma: " << this->DepthSigma << "\n";
  os << indent << "NormalPower: " << this->NormalPower << "\n";
  os << indent << "NumberOfComponents: " << this->NumberOfComponents << "\n";
  os << indent << "Kernel: " << (this->Kernel == Box ? "Box" : "Gaussian") << "\n";
  os << indent << "Upsample: " << this->Upsample << "\n";
  os << indent << "SkipBackground: " << this->SkipBackground << "\n";
  os << indent << "Separable: " << this->Separable << "\n";
}
