#include "vtkFXSSAOPass.h"

#include "vtkFXBilateralBlurPass.h"
#include "vtkFXGBufferPass.h"
#include "vtkFXJointUpsample.h"
#include "vtkFXNormalCoding.h"
#include "vtkFXOcclusionBasis.h"
#include "vtkFXViewPosition.h"
#include "vtkFXRenderUtilities.h"
#include "vtkFXSSAOFS.h"
#include "vtkFXSurfaceMaskFS.h"

#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
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
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkFXSSAOPass);

namespace
{
using GB = vtkFXGBufferPass;

// Slices of the horizon method: its samples are 2 sides x steps x slices.
constexpr int HorizonSlices = 2;

// Radical inverse of i in `base`: a low-discrepancy sequence in [0,1), so
// that few samples already cover the hemisphere evenly and deterministically.
double RadicalInverse(unsigned int i, unsigned int base)
{
  double result = 0.0, scale = 1.0 / base;
  for (; i > 0; i /= base, scale /= base)
  {
    result += (i % base) * scale;
  }
  return result;
}

// Ordered-dither (Bayer) rank of each entry of a size x size tile, size a
// power of two, row by row: neighbours differ most. Built by the recursion
// M(2s) = [4M, 4M + 2; 4M + 3, 4M + 1].
std::vector<int> BayerOrder(int size)
{
  std::vector<int> order(1, 0);
  for (int s = 1; s < size; s *= 2)
  {
    std::vector<int> next(4 * s * s);
    static const int quadrant[2][2] = { { 0, 2 }, { 3, 1 } };
    for (int y = 0; y < 2 * s; ++y)
    {
      for (int x = 0; x < 2 * s; ++x)
      {
        next[y * 2 * s + x] = 4 * order[(y % s) * s + (x % s)] + quadrant[y / s][x / s];
      }
    }
    order.swap(next);
  }
  return order;
}
}

vtkFXSSAOPass::vtkFXSSAOPass()
{
  this->DeclareOutput("occlusion");
  this->DeclareInput("denoised", true, true);
}

vtkFXSSAOPass::~vtkFXSSAOPass() = default;

bool vtkFXSSAOPass::HasWork(const vtkFXSceneInfo& scene)
{
  return scene.LightingComplexity > 0 && this->Superclass::HasWork(scene);
}

unsigned int vtkFXSSAOPass::GetRequiredChannels()
{
  return GB::ChannelBit(GB::Normal) | GB::ChannelBit(GB::LinearDepth);
}

vtkFXEffectPass::Output vtkFXSSAOPass::GetOutput(const char* name)
{
  Output output;
  if (name && std::string(name) == "occlusion" && this->Occlusion)
  {
    output.Texture = this->Occlusion;
    output.Step = this->HalfResolution ? 2 : 1;
    output.Components = this->Channels;
    output.Format = this->GetOcclusionFormat();
    output.DepthComponent = this->Channels == 3 ? 3 : 1;
    output.Packing = this->Channels == 3 ? 1 : 0;
    if (this->SkippedSurfaces)
    {
      output.Surfaces = this->SkippedSurfaces;
      this->GetOpenValue(output.Background);
    }
  }
  return output;
}

void vtkFXSSAOPass::GetOpenValue(float value[4]) const
{
  // What the shader writes where there is no surface. (The horizon
  // method's channels are stored as (v + 0.5) / 2: open is 0.75.)
  if (this->Channels != 3)
  {
    const float open1[4] = { 1.0f, 0.0f, 0.0f, 1.0f };
    std::copy(open1, open1 + 4, value);
    return;
  }
  const bool shifted = this->GetEffectiveMethod() == Horizon;
  const float one = shifted ? 3071.0f : 4095.0f; // fxPack12's q for the open value
  const float pack12Ones = one * 4096.0f + one, pack12Halves = 2048.0f * 4096.0f + 2048.0f;
  const float open3[4] = { pack12Ones, shifted ? 0.75f : 1.0f, pack12Halves, 0.0f };
  std::copy(open3, open3 + 4, value);
}

std::string vtkFXSSAOPass::GetCompositeCode(int hook)
{
  switch (hook)
  {
    case Declarations:
      // Texel i of a reduced-resolution occlusion holds G-buffer pixel
      // i * step (not the centre of a step x step block): pixel p reads
      // texture coordinate (p / step + 0.5) / size = texCoord * scale + offset.
      // (@written: 0 when no occlusion texture was written this frame, see
      // BindCompositeResources)
      return std::string("uniform sampler2D @occlusion;\nuniform vec2 @scale;\n"
                         "uniform vec2 @offset;\nuniform int @written;\n"
                         "uniform ivec2 @fullSize;\nuniform int @step;\n") +
        (this->UpsamplesByDepth(this->CompositeSource()) ? vtkFXJointUpsample : "");
    case Ambient:
    {
      // Where the occlusion carries its depth, upsampled by it (a depth
      // edge keeps each side's occlusion: detail score on vtkfx-bench ao's
      // scenes +0.02 to +0.11 against one bilinear read, PSNR the same or
      // better, 1.6 ms more composite time at 1280x720 on the bunny, two
      // gathers for four texels), judged against the pixel's tangent plane
      // with vtkFXBilateralBlurPass's default tolerance, so that a crease
      // keeps each side's occlusion too; the composite reads fxPixelDepth
      // where a depth channel exists. The plane is the geometric one: the
      // composite's n, unless shading normals (normal textures, bumps)
      // perturb it, when the depth alone is judged (n0 = 0).
      const bool shadingNormals =
        this->GBuffer && this->GBuffer->GetChannelTexture(vtkFXGBufferPass::GeometricNormal);
      const std::string plane = std::string(shadingNormals ? "vec3(0.0)" : "n") + ", @fullSize";
      const std::string sigma =
        vtkFXRenderUtilities::GLSLFloat(vtkFXBilateralBlurPass::DefaultDepthSigma) + ", ";
      const std::string read = this->UpsamplesByDepth(this->CompositeSource())
        ? "\n#if FX_GATHER\n"
          "      float ao = fxPixelDepth > 0.0 ? fxJointUpsampleGathered(@occlusion, "
          "textureSize(@occlusion, 0), @step, ivec2(texCoord * vec2(@fullSize)), fxPixelDepth, " +
          sigma + plane + ") : 1.0;\n"
          "#else\n"
          "      float ao = fxPixelDepth > 0.0 ? fxJointUpsample(@occlusion, true, @occlusion, 1, "
          "textureSize(@occlusion, 0), @step, ivec2(texCoord * vec2(@fullSize)), fxPixelDepth, " +
          sigma + plane + ", vec4(1.0)).r : 1.0;\n"
          "#endif\n"
        : "      float ao = texture(@occlusion, texCoord * @scale + @offset).r;\n";
      return "    if (@written != 0)\n"
             "    {\n" +
        read + "      ambientVisibility *= clamp(isnan(ao) ? 1.0 : ao, 0.0, 1.0);\n"
               "    }";
    }
    default:
      return std::string();
  }
}

vtkFXEffectPass::Output vtkFXSSAOPass::CompositeSource()
{
  Output source = this->GetInput("denoised");
  return source.Texture ? source : this->GetOutput("occlusion");
}

bool vtkFXSSAOPass::UpsamplesByDepth(const Output& source) const
{
  // (plain values with their depth after them, read in the composite where
  // depth exists: one value, or directional occlusion's three once blurred)
  return this->DepthAwareUpsample && source.Texture && source.Step > 1 &&
    source.Packing == 0 && source.DepthComponent == source.Components && this->GBuffer &&
    this->GBuffer->GetChannelTexture(vtkFXGBufferPass::LinearDepth);
}

void vtkFXSSAOPass::BindCompositeResources(vtkShaderProgram* program, const std::string& prefix)
{
  Output source = this->CompositeSource();
  // Nothing written (the pass did not run, say in another stage): the
  // composite's code reads no occlusion rather than whatever unit 0 holds.
  const std::string written = prefix + "written";
  if (program->IsUniformUsed(written.c_str()))
  {
    program->SetUniformi(written.c_str(), source.Texture ? 1 : 0);
  }
  if (!source.Texture)
  {
    return;
  }
  source.Texture->Activate();
  this->BoundInComposite = source.Texture;
  program->SetUniformi((prefix + "occlusion").c_str(), source.Texture->GetTextureUnit());
  this->SetReadUniforms(program, prefix + "scale", prefix + "offset", source);
  vtkTextureObject* reference = this->GBuffer ? this->GBuffer->GetDepthTexture() : nullptr;
  const std::string fullSize = prefix + "fullSize", step = prefix + "step";
  if (reference && program->IsUniformUsed(fullSize.c_str()))
  {
    const int size[2] = { static_cast<int>(reference->GetWidth()),
      static_cast<int>(reference->GetHeight()) };
    program->SetUniform2i(fullSize.c_str(), size);
  }
  if (program->IsUniformUsed(step.c_str()))
  {
    program->SetUniformi(step.c_str(), std::max(1, source.Step));
  }
}

void vtkFXSSAOPass::SetReadUniforms(vtkShaderProgram* program, const std::string& scaleName,
  const std::string& offsetName, const Output& source)
{
  vtkTextureObject* reference = this->GBuffer ? this->GBuffer->GetDepthTexture() : nullptr;
  if (!source.Texture || !reference)
  {
    return;
  }
  const int full[2] = { static_cast<int>(reference->GetWidth()),
    static_cast<int>(reference->GetHeight()) };
  const int low[2] = { std::max(1, static_cast<int>(source.Texture->GetWidth())),
    std::max(1, static_cast<int>(source.Texture->GetHeight())) };
  // (as the step uniform: an input that reports no step is at full resolution)
  const int step = std::max(1, source.Step);
  float scale[2], offset[2];
  for (int i = 0; i < 2; ++i)
  {
    scale[i] = static_cast<float>(static_cast<double>(full[i]) / (step * low[i]));
    offset[i] = static_cast<float>((0.5 - 0.5 / step) / low[i]);
  }
  program->SetUniform2f(scaleName.c_str(), scale);
  program->SetUniform2f(offsetName.c_str(), offset);
}

void vtkFXSSAOPass::UnbindCompositeResources()
{
  if (this->BoundInComposite)
  {
    this->BoundInComposite->Deactivate();
    this->BoundInComposite = nullptr;
  }
}

int vtkFXSSAOPass::GetHorizonSteps() const
{
  return std::max(1, this->NumberOfSamples / (2 * HorizonSlices));
}

int vtkFXSSAOPass::GetEffectiveNumberOfSamples() const
{
  if (this->GetEffectiveMethod() == Horizon)
  {
    return 2 * HorizonSlices * this->GetHorizonSteps();
  }
  if (this->Channels != 3)
  {
    return this->NumberOfSamples;
  }
  // A multiple of 3 (see SetHemisphereKernel), at most 63.
  return std::min(63, 3 * ((this->NumberOfSamples + 2) / 3));
}

int vtkFXSSAOPass::GetEffectiveMethod() const
{
  return this->Method;
}

int vtkFXSSAOPass::GetOcclusionFormat() const
{
  // The values and the blur's guide depth after them, 32-bit: a 16-bit
  // float overflows at 65504 world units.
  return this->Channels == 3 ? vtkFXRenderUtilities::RGBA32F : vtkFXRenderUtilities::RG32F;
}

double vtkFXSSAOPass::ComputeRadius(vtkRenderer* ren) const
{
  // Within what a float holds with room to square and divide (a radius
  // that rounds to 0 or inf in the shaders would make NaN).
  const auto representable = [](double r) { return std::min(std::max(r, 1e-30), 1e30); };
  if (this->Radius > 0.0)
  {
    return representable(this->Radius);
  }
  double bounds[6];
  vtkFXRenderUtilities::ComputeVisiblePropBounds(ren, bounds);
  if (!vtkMath::AreBoundsInitialized(bounds))
  {
    return 1.0;
  }
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  return diagonal > 0.0 ? representable(this->RadiusFraction * diagonal) : 1.0;
}

void vtkFXSSAOPass::SetHemisphereKernel(vtkShaderProgram* program) const
{
  // Vizerie's (2009) distribution: cosine-weighted directions (z = sqrt(r2))
  // and lengths u^3 (CubeRoot falloff), or 1 (Binary: every sample at R). Azimuths are stratified over [0, 2 pi); r2 and u follow
  // radical-inverse sequences (bases 2 and 3).
  // (A kernel of triples turned by 120 degrees would balance the three
  // directional channels exactly, but with a third of the elevations it
  // measured less accurate: worst channel band 0.035 against 0.019 in
  // TestDirectionalOcclusion, 0.5 dB lower on scene:bumps.)
  const int n = this->GetEffectiveNumberOfSamples();
  std::vector<float> kernel(4 * n);
  for (int i = 0; i < n; ++i)
  {
    const double r1 = (i + 0.5) / n;
    const double r2 = RadicalInverse(i + 1, 2);
    const double u = RadicalInverse(i + 1, 3);
    const double phi = 2.0 * vtkMath::Pi() * r1;
    kernel[4 * i + 0] = static_cast<float>(std::cos(phi) * std::sqrt(1.0 - r2));
    kernel[4 * i + 1] = static_cast<float>(std::sin(phi) * std::sqrt(1.0 - r2));
    kernel[4 * i + 2] = static_cast<float>(std::sqrt(r2));
    kernel[4 * i + 3] = static_cast<float>(this->Falloff == CubeRoot ? u * u * u : 1.0);
  }
  program->SetUniform4fv("fxKernel", n, reinterpret_cast<const float(*)[4]>(kernel.data()));
}

bool vtkFXSSAOPass::UsesThinOccluders() const
{
  return this->OccluderThickness < HeightField && this->GetEffectiveMethod() == Horizon &&
    this->Falloff == Binary && this->Channels == 1;
}

void vtkFXSSAOPass::SetKernelUniforms(vtkShaderProgram* program) const
{
  const int n = this->GetEffectiveNumberOfSamples();
  const bool hemisphere = this->GetEffectiveMethod() == Hemisphere;
  if (hemisphere)
  {
    this->SetHemisphereKernel(program);
  }

  // Tile of rotations within one azimuth stratum (2 pi / n), in the order
  // of an ordered-dither matrix so that neighbours differ most.
  const int entries = this->TileSize * this->TileSize;
  const std::vector<int> order = BayerOrder(this->TileSize);
  std::vector<float> tile(4 * entries);
  for (int i = 0; i < entries; ++i)
  {
    // The entry's place within the stratum, in [0, 1). The hemisphere's
    // rotation covers a stratum of the whole turn; the horizon method's
    // slices cover half a turn (each looks both ways) and take a step
    // offset from the low bits of the rank (see fxHorizonOcclusion).
    const double jitter = (order[i] + 0.5) / entries;
    const double angle = hemisphere ? 2.0 * vtkMath::Pi() / n * jitter
                                    : vtkMath::Pi() * jitter / HorizonSlices;
    tile[4 * i + 0] = static_cast<float>(std::cos(angle));
    tile[4 * i + 1] = static_cast<float>(std::sin(angle));
    tile[4 * i + 2] = static_cast<float>(jitter * 4.0 - std::floor(jitter * 4.0));
    tile[4 * i + 3] = 0.0f;
  }
  program->SetUniform4fv("fxTile", entries, reinterpret_cast<const float(*)[4]>(tile.data()));
}

void vtkFXSSAOPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  this->SkippedSurfaces = nullptr;
  vtkRenderer* ren = s->GetRenderer();
  vtkTextureObject* depth = this->GBuffer ? this->GBuffer->GetChannelTexture(GB::LinearDepth) : nullptr;
  vtkTextureObject* normal = this->GBuffer ? this->GBuffer->GetGeometricNormalTexture() : nullptr;
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!depth || !normal)
  {
    // (used alone, without vtkFXPipelinePass's scheduling) No output rather
    // than last frame's, which the composite would read at another size or
    // from another view.
    if (!this->WarnedNoChannels)
    {
      vtkErrorMacro("vtkFXSSAOPass needs a G-buffer with normal and linear depth channels; "
                    "no occlusion.");
      this->WarnedNoChannels = true;
    }
    vtkFXRenderUtilities::Release(this->Occlusion, window);
    return;
  }
  this->WarnedNoChannels = false;
  this->WarnIfDrawnInTiles(ren, "the occlusion cannot see occluders");
  const int fullWidth = static_cast<int>(depth->GetWidth());
  const int fullHeight = static_cast<int>(depth->GetHeight());
  const int step = this->HalfResolution ? 2 : 1;
  vtkFXRenderUtilities::EnsureTexture(this->Occlusion, window, (fullWidth + step - 1) / step,
    (fullHeight + step - 1) / step, this->GetOcclusionFormat());
  this->Occlusion->SetMinificationFilter(vtkTextureObject::Linear);
  this->Occlusion->SetMagnificationFilter(vtkTextureObject::Linear);

  vtkFXRenderUtilities::CodeStream defines;
  defines << "//VTK::System::Dec\n#define FX_SAMPLES " << this->GetEffectiveNumberOfSamples()
          << "\n#define FX_METHOD " << this->GetEffectiveMethod()
          << "\n#define FX_CHANNELS " << this->Channels << "\n#define FX_TILE " << this->TileSize
          << "\n#define FX_FALLOFF " << this->Falloff
          << "\n#define FX_SLICES " << HorizonSlices
          << "\n#define FX_STEPS " << this->GetHorizonSteps()
          << "\n#define FX_THIN " << (this->UsesThinOccluders() ? 1 : 0) << "\n"
          << this->GetExtensionDefines(ren);
  std::string fs = vtkFXSSAOFS;
  vtkShaderProgram::Substitute(fs, "//VTK::System::Dec", defines.str(), false);
  vtkShaderProgram::Substitute(fs, "//VTK::FXNormalCoding::Dec", vtkFXNormalCoding, false);
  vtkShaderProgram::Substitute(fs, "//VTK::FXViewPosition::Dec", vtkFXViewPosition, false);
  vtkShaderProgram::Substitute(fs, "//VTK::FXOcclusionBasis::Dec",
    this->Channels == 3 ? vtkFXOcclusionBasis : "", false);
  vtkShaderProgram::Substitute(fs, "//VTK::FXExtension::Dec", this->GetExtensionCode(ren), false);

  std::vector<vtkTextureObject*> targets = { this->Occlusion };
  this->AddExtensionTargets(ren, static_cast<int>(this->Occlusion->GetWidth()),
    static_cast<int>(this->Occlusion->GetHeight()), targets);
  // The pixels without a surface are left out before the shader runs (a
  // software rasteriser skips their 4x4 blocks; 16% of the pass at
  // 1280x720 on the bunny): at full resolution by the G-buffer's depth, at
  // half by a mask of this resolution. They keep the open value the shader
  // would write. (With a second target, bleeding, every pixel runs: its
  // background value is not the clear's.)
  vtkTextureObject* surfaces = nullptr;
  if (this->SkipBackground && targets.size() == 1)
  {
    if (step == 1)
    {
      surfaces = this->GBuffer->GetDepthTexture();
    }
    else
    {
      // (a mask that failed, say for memory at a huge size, is tried again
      // at another size only: it would fail and warn every frame)
      const int size[2] = { static_cast<int>(this->Occlusion->GetWidth()),
        static_cast<int>(this->Occlusion->GetHeight()) };
      if (size[0] != this->SurfaceMaskFailedSize[0] || size[1] != this->SurfaceMaskFailedSize[1])
      {
        const bool made = this->MakeSurfaceMask(window, depth, step);
        this->SurfaceMaskFailedSize[0] = made ? 0 : size[0];
        this->SurfaceMaskFailedSize[1] = made ? 0 : size[1];
        if (!made)
        {
          vtkWarningMacro("vtkFXSSAOPass could not make its " << size[0] << " x " << size[1]
                                                              << " surface mask; every pixel "
                                                                 "runs the estimator.");
        }
        surfaces = made ? this->SurfaceMask.Texture.Get() : nullptr;
      }
    }
  }
  if (!surfaces || step == 1)
  {
    vtkFXRenderUtilities::ReleaseDepthMask(this->SurfaceMask, window);
  }
  vtkFXRenderUtilities::RenderTargetScope target(window, this->FrameBuffer, targets);
  if (!target.IsComplete())
  {
    // (say, no memory for the occlusion texture) No output: the composite
    // then reads no occlusion, rather than an empty texture's zeros.
    if (!this->WarnedIncomplete)
    {
      vtkErrorMacro("The occlusion texture of " << this->Occlusion->GetWidth() << " x "
                                                << this->Occlusion->GetHeight()
                                                << " texels could not be made; no occlusion.");
      this->WarnedIncomplete = true;
    }
    vtkFXRenderUtilities::Release(this->Occlusion, window);
    return;
  }
  this->Quad.AtFarPlane = surfaces != nullptr;
  vtkShaderProgram* program =
    vtkFXRenderUtilities::ReadyQuad(this->Quad, window, fs);
  if (!program || surfaces)
  {
    // Open (what the shader writes where there is no surface), so that the
    // composite shows no occlusion rather than old texels where the shader
    // does not run.
    float open[4];
    this->GetOpenValue(open);
    vtkFXRenderUtilities::ClearTargets(static_cast<int>(targets.size()), open);
  }
  if (!program)
  {
    return;
  }
  this->SkippedSurfaces = target.SkipWhereDepthIsOne(surfaces) ? surfaces : nullptr;
  depth->Activate();
  normal->Activate();
  program->SetUniformi("fxLinearDepth", depth->GetTextureUnit());
  program->SetUniformi("fxNormal", normal->GetTextureUnit());
  const int size[2] = { fullWidth, fullHeight };
  program->SetUniform2i("fxGBufferSize", size);
  program->SetUniformi("fxStep", step);
  vtkFXRenderUtilities::SetFrustumRayUniforms(program, ren);
  // vtkShaderProgram hands a matrix's row-major elements to GLSL, which reads
  // them column by column: upload the transpose so that GLSL sees P.
  vtkNew<vtkMatrix4x4> projection;
  projection->DeepCopy(
    ren->GetActiveCamera()->GetProjectionTransformMatrix(ren->GetTiledAspectRatio(), -1, 1));
  projection->Transpose();
  program->SetUniformMatrix("fxProjection", projection);
  this->EffectiveRadius = this->ComputeRadius(ren);
  program->SetUniformf("fxRadius", static_cast<float>(this->EffectiveRadius));
  program->SetUniformf("fxBias", static_cast<float>(this->Bias * this->EffectiveRadius));
  if (this->UsesThinOccluders())
  {
    program->SetUniformf("fxThickness", static_cast<float>(this->OccluderThickness));
  }
  this->SetKernelUniforms(program);
  this->BindExtensionInputs(program, ren);
  this->Quad.Helper->Render();
  this->UnbindExtensionInputs();
  depth->Deactivate();
  normal->Deactivate();
}

bool vtkFXSSAOPass::MakeSurfaceMask(
  vtkOpenGLRenderWindow* window, vtkTextureObject* depth, int step)
{
  const int size[2] = { static_cast<int>(this->Occlusion->GetWidth()),
    static_cast<int>(this->Occlusion->GetHeight()) };
  const int full[2] = { static_cast<int>(depth->GetWidth()), static_cast<int>(depth->GetHeight()) };
  depth->Activate();
  const bool made = vtkFXRenderUtilities::DrawDepthMask(window, this->SurfaceMask, size[0],
    size[1], vtkFXSurfaceMaskFS,
    [&](vtkShaderProgram* program) {
      program->SetUniformi("fxLinearDepth", depth->GetTextureUnit());
      program->SetUniform2i("fxGBufferSize", full);
      program->SetUniformi("fxStep", step);
    });
  depth->Deactivate();
  return made;
}

void vtkFXSSAOPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->SkippedSurfaces = nullptr; // (the mask goes)
  // (another context may draw it)
  this->SurfaceMaskFailedSize[0] = this->SurfaceMaskFailedSize[1] = 0;
  vtkFXRenderUtilities::ReleaseDepthMask(this->SurfaceMask, w);
  vtkFXRenderUtilities::ReleaseQuad(this->Quad, w);
  this->UnbindCompositeResources();
  vtkFXRenderUtilities::Release(this->Occlusion, w);
  vtkFXRenderUtilities::Release(this->FrameBuffer, w);
}

void vtkFXSSAOPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Radius: " << this->Radius << " (effective " << this->EffectiveRadius << ")\n";
  os << indent << "SkipBackground: " << this->SkipBackground << "\n";
  os << indent << "DepthAwareUpsample: " << this->DepthAwareUpsample << "\n";
  os << indent << "RadiusFraction: " << this->RadiusFraction << "\n";
  os << indent << "NumberOfSamples: " << this->NumberOfSamples << "\n";
  os << indent << "Method: " << (this->Method == Hemisphere ? "Hemisphere" : "Horizon") << "\n";
  os << indent << "Falloff: " << (this->Falloff == Binary ? "Binary" : "CubeRoot") << "\n";
  os << indent << "Bias: " << this->Bias << "\n";
  os << indent << "OccluderThickness: " << this->OccluderThickness << "\n";
  os << indent << "HalfResolution: " << this->HalfResolution << "\n";
}
