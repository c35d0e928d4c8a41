#include "vtkFXBloomPass.h"

#include "vtkFXCompositePass.h"

#include "vtkFXBloomDownsampleFS.h"
#include "vtkFXBloomMirror.h"
#include "vtkFXBloomPrefilterFS.h"
#include "vtkFXBloomUpsampleFS.h"
#include "vtkFXGBufferPass.h"
#include "vtkFXRenderUtilities.h"

#include "vtkBoundingBox.h"
#include "vtkCamera.h"
#include "vtkActor2D.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkProp.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkFXOpenGL.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkFXBloomPass);

namespace
{
using GB = vtkFXGBufferPass;
const int MaximumLevels = 10;
const float Transparent[4] = { 0.0f, 0.0f, 0.0f, 0.0f };

}

namespace
{
// Levels are read bilinearly and mirrored past their borders: a filter
// reaching past the image reads the texels it reflects, so a texel near
// the border gives away as much light as one inside (clamped, the border
// texels would count again for every tap past them).
void SetFilterAndMirror(vtkTextureObject* texture)
{
  texture->SetMinificationFilter(vtkTextureObject::Linear);
  texture->SetMagnificationFilter(vtkTextureObject::Linear);
  texture->SetWrapS(vtkTextureObject::MirroredRepeat);
  texture->SetWrapT(vtkTextureObject::MirroredRepeat);
}
}

// One level of the pyramid: the step down and the step up, each with the
// framebuffer that writes it.
struct vtkFXBloomPass::Level
{
  vtkSmartPointer<vtkTextureObject> Down;
  vtkSmartPointer<vtkTextureObject> Up;
  vtkSmartPointer<vtkOpenGLFramebufferObject> DownTarget;
  vtkSmartPointer<vtkOpenGLFramebufferObject> UpTarget;

  void Release(vtkWindow* window)
  {
    vtkFXRenderUtilities::Release(this->Down, window);
    vtkFXRenderUtilities::Release(this->Up, window);
    vtkFXRenderUtilities::Release(this->DownTarget, window);
    vtkFXRenderUtilities::Release(this->UpTarget, window);
  }
};

vtkFXBloomPass::vtkFXBloomPass()
{
  this->Stage = PostProcess;
}

vtkFXBloomPass::~vtkFXBloomPass()
{
  // (vtkRenderer::SetPass does not release the pass it replaces: the
  // sampler, a bare GL name, goes here while its context lives)
  this->ReleaseSampler();
}

void vtkFXBloomPass::ReleaseSampler()
{
  if (this->LinearSampler && this->SamplerWindow)
  {
    // (in its own context, then back to whichever was current)
    this->SamplerWindow->PushContext();
    glDeleteSamplers(1, &this->LinearSampler);
    this->SamplerWindow->PopContext();
  }
  this->LinearSampler = 0;
  this->SamplerWindow = nullptr;
}

bool vtkFXBloomPass::HasWork(const vtkFXSceneInfo& scene)
{
  // Where the glow can be: around what the emissive props draw, splats
  // whole (see ComputeGlowRect); anywhere when that cannot be told (wide
  // points or lines reach past the bounds by pixels).
  vtkBoundingBox emissive;
  bool anywhere = false;
  for (vtkProp* prop : scene.EmissiveProps)
  {
    double b[6];
    const int kind = vtkFXRenderUtilities::GetReachedBounds(prop, -1.0, b);
    anywhere = anywhere || kind == vtkFXRenderUtilities::DrawsAnywhere;
    if (kind == vtkFXRenderUtilities::DrawsWithin)
    {
      emissive.AddBounds(b);
    }
  }
  // (uninitialized, glow anywhere, when a prop's extent is unknown or none
  // has any)
  emissive.GetBounds(this->EmissiveBounds);
  if (anywhere)
  {
    vtkMath::UninitializeBounds(this->EmissiveBounds);
  }
  // The emission channel only when something emits: a threshold alone
  // reads the lit image.
  this->ReadsEmission = this->UseEmission && !scene.EmissiveProps.empty() &&
    this->Superclass::HasWork(scene); // (the channel comes with the G-buffer)
  // Opaque props drawn forward and the layers below can hide emissive
  // surfaces, whose emission must then not glow: the prefilter compares
  // depths, in the HDR target (GetNeedsHDRTarget).
  // (2D props among them are drawn in the overlay, after the glow)
  const bool forward3D = std::any_of(scene.ForwardOpaqueProps.begin(),
    scene.ForwardOpaqueProps.end(), [](vtkProp* prop) { return !vtkActor2D::SafeDownCast(prop); });
  this->MasksHiddenEmission = this->ReadsEmission && (forward3D || scene.KeepsLowerDepth);
  // Translucent props and volumes drawn over an emitter dim its glow by
  // what they let through (vtkFXCompositePass::SetMarksTransmittance),
  // where their screen rectangles meet the emitters'.
  this->DimsEmissionByCoverage = this->ReadsEmission && this->MayCoverEmitters(scene);
  // A threshold reads the lit image, whatever drew it (translucent props
  // and volumes too, with no opaque prop).
  const bool source = this->ReadsEmission || this->Threshold >= 0.0;
  return source && this->Intensity > 0.0;
}

unsigned int vtkFXBloomPass::GetRequiredChannels()
{
  return this->ReadsEmission ? GB::ChannelBit(GB::Emission) : 0u;
}

void vtkFXBloomPass::SetKnee(double knee)
{
  if (std::isnan(knee))
  {
    vtkErrorMacro("Bloom knee NaN refused; keeping " << this->Knee << ".");
    return;
  }
  knee = std::min(std::max(knee, 0.0), 1.0);
  if (knee != this->Knee)
  {
    this->Knee = knee;
    this->Modified();
  }
}

int vtkFXBloomPass::GetNumberOfLevels(int width, int height, int imageRows) const
{
  // The level whose blur is nearest the reach (on a log scale) is the last.
  const double reach = std::max(1.0, this->Radius * (imageRows > 0 ? imageRows : height));
  int levels = 1;
  for (int k = 2; k <= MaximumLevels; ++k)
  {
    if (std::fabs(std::log(GetLevelSigma(k) / reach)) < std::fabs(std::log(GetLevelSigma(levels) / reach)))
    {
      levels = k;
    }
  }
  // Stop before a level would be smaller than 2 x 2 texels.
  while (levels > 1 && ((width >> levels) < 2 || (height >> levels) < 2))
  {
    --levels;
  }
  return levels;
}

double vtkFXBloomPass::GetLevelSigma(int k)
{
  double variance = 0.0;
  for (int j = 0; j < k; ++j)
  {
    // down from level j: the 4x4 box from full resolution, then 13 taps
    variance += (j == 0 ? 1.25 : 1.75) * std::pow(4.0, j);
    // up from level j + 1: a tent, or (j = 0) the last step's bilinear read
    variance += (j == 0 ? 0.1875 : 0.4375) * std::pow(4.0, j + 1);
  }
  return std::sqrt(variance);
}

bool vtkFXBloomPass::ProjectToScreen(
  vtkRenderer* ren, const double bounds[6], double ndcMin[3], double ndcMax[3])
{
  vtkMatrix4x4* m = ren->GetActiveCamera()->GetCompositeProjectionTransformMatrix(
    ren->GetTiledAspectRatio(), -1, 1);
  return vtkFXRenderUtilities::ProjectBox(bounds, &m->Element[0][0], ndcMin, ndcMax) == 0;
}

bool vtkFXBloomPass::MayCoverEmitters(const vtkFXSceneInfo& scene) const
{
  if (scene.TranslucentProps.empty() && scene.VolumeProps.empty())
  {
    return false;
  }
  double emitters[2][3];
  if (!scene.Renderer || !vtkMath::AreBoundsInitialized(this->EmissiveBounds) ||
    !ProjectToScreen(scene.Renderer, this->EmissiveBounds, emitters[0], emitters[1]))
  {
    return true; // the emitters may be anywhere on screen
  }
  for (const auto* props : { &scene.TranslucentProps, &scene.VolumeProps })
  {
    for (vtkProp* prop : *props)
    {
      double b[6], lo[3], hi[3];
      const int kind = vtkFXRenderUtilities::GetReachedBounds(prop, -1.0, b);
      if (kind == vtkFXRenderUtilities::DrawsAnywhere ||
        (kind == vtkFXRenderUtilities::DrawsWithin &&
          (!ProjectToScreen(scene.Renderer, b, lo, hi) ||
            (lo[0] <= emitters[1][0] && hi[0] >= emitters[0][0] && lo[1] <= emitters[1][1] &&
              hi[1] >= emitters[0][1]))))
      {
        return true;
      }
    }
  }
  return false;
}

void vtkFXBloomPass::ComputeGlowRect(vtkRenderer* ren, int width, int height, int levels)
{
  int* rect = this->GlowRect;
  rect[0] = 0;
  rect[1] = 0;
  rect[2] = width;
  rect[3] = height;
  if (this->Threshold >= 0.0 || !vtkMath::AreBoundsInitialized(this->EmissiveBounds))
  {
    return; // lit light may glow anywhere
  }
  double lo[3], hi[3];
  if (!ProjectToScreen(ren, this->EmissiveBounds, lo, hi))
  {
    return; // reaches behind the camera: anywhere
  }
  // The glow reaches 4 deviations of the widest level (its Gaussian is
  // 3e-4 of its peak there) plus the pyramid's texels at the coarsest level.
  const double margin = 4.0 * GetLevelSigma(levels) + std::ldexp(2.0, levels);
  const int size[2] = { width, height };
  for (int a = 0; a < 2; ++a)
  {
    const double first = (0.5 * lo[a] + 0.5) * size[a] - margin;
    const double last = (0.5 * hi[a] + 0.5) * size[a] + margin;
    rect[a] = static_cast<int>(std::max(0.0, std::min(std::floor(first), double(size[a]))));
    rect[a + 2] = static_cast<int>(std::max(0.0, std::min(std::ceil(last), double(size[a]))));
  }
}

void vtkFXBloomPass::LevelRect(int k, int rect[4]) const
{
  vtkTextureObject* t = this->Levels[k]->Down;
  const int size[2] = { static_cast<int>(t->GetWidth()), static_cast<int>(t->GetHeight()) };
  this->LevelRect(k, size, rect);
}

void vtkFXBloomPass::LevelRect(int k, const int size[2], int rect[4]) const
{
  // Level k (0: half resolution) has texels of 2^(k+1) pixels; two texels
  // more on each side hold what its filters read.
  const int shift = k + 1;
  for (int a = 0; a < 2; ++a)
  {
    rect[a] = std::max(0, (this->GlowRect[a] >> shift) - 2);
    rect[a + 2] = std::min(size[a], ((this->GlowRect[a + 2] + (1 << shift) - 1) >> shift) + 2);
  }
}

void vtkFXBloomPass::SetLevelExtent(vtkShaderProgram* program, const char* name, int k) const
{
  const float scale = 1.0f / static_cast<float>(1 << (k + 1));
  const float extent[2] = { this->FullSize[0] * scale, this->FullSize[1] * scale };
  program->SetUniform2f(name, extent);
}

std::string vtkFXBloomPass::WithMirror(const char* shader, const std::string& defines)
{
  std::string fs = shader;
  vtkShaderProgram::Substitute(fs, "//VTK::System::Dec", "//VTK::System::Dec\n" + defines, false);
  vtkShaderProgram::Substitute(fs, "//VTK::FXBloomMirror::Dec", vtkFXBloomMirror, false);
  return fs;
}

vtkTextureObject* vtkFXBloomPass::GetGlowTexture()
{
  // What AddGlow reads: with one level, its own share is the whole glow.
  if (this->Levels.empty())
  {
    return nullptr;
  }
  return this->Levels.size() > 1 ? this->Levels[0]->Up.GetPointer()
                                  : this->Levels[0]->Down.GetPointer();
}

vtkShaderProgram* vtkFXBloomPass::ReadyProgram(
  int which, vtkOpenGLRenderWindow* window, const std::string& fs)
{
  return vtkFXRenderUtilities::ReadyQuad(this->Quads[which], window, fs);
}

bool vtkFXBloomPass::Prefilter(vtkOpenGLRenderWindow* window, vtkTextureObject* color,
  vtkTextureObject* emission, vtkTextureObject* targetDepth, vtkTextureObject* coverage)
{
  vtkTextureObject* surfaceDepth = this->GBuffer ? this->GBuffer->GetDepthTexture() : nullptr;
  vtkTextureObject* full = color ? color : emission;
  // (the target's alpha, read where it is the emission's size)
  coverage = emission && coverage && coverage->GetWidth() == emission->GetWidth() &&
      coverage->GetHeight() == emission->GetHeight()
    ? coverage
    : nullptr;
  const int width = static_cast<int>(full->GetWidth());
  const int height = static_cast<int>(full->GetHeight());
  // (a multisampled depth cannot be read as a plain texture: no mask)
  const bool mask = emission && targetDepth && surfaceDepth && targetDepth->GetSamples() <= 1 &&
    static_cast<int>(targetDepth->GetWidth()) == width &&
    static_cast<int>(targetDepth->GetHeight()) == height &&
    static_cast<int>(surfaceDepth->GetWidth()) == width &&
    static_cast<int>(surfaceDepth->GetHeight()) == height;
  vtkFXRenderUtilities::EnsureTexture(
    this->Prefiltered, window, width, height, vtkFXRenderUtilities::RGBA16F);
  SetFilterAndMirror(this->Prefiltered);
  std::string fs = vtkFXBloomPrefilterFS;
  vtkShaderProgram::Substitute(fs, "//VTK::System::Dec",
    std::string("//VTK::System::Dec\n#define FX_EMISSION ") + (emission ? "1" : "0") +
      "\n#define FX_THRESHOLD " + (color ? "1" : "0") + "\n#define FX_MASK " +
      (mask ? "1" : "0") + "\n#define FX_COVERAGE " + (coverage ? "1" : "0") + "\n",
    false);
  vtkFXRenderUtilities::RenderTargetScope target(window, this->PrefilterTarget, this->Prefiltered);
  vtkShaderProgram* program = target.IsComplete()
    ? this->ReadyProgram(PrefilterProgram, window, fs)
    : nullptr;
  if (!program)
  {
    return false;
  }
  // Only what the first step down reads: its texels' 4x4 boxes, from
  // pixel 2t - 1 to 2t + 2 for texel t.
  const int size[2] = { width, height };
  const int halfSize[2] = { std::max(1, (width + 1) / 2), std::max(1, (height + 1) / 2) };
  int rect[4];
  this->LevelRect(0, halfSize, rect);
  for (int a = 0; a < 2; ++a)
  {
    rect[a] = std::max(0, 2 * rect[a] - 1);
    rect[a + 2] = std::min(size[a], 2 * rect[a + 2] + 1);
  }
  vtkFXRenderUtilities::ScissorScope scissor(window->GetState(), rect);
  std::vector<vtkTextureObject*> bound;
  const auto bind = [&](const char* name, vtkTextureObject* texture) {
    texture->Activate();
    program->SetUniformi(name, texture->GetTextureUnit());
    bound.push_back(texture);
  };
  if (color)
  {
    bind("fxColor", color);
    program->SetUniformf("fxThreshold", static_cast<float>(this->Threshold));
    program->SetUniformf("fxKnee", static_cast<float>(this->Knee * this->Threshold));
  }
  if (emission)
  {
    bind("fxEmission", emission);
  }
  if (coverage)
  {
    bind("fxCoverage", coverage);
    program->SetUniformf("fxAlphaMark", static_cast<float>(vtkFXCompositePass::TransmittanceMark));
  }
  if (mask)
  {
    bind("fxSurfaceDepth", surfaceDepth);
    bind("fxTargetDepth", targetDepth);
  }
  this->Quads[PrefilterProgram].Helper->Render();
  for (vtkTextureObject* texture : bound)
  {
    texture->Deactivate();
  }
  return true;
}

void vtkFXBloomPass::ReleasePrefilter(vtkWindow* window)
{
  vtkFXRenderUtilities::ReleaseQuad(this->Quads[PrefilterProgram], window);
  vtkFXRenderUtilities::Release(this->Prefiltered, window);
  vtkFXRenderUtilities::Release(this->PrefilterTarget, window);
}

bool vtkFXBloomPass::Downsample(vtkOpenGLRenderWindow* window, vtkTextureObject* color,
  vtkTextureObject* targetDepth, vtkTextureObject* coverage, int levels)
{
  vtkTextureObject* emission =
    this->ReadsEmission && this->GBuffer ? this->GBuffer->GetChannelTexture(GB::Emission) : nullptr;
  const bool threshold = this->Threshold >= 0.0 && color;
  if (!emission && !threshold)
  {
    return false;
  }
  // With a threshold, or emission to mask, the first step reads the
  // prefiltered image as it reads any level; otherwise the emission
  // channel, bilinearly, through the sampler object (without sampler
  // objects, before GL 3.3, through the prefilter too, which fetches
  // texels).
  const bool prefiltered =
    threshold || (emission && (targetDepth || coverage || !this->LinearSampler));
  if (prefiltered &&
    !this->Prefilter(window, threshold ? color : nullptr, emission, targetDepth, coverage))
  {
    return false;
  }
  if (!prefiltered)
  {
    this->ReleasePrefilter(window);
  }
  vtkTextureObject* full = prefiltered ? this->Prefiltered.GetPointer() : emission;
  int width = static_cast<int>(full->GetWidth());
  int height = static_cast<int>(full->GetHeight());
  this->FullSize[0] = width;
  this->FullSize[1] = height;
  for (int k = 0; k < levels; ++k)
  {
    const int sourceSize[2] = { width, height };
    width = std::max(1, (width + 1) / 2);
    height = std::max(1, (height + 1) / 2);
    Level& level = *this->Levels[k];
    vtkFXRenderUtilities::EnsureTexture(
      level.Down, window, width, height, vtkFXRenderUtilities::RGBA16F);
    SetFilterAndMirror(level.Down);

    const bool first = k == 0;
    const bool readsEmission = first && !prefiltered;
    const std::string fs = WithMirror(vtkFXBloomDownsampleFS,
      std::string("#define FX_FIRST ") + (readsEmission ? "1" : "0") + "\n#define FX_BOX " +
        (first ? "1" : "0") + "\n#define FX_KARIS " +
        (first && this->FireflySuppression ? "1" : "0") + "\n");
    vtkFXRenderUtilities::RenderTargetScope target(window, level.DownTarget, level.Down);
    // (a level that cannot be drawn, say for want of memory: no glow this
    // frame rather than the undefined contents of an unwritten level; and
    // checked before the scissor's clear, which would leave a GL error)
    if (!target.IsComplete())
    {
      return false;
    }
    int rect[4];
    this->LevelRect(k, rect);
    vtkFXRenderUtilities::ScissorScope scissor(window->GetState(), rect, Transparent);
    vtkShaderProgram* program = this->ReadyProgram(first ? FirstDown : Down, window, fs);
    if (!program)
    {
      return false;
    }
    const float texel[2] = { 1.0f / sourceSize[0], 1.0f / sourceSize[1] };
    program->SetUniform2f("fxSourceTexel", texel);
    this->SetLevelExtent(program, "fxSourceExtent", k - 1);
    vtkTextureObject* source = readsEmission ? emission
      : first                                ? this->Prefiltered.GetPointer()
                                             : this->Levels[k - 1]->Down.GetPointer();
    source->Activate();
    program->SetUniformi(readsEmission ? "fxEmission" : "fxSource", source->GetTextureUnit());
    if (readsEmission)
    {
      // The G-buffer's channel is another pass's texture, filtered nearest:
      // read it bilinearly through a sampler object instead of changing it.
      glBindSampler(source->GetTextureUnit(), this->LinearSampler);
    }
    this->Quads[first ? FirstDown : Down].Helper->Render();
    if (readsEmission)
    {
      glBindSampler(source->GetTextureUnit(), 0);
    }
    source->Deactivate();
  }
  return true;
}

bool vtkFXBloomPass::Upsample(vtkOpenGLRenderWindow* window, int levels)
{
  // Equal shares: the glow is the mean of the levels brought up.
  const float share = 1.0f / levels;
  for (int k = levels - 2; k >= 0; --k)
  {
    Level& level = *this->Levels[k];
    const bool coarsest = k + 1 == levels - 1;
    vtkTextureObject* coarse = coarsest ? this->Levels[k + 1]->Down : this->Levels[k + 1]->Up;
    vtkFXRenderUtilities::EnsureTexture(level.Up, window, static_cast<int>(level.Down->GetWidth()),
      static_cast<int>(level.Down->GetHeight()), vtkFXRenderUtilities::RGBA16F);
    SetFilterAndMirror(level.Up);
    const std::string fs = WithMirror(vtkFXBloomUpsampleFS, "#define FX_FINAL 0\n");
    vtkFXRenderUtilities::RenderTargetScope target(window, level.UpTarget, level.Up);
    if (!target.IsComplete())
    {
      return false; // (as in Downsample)
    }
    int rect[4];
    this->LevelRect(k, rect);
    vtkFXRenderUtilities::ScissorScope scissor(window->GetState(), rect, Transparent);
    vtkShaderProgram* program = this->ReadyProgram(Up, window, fs);
    if (!program)
    {
      return false;
    }
    coarse->Activate();
    level.Down->Activate();
    program->SetUniformi("fxCoarse", coarse->GetTextureUnit());
    program->SetUniformi("fxLevel", level.Down->GetTextureUnit());
    const float texel[2] = { 1.0f / coarse->GetWidth(), 1.0f / coarse->GetHeight() };
    program->SetUniform2f("fxCoarseTexel", texel);
    this->SetLevelExtent(program, "fxCoarseExtent", k + 1);
    program->SetUniformf("fxCoarseScale", coarsest ? share : 1.0f);
    const int origin[2] = { 0, 0 };
    program->SetUniform2i("fxOrigin", origin);
    program->SetUniformf("fxShare", share);
    this->Quads[Up].Helper->Render();
    coarse->Deactivate();
    level.Down->Deactivate();
  }
  return true;
}

void vtkFXBloomPass::AddGlow(vtkOpenGLRenderWindow* window)
{
  vtkTextureObject* glow = this->GetGlowTexture();
  if (!glow)
  {
    return;
  }
  const std::string fs = WithMirror(vtkFXBloomUpsampleFS, "#define FX_FINAL 1\n");
  vtkShaderProgram* program = this->ReadyProgram(Final, window, fs);
  if (!program)
  {
    return;
  }
  // Light adds; the glow's coverage goes over the alpha (src + dst (1 - src),
  // written as src (1 - dst) + dst: the same sum). Only where glow can be
  // (the viewport's corner may be off the framebuffer's).
  vtkFXRenderUtilities::BlendOntoScope blend(
    window, GL_ONE, GL_ONE, GL_ONE_MINUS_DST_ALPHA, GL_ONE);
  int viewport[4];
  window->GetState()->vtkglGetIntegerv(GL_VIEWPORT, viewport);
  const int rect[4] = { viewport[0] + this->GlowRect[0], viewport[1] + this->GlowRect[1],
    viewport[0] + this->GlowRect[2], viewport[1] + this->GlowRect[3] };
  vtkFXRenderUtilities::ScissorScope scissor(window->GetState(), rect);
  glow->Activate();
  program->SetUniformi("fxCoarse", glow->GetTextureUnit());
  const float texel[2] = { 1.0f / glow->GetWidth(), 1.0f / glow->GetHeight() };
  program->SetUniform2f("fxCoarseTexel", texel);
  this->SetLevelExtent(program, "fxCoarseExtent", 0); // (the glow: level 0's Up, or its Down)
  program->SetUniformf("fxCoarseScale", 1.0f);
  program->SetUniform2i("fxOrigin", viewport);
  program->SetUniformf("fxIntensity", static_cast<float>(this->Intensity));
  this->Quads[Final].Helper->Render();
  glow->Deactivate();
}

void vtkFXBloomPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  vtkOpenGLRenderWindow* window =
    vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow());
  // The lit HDR image, for the threshold: the colour of the framebuffer
  // the pipeline renders into.
  auto* target = vtkOpenGLFramebufferObject::SafeDownCast(s->GetFrameBuffer());
  vtkTextureObject* color = target ? target->GetColorAttachmentAsTextureObject(0) : nullptr;
  if (this->Threshold >= 0.0 && !color && !this->WarnedNoLitImage)
  {
    vtkWarningMacro("vtkFXBloomPass's threshold reads the lit image of an HDR target "
                    "(vtkFXPipelinePass provides one); only emission glows.");
    this->WarnedNoLitImage = true; // (once: the frames after are the same)
  }
  vtkTextureObject* emission =
    this->ReadsEmission && this->GBuffer ? this->GBuffer->GetChannelTexture(GB::Emission) : nullptr;
  // The size the pyramid starts from: what Downsample's first step reads
  // (the prefiltered lit image with a threshold, else the emission).
  vtkTextureObject* full = this->Threshold >= 0.0 && color ? color : (emission ? emission : color);
  if (!full)
  {
    vtkErrorMacro("vtkFXBloomPass needs the G-buffer's emission channel or a threshold on the "
                  "HDR target's image.");
    return;
  }
  this->WarnIfDrawnInTiles(s->GetRenderer(), "the glow cannot reach");
  if (this->LinearSampler && this->SamplerWindow != window)
  {
    this->ReleaseSampler(); // (made in another window's context)
  }
  if (!this->LinearSampler &&
    (vtkFXRenderUtilities::IsOpenGLSupported("GL_VERSION_3_3") ||
      vtkFXRenderUtilities::IsOpenGLSupported("GL_ARB_sampler_objects")))
  {
    this->SamplerWindow = window;
    glGenSamplers(1, &this->LinearSampler);
    glSamplerParameteri(this->LinearSampler, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glSamplerParameteri(this->LinearSampler, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(this->LinearSampler, GL_TEXTURE_WRAP_S, GL_MIRRORED_REPEAT);
    glSamplerParameteri(this->LinearSampler, GL_TEXTURE_WRAP_T, GL_MIRRORED_REPEAT);
  }
  const int levels =
    this->GetNumberOfLevels(static_cast<int>(full->GetWidth()), static_cast<int>(full->GetHeight()),
      vtkFXRenderUtilities::GetImageRows(s->GetRenderer(), static_cast<int>(full->GetHeight())));
  if (static_cast<int>(this->Levels.size()) > levels)
  {
    while (static_cast<int>(this->Levels.size()) > levels)
    {
      this->Levels.back()->Release(window);
      this->Levels.pop_back();
    }
    // The new coarsest level is read from its Down texture: no Up.
    vtkFXRenderUtilities::Release(this->Levels.back()->Up, window);
    vtkFXRenderUtilities::Release(this->Levels.back()->UpTarget, window);
  }
  while (static_cast<int>(this->Levels.size()) < levels)
  {
    this->Levels.emplace_back(new Level);
  }
  this->ComputeGlowRect(s->GetRenderer(), static_cast<int>(full->GetWidth()),
    static_cast<int>(full->GetHeight()), levels);
  if (levels == 1 && !this->Levels.empty())
  {
    // No step up: an earlier frame's upsampled glow must not linger.
    vtkFXRenderUtilities::Release(this->Levels[0]->Up, window);
  }
  // Emission of surfaces something drawn in front hides must not glow:
  // where the target's depth, which holds what hides them, is nearer than
  // the G-buffer's.
  vtkTextureObject* targetDepth =
    this->MasksHiddenEmission && target ? target->GetDepthAttachmentAsTextureObject() : nullptr;
  // The target's alpha, which tells the emitters' transmittance
  // (vtkFXCompositePass::SetMarksTransmittance); a float one only: where
  // the HDR target could not be made, the pipeline draws into the
  // framebuffer it found, whose 8 bits clamp the mark to 1 (T = 0: the
  // glow would vanish).
  vtkTextureObject* coverage =
    this->DimsEmissionByCoverage && color && color->GetVTKDataType() == VTK_FLOAT ? color : nullptr;
  if (this->Downsample(window, color, targetDepth, coverage, levels) &&
    this->Upsample(window, levels))
  {
    this->AddGlow(window);
  }
}

void vtkFXBloomPass::ReleaseGraphicsResources(vtkWindow* w)
{
  for (int i = 0; i < NumberOfPrograms; ++i)
  {
    vtkFXRenderUtilities::ReleaseQuad(this->Quads[i], w);
  }
  for (auto& level : this->Levels)
  {
    level->Release(w);
  }
  this->Levels.clear();
  this->ReleasePrefilter(w);
  this->ReleaseSampler();
}

void vtkFXBloomPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Intensity: " << this->Intensity << "\n";
  os << indent << "Radius: " << this->Radius << "\n";
  os << indent << "UseEmission: " << this->UseEmission << "\n";
  os << indent << "Threshold: " << this->Threshold << "\n";
  os << indent << "Knee: " << this->Knee << "\n";
  os << indent << "FireflySuppression: " << this->FireflySuppression << "\n";
}
