#include "vtkFXToonPass.h"

#include "vtkFXGBufferPass.h"
#include "vtkFXNormalCoding.h"
#include "vtkFXViewPosition.h"
#include "vtkFXRenderUtilities.h"
#include "vtkFXToonBands.h"
#include "vtkFXToonEdgesFS.h"
#include "vtkFXToonLinesFS.h"

#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <sstream>

vtkStandardNewMacro(vtkFXToonPass);

namespace
{
using GB = vtkFXGBufferPass;
const int MaximumBandThresholds = 16; // each one is a step in the composite

// After the version line: FX_GATHER 1 where textureGather can read any
// component (GLSL 4.00, or GLSL 1.50 with ARB_gpu_shader5); both line
// shaders fall back to texelFetch otherwise.
const char* const GatherDefines = "//VTK::System::Dec\n"
                                  "#if __VERSION__ >= 400\n"
                                  "#define FX_GATHER 1\n"
                                  "#elif defined(GL_ARB_gpu_shader5)\n"
                                  "#extension GL_ARB_gpu_shader5 : enable\n"
                                  "#define FX_GATHER 1\n"
                                  "#else\n"
                                  "#define FX_GATHER 0\n"
                                  "#endif\n";
}

vtkFXToonPass::vtkFXToonPass()
{
  this->Stage = PostProcess;
  this->SetDefaultBandThresholds();
}

vtkFXToonPass::~vtkFXToonPass() = default;

void vtkFXToonPass::AddBandThreshold(double threshold)
{
  if (!(threshold > 0.0 && threshold <= 1.0) ||
    (!this->BandThresholds.empty() && !(threshold > this->BandThresholds.back())))
  {
    vtkErrorMacro("Band threshold " << threshold
                                    << " refused: thresholds increase, within (0, 1].");
    return;
  }
  if (static_cast<int>(this->BandThresholds.size()) >= MaximumBandThresholds)
  {
    vtkErrorMacro("At most " << MaximumBandThresholds << " band thresholds; " << threshold
                             << " refused.");
    return;
  }
  this->BandThresholds.push_back(threshold);
  this->Modified();
}

void vtkFXToonPass::RemoveAllBandThresholds()
{
  this->BandThresholds.clear();
  this->Modified();
}

void vtkFXToonPass::SetDefaultBandThresholds()
{
  this->BandThresholds = { 0.05, 0.25, 0.5, 0.75 }; // seed 004
  this->Modified();
}

int vtkFXToonPass::GetNumberOfBandThresholds() const
{
  return static_cast<int>(this->BandThresholds.size());
}

double vtkFXToonPass::GetBandThreshold(int i) const
{
  return (i >= 0 && i < this->GetNumberOfBandThresholds()) ? this->BandThresholds[i] : 0.0;
}

void vtkFXToonPass::SetFeatureLines(bool lines)
{
  if (this->FeatureLines != lines)
  {
    this->FeatureLines = lines;
    // Lines draw onto the lit image; bands alone need no pass of their own.
    this->Stage = lines ? PostProcess : Composite;
    this->Modified();
  }
}

double vtkFXToonPass::GetEffectiveLineWidth(int height) const
{
  return std::max(0.25, this->LineWidth * height / this->LineReferenceHeight);
}

vtkTextureObject* vtkFXToonPass::GetEdgeTexture()
{
  return this->Edges;
}

bool vtkFXToonPass::HasWork(const vtkFXSceneInfo& scene)
{
  return (this->Bands || this->FeatureLines) && this->Superclass::HasWork(scene);
}

unsigned int vtkFXToonPass::GetRequiredChannels()
{
  unsigned int channels = GB::ChannelBit(GB::Normal);
  if (this->FeatureLines)
  {
    channels |= GB::ChannelBit(GB::LinearDepth);
  }
  return channels;
}

std::string vtkFXToonPass::BandCode() const
{
  // Crossing threshold i raises the level to threshold i + 1 (to 1 past
  // the last one): one step per threshold, by the rise.
  std::ostringstream steps;
  steps.precision(9);
  const size_t n = this->BandThresholds.size();
  double level = 0.0;
  for (size_t i = 0; i < n; ++i)
  {
    const double next = i + 1 < n ? this->BandThresholds[i + 1] : 1.0;
    steps << "  level += step(" << std::fixed << this->BandThresholds[i] << ", df) * "
          << next - level << ";\n";
    level = next;
  }
  if (this->BandThresholds.empty())
  {
    steps << "  level = 1.0;\n";
  }
  std::string code = vtkFXToonBands;
  vtkShaderProgram::Substitute(code, "//VTK::FXToonBands::Steps", steps.str(), false);
  return code;
}

std::string vtkFXToonPass::GetCompositeCode(int hook)
{
  if (!this->Bands)
  {
    return std::string();
  }
  switch (hook)
  {
    case Declarations:
      return this->BandCode();
    case DiffuseResponse:
      return "df = @band(df);";
    default:
      return std::string();
  }
}

bool vtkFXToonPass::FindEdges(const vtkRenderState* s, vtkOpenGLRenderWindow* window)
{
  vtkTextureObject* depth = this->GBuffer->GetChannelTexture(GB::LinearDepth);
  vtkTextureObject* normal = this->GBuffer->GetChannelTexture(GB::Normal);
  const int size[2] = { static_cast<int>(depth->GetWidth()), static_cast<int>(depth->GetHeight()) };
  vtkFXRenderUtilities::EnsureTexture(
    this->Edges, window, size[0], size[1], vtkFXRenderUtilities::R8);
  // Gathers that reach past the image read no marks there.
  this->Edges->SetWrapS(vtkTextureObject::ClampToBorder);
  this->Edges->SetWrapT(vtkTextureObject::ClampToBorder);
  this->Edges->SetBorderColor(0.0f, 0.0f, 0.0f, 0.0f);

  std::string fs = vtkFXToonEdgesFS;
  vtkShaderProgram::Substitute(fs, "//VTK::System::Dec",
    std::string(GatherDefines) + "#define FX_SILHOUETTES " + (this->Silhouettes ? "1" : "0") +
      "\n#define FX_CREASES " + (this->Creases ? "1" : "0") + "\n",
    false);
  vtkShaderProgram::Substitute(fs, "//VTK::FXNormalCoding::Dec", vtkFXNormalCoding, false);
  vtkShaderProgram::Substitute(fs, "//VTK::FXViewPosition::Dec", vtkFXViewPosition, false);
  vtkFXRenderUtilities::RenderTargetScope target(window, this->EdgeFrameBuffer, this->Edges);
  vtkShaderProgram* program =
    vtkFXRenderUtilities::ReadyQuad(this->EdgeQuad, window, fs);
  if (!program)
  {
    return false;
  }
  depth->Activate();
  normal->Activate();
  program->SetUniformi("fxLinearDepth", depth->GetTextureUnit());
  program->SetUniformi("fxNormal", normal->GetTextureUnit());
  program->SetUniform2i("fxGBufferSize", size);
  vtkFXRenderUtilities::SetFrustumRayUniforms(program, s->GetRenderer());
  program->SetUniformf("fxSilhouetteThreshold", static_cast<float>(this->SilhouetteThreshold));
  program->SetUniformf(
    "fxCreaseCosine", static_cast<float>(std::cos(vtkMath::RadiansFromDegrees(this->CreaseAngle))));
  this->EdgeQuad.Helper->Render();
  depth->Deactivate();
  normal->Deactivate();
  return true;
}

void vtkFXToonPass::DrawLines(const vtkRenderState*, vtkOpenGLRenderWindow* window)
{
  std::string fs = vtkFXToonLinesFS;
  vtkShaderProgram::Substitute(fs, "//VTK::System::Dec", GatherDefines, false);
  vtkShaderProgram* program =
    vtkFXRenderUtilities::ReadyQuad(this->LineQuad, window, fs);
  if (!program)
  {
    return;
  }
  // Onto the image the pipeline is drawing (its HDR target, or whatever
  // framebuffer a hand-built chain renders to), blended by coverage; the
  // alpha of what is under a line becomes opaque where the line covers it.
  vtkFXRenderUtilities::BlendOntoScope blend(
    window, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);

  const int size[2] = { static_cast<int>(this->Edges->GetWidth()),
    static_cast<int>(this->Edges->GetHeight()) };
  // gl_FragCoord counts from the framebuffer's corner, the edges from the
  // viewport's.
  int viewport[4];
  window->GetState()->vtkglGetIntegerv(GL_VIEWPORT, viewport);
  program->SetUniform2i("fxOrigin", viewport);
  const double width = this->GetEffectiveLineWidth(size[1]);
  this->Edges->Activate();
  program->SetUniformi("fxEdges", this->Edges->GetTextureUnit());
  program->SetUniform2i("fxEdgeSize", size);
  program->SetUniformf("fxHalfWidth", static_cast<float>(0.5 * width));
  // Texel offsets whose side midpoints can be within width / 2 + 1/2 of a
  // pixel's centre, widened to an even count (2x2 blocks).
  const int reach[2] = { -static_cast<int>(std::floor(0.5 * width + 1.0)),
    static_cast<int>(std::floor(0.5 * width + 0.5)) };
  const int blocks[2] = { reach[0], reach[1] + (reach[1] - reach[0] + 1) % 2 };
  program->SetUniform2i("fxWindow", blocks);
  float color[3];
  for (int i = 0; i < 3; ++i)
  {
    // NaN and negative colours would spread into the image: clamp them.
    const double c = this->LineColor[i];
    color[i] = static_cast<float>(c >= 0.0 ? std::min(c, 65504.0) : 0.0);
  }
  program->SetUniform3f("fxLineColor", color);
  this->LineQuad.Helper->Render();
  this->Edges->Deactivate();
}

void vtkFXToonPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  if (!this->FeatureLines)
  {
    return; // bands are composite code
  }
  if (!this->GBuffer || !this->GBuffer->GetChannelTexture(GB::LinearDepth) ||
    !this->GBuffer->GetChannelTexture(GB::Normal))
  {
    vtkErrorMacro("vtkFXToonPass's lines need a G-buffer with normal and linear depth channels.");
    return;
  }
  vtkOpenGLRenderWindow* window =
    vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow());
  if (this->FindEdges(s, window))
  {
    this->DrawLines(s, window);
  }
}

void vtkFXToonPass::ReleaseGraphicsResources(vtkWindow* w)
{
  vtkFXRenderUtilities::ReleaseQuad(this->EdgeQuad, w);
  vtkFXRenderUtilities::ReleaseQuad(this->LineQuad, w);
  vtkFXRenderUtilities::Release(this->Edges, w);
  vtkFXRenderUtilities::Release(this->EdgeFrameBuffer, w);
}

void vtkFXToonPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Bands: " << this->Bands << " (thresholds";
  for (double t : this->BandThresholds)
  {
    os << " " << t;
  }
  os << ")\n";
  os << indent << "FeatureLines: " << this->FeatureLines << "\n";
  os << indent << "Silhouettes: " << this->Silhouettes << "\n";
  os << indent << "Creases: " << this->Creases << "\n";
  os << indent << "SilhouetteThreshold: " << this->SilhouetteThreshold << "\n";
  os << indent << "CreaseAngle: " << this->CreaseAngle << "\n";
  os << indent << "LineWidth: " << this->LineWidth << " at " << this->LineReferenceHeight
     << " rows\n";
  os << indent << "LineColor: " << this->LineColor[0] << " " << this->LineColor[1] << " "
     << this->LineColor[2] << "\n";
}
