#include "vtkFXToonPass.h"

#include "vtkFXGBufferPass.h"
#include "vtkFXNormalCoding.h"
#include "vtkFXViewPosition.h"
#include "vtkFXRenderUtilities.h"
#include "vtkFXToonBands.h"
#include "vtkFXToonEdgeMaskFS.h"
#include "vtkFXToonEdgesFS.h"
#include "vtkFXToonLinesFS.h"

#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderState.h"
#include "vtkCamera.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkFXOpenGL.h"

#include <algorithm>
#include <limits>
#include <cmath>
#include <sstream>

vtkStandardNewMacro(vtkFXToonPass);

namespace
{
using GB = vtkFXGBufferPass;
const int MaximumBandThresholds = 16; // each one is a step in the composite
const int LineTileSize = 8;           // pixels; lines are drawn tile by tile
// Pixels; the lines shader visits every side midpoint within half of it.
const double MaximumLineWidth = 32.0;
// Line windows (texels per side) up to this get straight-line code: lines
// under 5 px wide (72 midpoints); wider ones a loop.
const int MaximumUnrolledLineWindow = 6;

// The defines both line shaders take for UseTextureGather (both fall back
// to texelFetch without it).
const char* GatherDefinesFor(bool useTextureGather)
{
  return vtkFXRenderUtilities::GatherDefines(useTextureGather);
}
}

vtkFXToonPass::vtkFXToonPass()
{
  this->Stage = PostProcess;
  // The edges shader's tile-flag loop runs a number of times that differs
  // between neighbouring pixels: safe on llvmpipe only without a
  // primitive edge inside the viewport (see FullScreenQuad::OneTriangle).
  this->EdgeQuad.OneTriangle = true;
  this->LineTiles.TileSize = LineTileSize;
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
  return std::min(MaximumLineWidth,
    std::max(0.25, this->LineWidth * height / this->LineReferenceHeight));
}

vtkTextureObject* vtkFXToonPass::GetEdgeTexture()
{
  return this->Edges;
}

bool vtkFXToonPass::HasWork(const vtkFXSceneInfo& scene)
{
  // Bands quantise light: with no light on there is none to band.
  const bool bands = this->Bands && scene.LightingComplexity > 0;
  return (bands || this->DrawsLines()) && this->Superclass::HasWork(scene);
}

double vtkFXToonPass::GetSmallestRaisedDiffuse()
{
  if (!this->Bands)
  {
    return 0.0;
  }
  // Without thresholds every positive factor becomes 1: the smallest
  // positive double says so (the light tiles then bound no light).
  return this->BandThresholds.empty() ? std::numeric_limits<double>::denorm_min()
                                      : this->BandThresholds.front();
}

bool vtkFXToonPass::DrawsLines() const
{
  return this->FeatureLines && (this->Silhouettes || this->Creases);
}

unsigned int vtkFXToonPass::GetRequiredChannels()
{
  unsigned int channels = GB::ChannelBit(GB::Normal);
  if (this->DrawsLines())
  {
    channels |= GB::ChannelBit(GB::LinearDepth);
  }
  return channels;
}

std::string vtkFXToonPass::BandCode() const
{
  // Crossing threshold i raises the level to threshold i + 1 (to 1 past
  // the last one): one step per threshold, by the rise.
  // (GLSLFloat: a threshold of 1e-12 must not print as 0)
  vtkFXRenderUtilities::CodeStream steps;
  const size_t n = this->BandThresholds.size();
  double level = 0.0;
  for (size_t i = 0; i < n; ++i)
  {
    const double next = i + 1 < n ? this->BandThresholds[i + 1] : 1.0;
    steps << "  level += step(" << vtkFXRenderUtilities::GLSLFloat(this->BandThresholds[i])
          << ", df) * " << vtkFXRenderUtilities::GLSLFloat(next - level) << ";\n";
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

void vtkFXToonPass::GetLineWindow(int height, int window[2]) const
{
  // Texel offsets whose side midpoints can be within width / 2 + 1/2 of a
  // pixel's centre, widened to an even count (2x2 blocks).
  const double width = this->GetEffectiveLineWidth(height);
  window[0] = -static_cast<int>(std::floor(0.5 * width + 1.0));
  const int reach = static_cast<int>(std::floor(0.5 * width + 0.5));
  window[1] = reach + (reach - window[0] + 1) % 2;
}

bool vtkFXToonPass::CanFlagLineTiles()
{
  // (the marks' framebuffer has no colour attachment)
  const bool noAttachments = vtkFXRenderUtilities::IsOpenGLSupported("GL_VERSION_4_3") ||
    vtkFXRenderUtilities::IsOpenGLSupported("GL_ARB_framebuffer_no_attachments");
  return noAttachments && vtkFXRenderUtilities::CanFlagTiles(LineTileSize);
}

bool vtkFXToonPass::MakeEdgeMask(
  vtkOpenGLRenderWindow* window, vtkTextureObject* depth, const int size[2])
{
  std::string fs = vtkFXToonEdgeMaskFS;
  vtkShaderProgram::Substitute(
    fs, "//VTK::System::Dec", GatherDefinesFor(this->UseTextureGather), false);
  depth->Activate();
  const bool made = vtkFXRenderUtilities::DrawDepthMask(window, this->EdgeMask, size[0], size[1], fs,
    [&](vtkShaderProgram* program) {
      program->SetUniformi("fxLinearDepth", depth->GetTextureUnit());
      program->SetUniform2i("fxGBufferSize", size);
    });
  depth->Deactivate();
  return made;
}

std::string vtkFXToonPass::EdgesSource(bool imageStores) const
{
  std::string fs = vtkFXToonEdgesFS;
  vtkShaderProgram::Substitute(fs, "//VTK::System::Dec",
    std::string(GatherDefinesFor(this->UseTextureGather)) + "#define FX_SILHOUETTES " +
      (this->Silhouettes ? "1" : "0") + "\n#define FX_CREASES " + (this->Creases ? "1" : "0") +
      "\n#define FX_TILE " + std::to_string(LineTileSize) + "\n" +
      (imageStores
          ? "#extension GL_ARB_shader_image_load_store : enable\n#define FX_TILE_MASK 1\n"
          : "#define FX_TILE_MASK 0\n"),
    false);
  vtkShaderProgram::Substitute(fs, "//VTK::FXNormalCoding::Dec", vtkFXNormalCoding, false);
  vtkShaderProgram::Substitute(fs, "//VTK::FXViewPosition::Dec", vtkFXViewPosition, false);
  return fs;
}

bool vtkFXToonPass::FindEdges(const vtkRenderState* s, vtkOpenGLRenderWindow* window)
{
  vtkTextureObject* depth = this->GBuffer->GetChannelTexture(GB::LinearDepth);
  const int size[2] = { static_cast<int>(depth->GetWidth()), static_cast<int>(depth->GetHeight()) };
  vtkFXRenderUtilities::EnsureTexture(
    this->Edges, window, size[0], size[1], vtkFXRenderUtilities::R8);
  // Gathers that reach past the image read no marks there.
  this->Edges->SetWrapS(vtkTextureObject::ClampToBorder);
  this->Edges->SetWrapT(vtkTextureObject::ClampToBorder);
  this->Edges->SetBorderColor(0.0f, 0.0f, 0.0f, 0.0f);
  this->TilesFlagged = false;
  if (this->CullLineTiles && CanFlagLineTiles())
  {
    vtkFXRenderUtilities::ReleaseDepthMask(this->EdgeMask, window);
    this->TilesFlagged = this->StoreEdgeMarks(s, window, size);
    if (this->TilesFlagged)
    {
      return true;
    }
  }
  vtkFXRenderUtilities::Release(this->LineTiles.Mask, window); // no flags kept
  return this->DrawEdgeMarks(s, window, size);
}

bool vtkFXToonPass::StoreEdgeMarks(
  const vtkRenderState* s, vtkOpenGLRenderWindow* window, const int size[2])
{
  // Both images start with no mark; the shader stores the marks and flags.
  const unsigned char zero = 0;
  glClearTexImage(this->Edges->GetHandle(), 0, GL_RED, GL_UNSIGNED_BYTE, &zero);
  if (!vtkFXRenderUtilities::ClearTileMask(this->LineTiles, window, size[0], size[1]))
  {
    return false;
  }
  // No colour attachment: the shader writes images. The G-buffer's depth
  // leaves out the pixels without a surface (they have no marks that a
  // covered neighbour does not store).
  vtkFXRenderUtilities::RenderTargetScope target(window, this->MarkFrameBuffer, size[0], size[1]);
  vtkTextureObject* surfaces =
    this->SkipBackgroundEdges ? this->GBuffer->GetDepthTexture() : nullptr;
  this->EdgeQuad.AtFarPlane = surfaces != nullptr;
  vtkShaderProgram* program =
    vtkFXRenderUtilities::ReadyQuad(this->EdgeQuad, window, this->EdgesSource(true));
  target.SkipWhereDepthIsOne(surfaces);
  if (!program || !target.IsComplete())
  {
    return false; // (the caller draws the marks as colour instead)
  }
  int lineWindow[2];
  this->GetLineWindow(this->OutputRows, lineWindow);
  program->SetUniform2i("fxLineWindow", lineWindow);
  glBindImageTexture(0, this->LineTiles.Mask->GetHandle(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R8);
  glBindImageTexture(1, this->Edges->GetHandle(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R8);
  program->SetUniformi("fxTileMask", 0);
  program->SetUniformi("fxEdges", 1);
  this->RenderEdgesQuad(s, program, size);
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R8);
  glBindImageTexture(1, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R8);
  // The lines read both as textures; the next frame clears them with
  // glClearTexImage.
  // (and a frame with culling switched off draws into Edges)
  glMemoryBarrier(
    GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
  return true;
}

bool vtkFXToonPass::DrawEdgeMarks(
  const vtkRenderState* s, vtkOpenGLRenderWindow* window, const int size[2])
{
  // (a mask that could not be made is not tried again until the
  // resources are released)
  const bool masked = this->SkipBackgroundEdges && !this->EdgeMaskFailed &&
    this->MakeEdgeMask(window, this->GBuffer->GetChannelTexture(GB::LinearDepth), size);
  if (this->SkipBackgroundEdges && !masked)
  {
    this->EdgeMaskFailed = true;
  }
  if (!masked)
  {
    vtkFXRenderUtilities::ReleaseDepthMask(this->EdgeMask, window);
  }
  vtkFXRenderUtilities::RenderTargetScope target(window, this->EdgeFrameBuffer, this->Edges);
  this->EdgeQuad.AtFarPlane = masked;
  // (marks that cannot be drawn: no lines this frame, not the last frame's)
  vtkShaderProgram* program = target.IsComplete()
    ? vtkFXRenderUtilities::ReadyQuad(this->EdgeQuad, window, this->EdgesSource(false))
    : nullptr;
  if (!program)
  {
    return false;
  }
  if (masked)
  {
    // Rejected pixels keep "no mark".
    const float noMark[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
    vtkFXRenderUtilities::ClearTargets(1, noMark);
    target.SkipWhereDepthIsOne(this->EdgeMask.Texture);
  }
  this->RenderEdgesQuad(s, program, size);
  return true;
}

void vtkFXToonPass::RenderEdgesQuad(
  const vtkRenderState* s, vtkShaderProgram* program, const int size[2])
{
  vtkTextureObject* depth = this->GBuffer->GetChannelTexture(GB::LinearDepth);
  vtkTextureObject* normal = this->GBuffer->GetGeometricNormalTexture();
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
}

std::string vtkFXToonPass::MidpointCode(int first, int last)
{
  // Every side midpoint of the texels first..last (an even count) away
  // from the pixel, in the order of the pixel's distance to it; ties keep
  // the order of 2x2 blocks (rows, then columns), texels in a block (w, z,
  // x, y as textureGather returns them) and sides (right, then above), so
  // the nearest two are always the same ones.
  struct Midpoint
  {
    int Block;
    char Component;
    int Bit;
    int X2, Y2; // twice the offset from the pixel's centre
  };
  static const struct
  {
    char Component;
    int X, Y;
  } texelsInBlock[4] = { { 'w', 0, 0 }, { 'z', 1, 0 }, { 'x', 0, 1 }, { 'y', 1, 1 } };
  vtkFXRenderUtilities::CodeStream blocks;
  std::vector<Midpoint> midpoints;
  int block = 0;
  for (int dy = first; dy <= last; dy += 2)
  {
    for (int dx = first; dx <= last; dx += 2, ++block)
    {
      blocks << "  ivec4 block" << block << " = fxMarkBits(fxMarkBlock(pixel + ivec2(" << dx
             << ", " << dy << ")));\n";
      for (const auto& texel : texelsInBlock)
      {
        const int x2 = 2 * (dx + texel.X);
        const int y2 = 2 * (dy + texel.Y);
        midpoints.push_back({ block, texel.Component, 1, x2 + 1, y2 });
        midpoints.push_back({ block, texel.Component, 2, x2, y2 + 1 });
      }
    }
  }
  std::stable_sort(midpoints.begin(), midpoints.end(), [](const Midpoint& a, const Midpoint& b) {
    return a.X2 * a.X2 + a.Y2 * a.Y2 < b.X2 * b.X2 + b.Y2 * b.Y2;
  });
  vtkFXRenderUtilities::CodeStream code;
  code.setf(std::ios::fixed);
  code.precision(1);
  if (last - first + 1 <= MaximumUnrolledLineWindow)
  {
    // One gather per block, then straight-line code.
    code << blocks.str();
    for (const Midpoint& m : midpoints)
    {
      code << "  fxTake(nearest, (block" << m.Block << "." << m.Component << " & " << m.Bit
           << ") != 0, vec2(" << 0.5 * m.X2 << ", " << 0.5 * m.Y2 << "));\n";
    }
    return code.str();
  }
  // Wide lines: a loop over the same list (a few hundred midpoints would
  // make the straight-line code too long). It runs to the end: past the
  // second mark fxTake changes nothing, and on llvmpipe a loop whose trip
  // count differs between neighbouring pixels goes wrong along a
  // primitive's inner edge (vtkFXTilePointsVS draws none; this keeps the
  // lines right whatever draws them).
  code << "  const vec3 midpoints[" << midpoints.size() << "] = vec3[](";
  for (size_t i = 0; i < midpoints.size(); ++i)
  {
    code << (i ? ", " : "") << "vec3(" << 0.5 * midpoints[i].X2 << ", " << 0.5 * midpoints[i].Y2
         << ", " << midpoints[i].Bit << ".0)";
  }
  code << ");\n"
       << "  for (int i = 0; i < " << midpoints.size() << "; ++i)\n"
       << "  {\n"
       << "    vec2 midpoint = midpoints[i].xy;\n"
       << "    int marks = fxMarkBits(vec4(fxMarkAt(pixel + ivec2(floor(midpoint))))).x;\n"
       << "    fxTake(nearest, (marks & int(midpoints[i].z)) != 0, midpoint);\n"
       << "  }\n";
  return code.str();
}

void vtkFXToonPass::DrawLines(const vtkRenderState*, vtkOpenGLRenderWindow* window)
{
  const int size[2] = { static_cast<int>(this->Edges->GetWidth()),
    static_cast<int>(this->Edges->GetHeight()) };
  int lineWindow[2];
  this->GetLineWindow(this->OutputRows, lineWindow);
  // The source depends on the window alone: made again only when it
  // changes (with the viewport's height).
  if (this->LineSource.empty() || this->LineSourceWindow[0] != lineWindow[0] ||
    this->LineSourceWindow[1] != lineWindow[1] || this->LineSourceGathers != this->UseTextureGather)
  {
    this->LineSource = vtkFXToonLinesFS;
    vtkShaderProgram::Substitute(
      this->LineSource, "//VTK::System::Dec", GatherDefinesFor(this->UseTextureGather), false);
    this->LineSourceGathers = this->UseTextureGather;
    vtkShaderProgram::Substitute(this->LineSource, "//VTK::FXToonLines::Midpoints",
      MidpointCode(lineWindow[0], lineWindow[1]), false);
    this->LineSourceWindow[0] = lineWindow[0];
    this->LineSourceWindow[1] = lineWindow[1];
  }
  vtkShaderProgram* program = vtkFXRenderUtilities::ReadyTileProgram(window, this->LineSource);
  if (!program)
  {
    vtkErrorMacro("The feature lines' shaders did not build; no lines are drawn.");
    return;
  }
  // Onto the image the pipeline is drawing (its HDR target, or whatever
  // framebuffer a hand-built chain renders to), blended by coverage; the
  // alpha of what is under a line becomes opaque where the line covers it.
  vtkFXRenderUtilities::BlendOntoScope blend(
    window, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  // Depth-tested at their surfaces' depth (the shader's gl_FragDepth), not
  // written: what hides a surface (an opaque prop drawn forward, a lower
  // layer's preserved depth) hides its lines. The target's depth holds the
  // G-buffer's surfaces (the composite copies them in).
  vtkTextureObject* surfaceDepth = this->GBuffer->GetDepthTexture();
  vtkOpenGLState::ScopedglDepthFunc depthFunc(window->GetState());
  if (surfaceDepth)
  {
    window->GetState()->vtkglEnable(GL_DEPTH_TEST);
    window->GetState()->vtkglDepthFunc(GL_LEQUAL);
  }
  // gl_FragCoord counts from the framebuffer's corner, the edges from the
  // viewport's.
  int viewport[4];
  window->GetState()->vtkglGetIntegerv(GL_VIEWPORT, viewport);
  program->SetUniform2i("fxOrigin", viewport);
  this->Edges->Activate();
  program->SetUniformi("fxEdges", this->Edges->GetTextureUnit());
  if (surfaceDepth)
  {
    surfaceDepth->Activate();
    program->SetUniformi("fxSurfaceDepth", surfaceDepth->GetTextureUnit());
  }
  program->SetUniform2i("fxEdgeSize", size);
  program->SetUniformf(
    "fxHalfWidth", static_cast<float>(0.5 * this->GetEffectiveLineWidth(this->OutputRows)));
  // (SetLineColor keeps it finite, within 0..65504)
  const float color[3] = { static_cast<float>(this->LineColor[0]),
    static_cast<float>(this->LineColor[1]), static_cast<float>(this->LineColor[2]) };
  program->SetUniform3f("fxLineColor", color);
  this->LineTilesCulled = vtkFXRenderUtilities::DrawTiles(
    this->LineTiles, program, window, viewport, size, this->TilesFlagged);
  this->Edges->Deactivate();
  if (surfaceDepth)
  {
    surfaceDepth->Deactivate();
  }
}

void vtkFXToonPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  if (!this->DrawsLines())
  {
    // Bands are composite code; the lines' textures go with the lines.
    vtkRenderWindow* window = s->GetRenderer()->GetRenderWindow();
    vtkFXRenderUtilities::ReleaseTilePoints(this->LineTiles, window);
    vtkFXRenderUtilities::Release(this->Edges, window);
    vtkFXRenderUtilities::Release(this->EdgeFrameBuffer, window);
    vtkFXRenderUtilities::Release(this->MarkFrameBuffer, window);
    vtkFXRenderUtilities::ReleaseDepthMask(this->EdgeMask, window);
    return;
  }
  if (!this->GBuffer || !this->GBuffer->GetChannelTexture(GB::LinearDepth) ||
    !this->GBuffer->GetChannelTexture(GB::Normal))
  {
    vtkErrorMacro("vtkFXToonPass's lines need a G-buffer with normal and linear depth channels.");
    return;
  }
  vtkOpenGLRenderWindow* window =
    vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow());
  // (so that lines keep their width in the whole image of a scaled
  // screenshot)
  this->OutputRows = vtkFXRenderUtilities::GetImageRows(s->GetRenderer(),
    static_cast<int>(this->GBuffer->GetChannelTexture(GB::LinearDepth)->GetHeight()));
  if (this->FindEdges(s, window))
  {
    this->DrawLines(s, window);
  }
}

void vtkFXToonPass::ReleaseGraphicsResources(vtkWindow* w)
{
  vtkFXRenderUtilities::ReleaseQuad(this->EdgeQuad, w);
  vtkFXRenderUtilities::ReleaseDepthMask(this->EdgeMask, w);
  this->EdgeMaskFailed = false;
  vtkFXRenderUtilities::ReleaseTilePoints(this->LineTiles, w);
  vtkFXRenderUtilities::Release(this->Edges, w);
  vtkFXRenderUtilities::Release(this->EdgeFrameBuffer, w);
  vtkFXRenderUtilities::Release(this->MarkFrameBuffer, w);
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
  os << indent << "CullLineTiles: " << this->CullLineTiles << "\n";
  os << indent << "SkipBackgroundEdges: " << this->SkipBackgroundEdges << "\n";
  os << indent << "UseTextureGather: " << this->UseTextureGather << "\n";
  os << indent << "LineColor: " << this->LineColor[0] << " " << this->LineColor[1] << " "
     << this->LineColor[2] << "\n";
}
