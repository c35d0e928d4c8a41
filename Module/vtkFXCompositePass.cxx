#include "vtkFXCompositePass.h"

#include "vtkFXCompositeDepthFS.h"
#include "vtkFXCompositeFS.h"
#include "vtkFXEffectPass.h"
#include "vtkFXLightingFS.h"
#include "vtkFXGBufferPass.h"
#include "vtkFXNormalCoding.h"
#include "vtkFXViewPosition.h"
#include "vtkFXRenderUtilities.h"

#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkTransform.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkRenderState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkFXOpenGL.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

vtkStandardNewMacro(vtkFXCompositePass);

namespace
{
using GB = vtkFXGBufferPass;

// Texels per light in the light texture, and the layout both sides share.
constexpr int LightTexels = 4;
static_assert(LightTexels == vtkFXLightTiles::EntryTexels, "tile entries copy whole rows");

// Wraps one light's call so that the effects' per-light visibility code can
// scale what this light contributes; without such code, the call adds
// straight into diffuseLight and specularLight as VTK's shaders do.
std::string LightTerm(const std::string& call, const std::string& index,
  const std::string& visibilityCode)
{
  if (visibilityCode.empty())
  {
    return "    " + call + "diffuseLight, specularLight);\n";
  }
  return "    {\n      vec3 lightDiffuse = vec3(0.0);\n      vec3 lightSpecular = vec3(0.0);\n      " +
    call + "lightDiffuse, lightSpecular);\n      float lightVisibility = 1.0;\n      int lightIndex = " +
    index + ";\n" + visibilityCode +
    "\n      diffuseLight += lightVisibility * lightDiffuse;\n"
    "      specularLight += lightVisibility * lightSpecular;\n    }\n";
}

// Calls of vtkFXLightingFS.glsl's functions, one per light that is on, with
// VTK's per-light uniform names (vtkOpenGLRenderer::GetLightingUniforms).
std::string UniformLightCalls(int complexity, int lightCount, const std::string& visibilityCode)
{
  vtkFXRenderUtilities::CodeStream s;
  for (int i = 0; i < lightCount && complexity > 0; ++i)
  {
    const std::string n = std::to_string(i);
    switch (complexity)
    {
      case 1: // a headlight is the only light by definition
        return LightTerm("fxHeadlight(n, lightColor0, specularPower, ", "0", visibilityCode);
      case 2:
        s << LightTerm("fxDirectionalLight(n, view, lightDirectionVC" + n + ", lightColor" + n +
            ", specularPower, ",
          n, visibilityCode);
        break;
      default:
        s << LightTerm("fxPositionalLight(n, position, view, lightPositional" + n +
            ", lightDirectionVC" + n + ", lightPositionVC" + n + ", lightAttenuation" + n +
            ", lightConeAngle" + n + ", lightExponent" + n + ", lightColor" + n +
            ", specularPower, ",
          n, visibilityCode);
        break;
    }
  }
  return s.str();
}

// The light texture's rows (UploadLightTexture) are sorted by kind:
// directional lights, then positional lights without a cone ("point"),
// then spot lights; fxFirstPoint and fxFirstSpot mark where each kind
// starts. Each kind has a loop of its own whose call passes that kind's
// constants (positional or not, no cone), so the compiler drops the other
// kinds' branches: a software rasteriser runs both sides of every if, and
// a point light used to pay for the spot cone's cosine and power (1024
// point lights at 1280x720 on llvmpipe: 83-89 ms to 77). `fetches` lists
// the texels a kind reads; the light's row in VTK's order (for the
// effects' per-light code) is read only when such code exists.
// A light's texels come from `sampler` at texel `at` + (k, 0) for texel k.
std::string LightLoopBody(const std::string& call, const std::string& fetches,
  const std::string& visibilityCode, const std::string& sampler, const std::string& at)
{
  std::string body;
  std::string wanted = fetches + (visibilityCode.empty() ? "" : "3");
  for (char texel = '0'; texel <= '3'; ++texel)
  {
    if (wanted.find(texel) != std::string::npos)
    {
      body += std::string("      vec4 light") + texel + " = texelFetch(" + sampler + ", " + at +
        " + ivec2(" + texel + ", 0), 0);\n";
    }
  }
  return body + LightTerm(call, "int(light3.z)", visibilityCode) + "    }\n";
}

// Loops over the light texture: directional lights over every pixel;
// positional ones over all of them or, with tiles, over this pixel's tile
// (vtkFXLightTiles: per tile the first entry and the counts of point and
// spot lights; each entry a copy of its light's row, or, with
// `entriesAreRows` false, the row's index in the light texture;
// `entriesPerRow` to a row of the entries' texture).
std::string TextureLightLoop(int complexity, const std::string& visibilityCode, bool tiled,
  bool entriesAreRows, int entriesPerRow)
{
  const std::string attenuation = "vec3(light0.w, light1.w, light2.w)";
  std::string code;
  code += "    for (int i = 0; i < fxFirstPoint; ++i)\n    {\n";
  code += complexity == 2
    ? LightLoopBody("fxDirectionalLight(n, view, light2.xyz, light0.rgb, specularPower, ", "02",
        visibilityCode, "fxLights", "ivec2(0, i)")
    : LightLoopBody("fxPositionalLight(n, position, view, 0, light2.xyz, vec3(0.0), vec3(1.0, 0.0, "
                    "0.0), 180.0, 1.0, light0.rgb, specularPower, ",
        "02", visibilityCode, "fxLights", "ivec2(0, i)");
  if (complexity < 3)
  {
    return code; // (directional lights only)
  }
  const std::string point = "fxPositionalLight(n, position, view, 1, light2.xyz, light1.xyz, " +
    attenuation + ", 180.0, 1.0, light0.rgb, specularPower, ";
  const std::string spot = "fxPositionalLight(n, position, view, 1, light2.xyz, light1.xyz, " +
    attenuation + ", light3.x, light3.y, light0.rgb, specularPower, ";
  if (!tiled)
  {
    code += "    for (int i = fxFirstPoint; i < fxFirstSpot; ++i)\n    {\n" +
      LightLoopBody(point, "012", visibilityCode, "fxLights", "ivec2(0, i)");
    code += "    for (int i = fxFirstSpot; i < fxLightCount; ++i)\n    {\n" +
      LightLoopBody(spot, "0123", visibilityCode, "fxLights", "ivec2(0, i)");
    return code;
  }
  const std::string perRow = std::to_string(entriesPerRow);
  const std::string entry = entriesAreRows
    ? "      ivec2 fxAt = ivec2(" + std::to_string(vtkFXLightTiles::EntryTexels) + " * (entry % " +
      perRow + "), entry / " + perRow + ");\n"
    : "      int i = int(texelFetch(fxLightTileEntries, ivec2(entry % " + perRow + ", entry / " +
      perRow + "), 0).r);\n      ivec2 fxAt = ivec2(0, i);\n";
  const std::string source = entriesAreRows ? "fxLightTileEntries" : "fxLights";
  code += "    ivec2 fxTile = ivec2(texCoord * vec2(textureSize(fxAlbedo, 0))) / " +
    std::to_string(vtkFXLightTiles::TileSize) +
    ";\n"
    "    vec4 fxTileList = texelFetch(fxLightTileHeaders, fxTile, 0);\n"
    "    int fxPointsEnd = int(fxTileList.r) + int(fxTileList.g);\n"
    "    int fxSpotsEnd = fxPointsEnd + int(fxTileList.b);\n";
  code += "    for (int entry = int(fxTileList.r); entry < fxPointsEnd; ++entry)\n    {\n" + entry +
    LightLoopBody(point, "012", visibilityCode, source, "fxAt");
  code += "    for (int entry = fxPointsEnd; entry < fxSpotsEnd; ++entry)\n    {\n" + entry +
    LightLoopBody(spot, "0123", visibilityCode, source, "fxAt");
  return code;
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

// The prefix that stands for '@' in the code of contributor `i`.
std::string ContributorPrefix(size_t i)
{
  return "fxE" + std::to_string(i) + "_";
}
}

vtkFXCompositePass::vtkFXCompositePass() = default;

vtkFXCompositePass::~vtkFXCompositePass()
{
  this->SetGBuffer(nullptr);
}

vtkCxxSetObjectMacro(vtkFXCompositePass, GBuffer, vtkFXGBufferPass);

void vtkFXCompositePass::RemoveAllContributors()
{
  this->Contributors.clear();
}

void vtkFXCompositePass::AddContributor(vtkFXEffectPass* effect)
{
  if (effect)
  {
    this->Contributors.emplace_back(effect);
  }
}

int vtkFXCompositePass::GetNumberOfContributors() const
{
  return static_cast<int>(this->Contributors.size());
}

std::string vtkFXCompositePass::EffectCode(int hook) const
{
  std::string code;
  for (size_t i = 0; i < this->Contributors.size(); ++i)
  {
    std::string part = this->Contributors[i]->GetCompositeCode(hook);
    if (!part.empty())
    {
      vtkShaderProgram::Substitute(part, "@", ContributorPrefix(i), true);
      code += part + "\n";
    }
  }
  return code;
}

bool vtkFXCompositePass::UsesLightTexture(vtkOpenGLRenderer* ren) const
{
  return this->LightingComplexity(ren) >= 2 && ren->GetLightingCount() > this->MaximumUniformLights;
}

int vtkFXCompositePass::LightingComplexity(vtkOpenGLRenderer* ren) const
{
  // (no normals: nothing to light)
  return (ren->GetLightingCount() == 0 || !this->GBuffer->GetChannelTexture(GB::Normal))
    ? 0
    : ren->GetLightingComplexity();
}

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
    if (this->UseEmission)
    {
      mask |= GB::ChannelBit(GB::Emission);
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
  const int complexity = this->LightingComplexity(ren);
  const bool hasDepth = gb->GetChannelTexture(GB::LinearDepth) != nullptr;
  bool hasSpecular = gb->GetChannelTexture(GB::Specular) != nullptr && complexity > 0;
  if (complexity >= 2 && hasSpecular && !hasDepth)
  {
    if (!this->WarnedSpecularWithoutDepth)
    {
      vtkWarningMacro("Specular highlights need the G-buffer's linear depth "
                      "(see GetRequiredChannels); they are left out.");
      this->WarnedSpecularWithoutDepth = true;
    }
    hasSpecular = false;
  }
  if (complexity == 3 && !hasDepth)
  {
    return std::string(); // Render() reports it
  }
  std::string hooks[vtkFXEffectPass::NumberOfCompositeHooks];
  bool anyHook = false;
  for (int h = 0; h < vtkFXEffectPass::NumberOfCompositeHooks; ++h)
  {
    hooks[h] = this->EffectCode(h);
    anyHook = anyHook || !hooks[h].empty();
  }
  // Effects' code may use the view-space position wherever depth exists.
  const bool needsPosition =
    complexity == 3 || (complexity == 2 && hasSpecular) || (anyHook && hasDepth);
  const bool lightTexture = this->UsesLightTexture(ren);
  const bool hasEmission = this->UseEmission && gb->GetChannelTexture(GB::Emission) != nullptr;

  vtkFXRenderUtilities::CodeStream defines;
  // (FX_GATHER: for the effects' code, e.g. vtkFXSSAOPass's upsample)
  defines << vtkFXRenderUtilities::GatherDefines(true)
          << "#define FX_LIGHTING " << complexity << "\n"
          << "#define FX_LIGHT_TEXTURE " << (lightTexture ? 1 : 0) << "\n"
          << "#define FX_LIGHT_TILES " << (lightTexture && this->LightCutoff > 0.0 ? 1 : 0) << "\n"
          << "#define FX_HAS_SPECULAR " << (hasSpecular ? 1 : 0) << "\n"
          << "#define FX_HAS_AMBIENT " << (gb->GetChannelTexture(GB::Ambient) ? 1 : 0) << "\n"
          << "#define FX_HAS_EMISSION " << (hasEmission ? 1 : 0) << "\n"
          << "#define FX_NEEDS_POSITION " << (needsPosition ? 1 : 0) << "\n"
          << "#define FX_WRITES_DEPTH " << (this->UsedDepthPrepass ? 0 : 1) << "\n"
          << "#define FX_CHANNEL_NORMAL " << GB::Normal << "\n"
          << "#define FX_CHANNEL_DEPTH " << GB::LinearDepth << "\n"
          << "#define FX_CHANNEL_GEOMETRIC_NORMAL " << GB::GeometricNormal << "\n"
          << "#define FX_DEBUG_OCCLUSION " << (this->DebugOcclusion ? 1 : 0) << "\n"
          << "#define FX_DEBUG_CHANNEL "
          << (gb->GetChannelTexture(this->DebugChannel) ? this->DebugChannel : -1) << "\n";

  const std::string& visibility = hooks[vtkFXEffectPass::LightVisibility];
  std::string fs = vtkFXCompositeFS;
  vtkShaderProgram::Substitute(fs, "//VTK::System::Dec", defines.str(), false);
  vtkShaderProgram::Substitute(fs, "//VTK::FXNormalCoding::Dec", vtkFXNormalCoding, false);
  vtkShaderProgram::Substitute(fs, "//VTK::FXViewPosition::Dec", vtkFXViewPosition, false);
  vtkShaderProgram::Substitute(fs, "//VTK::FXLighting::Dec", vtkFXLightingFS, false);
  vtkShaderProgram::Substitute(fs, "//VTK::Light::Dec",
    complexity > 0 && !lightTexture ? ren->GetLightingUniforms() : "", false);
  vtkShaderProgram::Substitute(fs, "//VTK::FXLight::Impl",
    lightTexture ? TextureLightLoop(complexity, visibility, this->LightCutoff > 0.0,
                     !this->LightTilesUsed || this->LightTiles->GetEntriesAreRows(),
                     this->LightTilesUsed ? this->LightTiles->GetEntriesPerRow() : 1)
                 : UniformLightCalls(complexity, lightCount, visibility),
    false);
  vtkShaderProgram::Substitute(
    fs, "//VTK::FXEffects::Dec", hooks[vtkFXEffectPass::Declarations], false);
  vtkShaderProgram::Substitute(
    fs, "//VTK::FXEffects::Ambient", hooks[vtkFXEffectPass::Ambient], false);
  vtkShaderProgram::Substitute(fs, "//VTK::FXEffects::Color", hooks[vtkFXEffectPass::Color], false);
  vtkShaderProgram::Substitute(
    fs, "//VTK::FXEffects::DiffuseResponse", hooks[vtkFXEffectPass::DiffuseResponse], false);
  return fs;
}

std::string vtkFXCompositePass::GetUniformLightCalls(int complexity, int lightCount)
{
  return UniformLightCalls(complexity, lightCount, std::string());
}

int vtkFXCompositePass::UploadLightTexture(vtkOpenGLRenderer* ren)
{
  // VTK's own light parameters (vtkOpenGLRenderer::UpdateLightingUniforms),
  // one row of 4 texels per light: colour x intensity and attenuation a0;
  // position in view space and a1; direction in view space and a2; cone
  // angle, exponent and the light's place among the lights that are on.
  // Rows sorted by kind (see TextureLightLoop): directional, point, spot.
  vtkTransform* view = ren->GetActiveCamera()->GetModelViewTransformObject();
  struct Row
  {
    int Kind; // 0 directional, 1 point, 2 spot
    vtkFXLightTiles::Light Light; // its sphere, and its row's texels (Light.Row)
  };
  std::vector<Row> rows;
  // A diffuse response that raises small factors (toon bands) makes a
  // light count wherever its factor reaches the smallest raised one.
  double raised = 0.0;
  for (const auto& contributor : this->Contributors)
  {
    const double smallest = contributor->GetSmallestRaisedDiffuse();
    raised = smallest > 0.0 && (raised == 0.0 || smallest < raised) ? smallest : raised;
  }
  vtkLightCollection* lights = ren->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  int place = -1; // among the lights that are on
  while (vtkLight* light = lights->GetNextLight(it))
  {
    if (light->GetSwitch() <= 0)
    {
      continue;
    }
    ++place;
    if (!vtkFXRenderUtilities::IsLightFinite(light))
    {
      continue; // left out (vtkFXPipelinePass says so)
    }
    double direction[3], directionVC[3], positionVC[3];
    vtkMath::Subtract(light->GetTransformedFocalPoint(), light->GetTransformedPosition(), direction);
    vtkMath::Normalize(direction);
    view->TransformNormal(direction, directionVC);
    view->TransformPoint(light->GetTransformedPosition(), positionVC);
    if (vtkTransform* user = vtkFXRenderUtilities::GetUserLightTransform(ren, light))
    {
      user->TransformNormal(directionVC, directionVC);
      user->TransformPoint(positionVC, positionVC);
    }
    const double* color = light->GetDiffuseColor();
    const double intensity = light->GetIntensity();
    const double* attenuation = light->GetAttenuationValues();
    Row r;
    // (VTK 9.1's shader: a cone below 90 degrees only)
    r.Kind = !light->GetPositional() ? 0 : light->GetConeAngle() < 90.0 ? 2 : 1;
    const double values[LightTexels * 4] = { color[0] * intensity, color[1] * intensity,
      color[2] * intensity, attenuation[0], positionVC[0], positionVC[1], positionVC[2],
      attenuation[1], directionVC[0], directionVC[1], directionVC[2], attenuation[2],
      light->GetConeAngle(), light->GetExponent(), static_cast<double>(place), 0.0 };
    std::copy(values, values + LightTexels * 4, r.Light.Row);
    // (VTK takes a negative intensity or colour as light taken away, as
    // visible as light added)
    const double brightest = this->MaterialColorScale * std::fabs(intensity) *
      std::max(std::fabs(color[0]), std::max(std::fabs(color[1]), std::fabs(color[2])));
    double range = std::numeric_limits<double>::infinity();
    if (light->GetPositional())
    {
      range = vtkFXLightTiles::Range(brightest, attenuation, this->LightCutoff);
      if (raised > 0.0)
      {
        // (Range(1, a, 2 f) is where 1 / attenuation falls to f)
        range = std::max(range, vtkFXLightTiles::Range(1.0, attenuation, 2.0 * raised));
      }
    }
    std::copy(positionVC, positionVC + 3, r.Light.Center);
    r.Light.Radius = range;
    rows.push_back(r);
  }
  std::stable_sort(
    rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.Kind < b.Kind; });
  for (int kind : { 1, 2 })
  {
    this->FirstLightOfKind[kind - 1] = static_cast<int>(std::partition_point(rows.begin(),
      rows.end(), [kind](const Row& r) { return r.Kind < kind; }) - rows.begin());
  }
  std::vector<float> texels;
  std::vector<vtkFXLightTiles::Light> spheres; // the positional lights, for the tiles
  for (const Row& r : rows)
  {
    texels.insert(texels.end(), r.Light.Row, r.Light.Row + LightTexels * 4);
    if (r.Kind > 0)
    {
      spheres.push_back(r.Light);
    }
  }
  int count = static_cast<int>(texels.size() / (LightTexels * 4));
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  // One row per light: no more lights than the texture can have rows.
  GLint maxRows = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxRows);
  if (maxRows > 0 && count > maxRows)
  {
    if (!this->ReportedTooManyLights)
    {
      vtkErrorMacro(<< count << " lights are on; this OpenGL's textures hold " << maxRows
                    << " rows, one per light: the last spot lights (or point lights, or "
                       "directional ones: the texture is sorted so) are left out.");
      this->ReportedTooManyLights = true;
    }
    count = maxRows;
    texels.resize(static_cast<size_t>(count) * LightTexels * 4);
    for (int& first : this->FirstLightOfKind)
    {
      first = std::min(first, count);
    }
    spheres.resize(static_cast<size_t>(count - this->FirstLightOfKind[0]));
  }
  vtkFXRenderUtilities::EnsureTexture(
    this->LightTexture, window, LightTexels, std::max(count, 1), vtkFXRenderUtilities::RGBA32F);
  // Its own texture unit first: binding on whatever unit is active would
  // replace a texture another sampler reads.
  this->LightTexture->Activate();
  if (count > 0)
  {
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, LightTexels, count, GL_RGBA, GL_FLOAT, texels.data());
  }
  this->LightTilesUsed = this->LightCutoff > 0.0;
  if (this->LightTilesUsed)
  {
    this->BuildLightTiles(ren, spheres);
  }
  else if (this->LightTiles)
  {
    this->LightTiles->ReleaseGraphicsResources(ren->GetRenderWindow());
  }
  return count;
}

void vtkFXCompositePass::BuildLightTiles(
  vtkOpenGLRenderer* ren, const std::vector<vtkFXLightTiles::Light>& lights)
{
  vtkTextureObject* albedo = this->GBuffer->GetChannelTexture(GB::Albedo);
  vtkMatrix4x4* projection =
    ren->GetActiveCamera()->GetProjectionTransformMatrix(ren->GetTiledAspectRatio(), -1, 1);
  if (!this->LightTiles)
  {
    this->LightTiles.reset(new vtkFXLightTiles);
  }
  // Each tile's surfaces' depths, so that a light counts only for tiles
  // whose surfaces its sphere reaches in depth too (a floor seen at an
  // angle: a sphere's screen rectangle covers much floor nearer and
  // farther than the sphere); not measured when no light's sphere is
  // bounded (VTK's default attenuation), which the bounds could not cull.
  vtkTextureObject* linearDepth = this->GBuffer->GetChannelTexture(GB::LinearDepth);
  const bool bounded = std::any_of(lights.begin(), lights.end(),
    [](const vtkFXLightTiles::Light& light) { return std::isfinite(light.Radius); });
  if (!this->TileDepthBounds || !linearDepth || !bounded ||
    !this->LightTiles->MeasureTileDepths(vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow()),
      linearDepth, static_cast<int>(albedo->GetWidth()), static_cast<int>(albedo->GetHeight())))
  {
    this->LightTiles->ForgetTileDepths();
  }
  // (the range the projection draws, a little wider: the depth buffer's own
  // rounding; without one, or one reaching behind the eye, no depth bound)
  double depthRange[2] = { -1.0, -1.0 };
  if (vtkFXRenderUtilities::ComputeViewDepthRange(ren, depthRange))
  {
    depthRange[0] *= 0.99;
    depthRange[1] *= 1.01;
  }
  // (the lights are the texture's rows from the first point light on; the
  // spot lights follow the point lights)
  const int firstPoint = this->FirstLightOfKind[0];
  this->LightTiles->SetRowEntryBudget(static_cast<size_t>(this->MaximumTileRowEntries));
  GLint maxTextureSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTextureSize);
  if (maxTextureSize > 0)
  {
    this->LightTiles->SetMaximumTextureSize(maxTextureSize);
  }
  if (!this->LightTiles->Build(lights, &projection->Element[0][0],
        static_cast<int>(albedo->GetWidth()), static_cast<int>(albedo->GetHeight()), depthRange,
        static_cast<size_t>(this->FirstLightOfKind[1] - firstPoint), firstPoint) &&
    !this->WarnedLightTiles)
  {
    vtkWarningMacro("The per-tile light lists would exceed "
      << this->LightTiles->GetEntryLimit() << " entries (" << lights.size()
      << " lights over this viewport): every pixel loops over every light instead.");
    this->WarnedLightTiles = true;
  }
  this->LightTiles->Upload(vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow()));
}

double vtkFXCompositePass::GetMeanLightsPerTile() const
{
  // (directional lights reach every tile)
  return this->LightTilesUsed && this->LightTiles
    ? this->FirstLightOfKind[0] + this->LightTiles->GetMeanLightsPerTile()
    : 0.0;
}

void vtkFXCompositePass::SetUniforms(vtkShaderProgram* program, vtkOpenGLRenderer* ren)
{
  vtkFXGBufferPass* gb = this->GBuffer;
  // (the path Render chose: a debug view's program leaves the light
  // texture's uniforms out, and its textures are kept for the next frame
  // all the same, where they were freed and made again every frame)
  if (this->UsesLightTexture(ren))
  {
    if (program->IsUniformUsed("fxLights"))
    {
      // (uploaded by Render, before the shader: its loops follow the tiles)
      BindSampler(program, "fxLights", this->LightTexture);
      program->SetUniformi("fxLightCount", this->UploadedLights);
      program->SetUniformi("fxFirstPoint", this->FirstLightOfKind[0]);
      program->SetUniformi("fxFirstSpot", this->FirstLightOfKind[1]);
      if (this->LightTilesUsed)
      {
        BindSampler(program, "fxLightTileHeaders", this->LightTiles->GetHeaderTexture());
        BindSampler(program, "fxLightTileEntries", this->LightTiles->GetEntryTexture());
      }
    }
  }
  else
  {
    this->LightTilesUsed = false;
    vtkFXRenderUtilities::Release(this->LightTexture, ren->GetRenderWindow());
    if (this->LightTiles)
    {
      this->LightTiles->ReleaseGraphicsResources(ren->GetRenderWindow());
    }
    // VTK's own light uniforms, exactly as its mappers receive them, less
    // the lights with a number that is not finite (left out as on the
    // light-texture path: no light rather than NaN or white).
    ren->UpdateLightingUniforms(program);
    vtkFXRenderUtilities::DarkenNonFiniteLights(ren, program);
  }
  BindSampler(program, "fxHardwareDepth", gb->GetDepthTexture());
  BindSampler(program, "fxAlbedo", gb->GetChannelTexture(GB::Albedo));
  BindSampler(program, "fxNormal", gb->GetChannelTexture(GB::Normal));
  BindSampler(program, "fxSpecular", gb->GetChannelTexture(GB::Specular));
  BindSampler(program, "fxAmbient", gb->GetChannelTexture(GB::Ambient));
  BindSampler(program, "fxEmission", gb->GetChannelTexture(GB::Emission));
  BindSampler(program, "fxLinearDepth", gb->GetChannelTexture(GB::LinearDepth));
  BindSampler(program, "fxDebugTexture", gb->GetChannelTexture(this->DebugChannel));
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
    vtkFXRenderUtilities::ComputeViewDepthRange(ren, range);
    const float r[2] = { static_cast<float>(range[0]), static_cast<float>(range[1]) };
    program->SetUniform2f("fxDepthRange", r);
  }
  for (size_t i = 0; i < this->Contributors.size(); ++i)
  {
    this->Contributors[i]->BindCompositeResources(program, ContributorPrefix(i));
  }
}

void vtkFXCompositePass::Draw(vtkOpenGLRenderer* ren)
{
  vtkOpenGLState* state = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow())->GetState();
  vtkOpenGLState::ScopedglEnableDisable depthTestSaver(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(state);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
  vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(state);
  // Depth-tested like VTK's opaque pass against what the framebuffer holds:
  // the renderer's cleared depth, or, for a layered renderer that preserves
  // the depth buffer, what the layers below drew, which stays in front.
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_LEQUAL);
  state->vtkglDepthMask(GL_TRUE);
  if (this->UsedDepthPrepass)
  {
    this->UsedDepthBlit = this->BlitDepth(ren);
    if (!this->UsedDepthBlit)
    {
      this->DrawDepthPrepass(ren);
    }
    // The framebuffer's depth was the clear value (1) everywhere: below 1
    // now exactly where the pre-pass wrote a surface. The lighting quad,
    // at the far plane, passes there only.
    state->vtkglDepthFunc(GL_GREATER);
    state->vtkglDepthMask(GL_FALSE);
  }
  // Blend like VTK's opaque pass (actors forced opaque with alpha below 1
  // by VTK's own tests are drawn forward, vtkFXGBufferPass::CanCapture; a
  // texture VTK counts as opaque may still cut holes of alpha 0); alpha
  // scaled by the mark while it is asked for (SetMarksTransmittance).
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA,
    this->MarksTransmittance ? GL_CONSTANT_ALPHA : GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  if (!this->MarksTransmittance)
  {
    this->Quad.Helper->Render();
    return;
  }
  float blendColor[4];
  glGetFloatv(GL_BLEND_COLOR, blendColor);
  glBlendColor(0.0f, 0.0f, 0.0f, static_cast<float>(TransmittanceMark));
  this->Quad.Helper->Render();
  glBlendColor(blendColor[0], blendColor[1], blendColor[2], blendColor[3]);
}

namespace
{
// Whether the bound framebuffer's depth buffer keeps every G-buffer depth
// below 1 (a 32-bit float) below 1, where the lighting pass's GL_GREATER
// test finds it: float and 24- or 32-bit fixed-point buffers do; a 16-bit
// one rounds depths within 2^-17 of the far plane up to 1 (a band of
// surface pixels would show the background), and without a depth buffer
// the test passes everywhere (nothing saved).
bool CanHoldDepthBelowOne()
{
  GLint framebuffer = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
  const GLenum attachment = framebuffer ? GL_DEPTH_ATTACHMENT : GL_DEPTH;
  GLint type = GL_NONE, bits = 0, components = GL_NONE;
  glGetFramebufferAttachmentParameteriv(
    GL_DRAW_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
  if (type == GL_NONE)
  {
    return false;
  }
  glGetFramebufferAttachmentParameteriv(
    GL_DRAW_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &bits);
  glGetFramebufferAttachmentParameteriv(
    GL_DRAW_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &components);
  return components == GL_FLOAT || bits >= 24;
}
}

bool vtkFXCompositePass::CanUseDepthPrepass(vtkOpenGLRenderer* ren)
{
  // (the pre-pass relies on the framebuffer's depth being the clear value
  // everywhere: what the camera pass leaves when the renderer and its
  // window erase and the renderer does not preserve its depth; the
  // composite is the first to draw)
  if (!this->UseDepthPrepass || vtkFXRenderUtilities::KeepsEarlierDepth(ren) ||
    !CanHoldDepthBelowOne())
  {
    return false;
  }
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  return vtkFXRenderUtilities::ReadyQuad(this->DepthQuad, window, vtkFXCompositeDepthFS) != nullptr;
}

bool vtkFXCompositePass::BlitDepth(vtkOpenGLRenderer* ren)
{
  // (the G-buffer keeps the renderer's depth format, so a blit copies its
  // depth in one go where the target has one sample; refused once, the
  // blit is not tried again until the resources are released)
  GLint target = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &target);
  if (!this->UseDepthBlit || this->RefusingFramebuffer == target)
  {
    return false;
  }
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  vtkOpenGLState* state = window->GetState();
  vtkTextureObject* depth = this->GBuffer->GetDepthTexture();
  const int width = static_cast<int>(depth->GetWidth());
  const int height = static_cast<int>(depth->GetHeight());
  GLint viewport[4];
  state->vtkglGetIntegerv(GL_VIEWPORT, viewport);
  if (viewport[2] != width || viewport[3] != height)
  {
    return false;
  }
  if (!vtkFXRenderUtilities::MakeDepthOnlyFramebuffer(this->DepthReadFrameBuffer, window, depth))
  {
    return false;
  }

  vtkOpenGLState::ScopedglEnableDisable scissorSaver(state, GL_SCISSOR_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST); // (a blit obeys the scissor)
  state->PushReadFramebufferBinding();
  this->DepthReadFrameBuffer->Bind(GL_READ_FRAMEBUFFER);
  // (what earlier steps left is not this blit's refusal)
  vtkFXRenderUtilities::ClearPendingErrors(this, "vtkFX's depth copy", this->WarnedEarlierError);
  glBlitFramebuffer(0, 0, width, height, viewport[0], viewport[1], viewport[0] + width,
    viewport[1] + height, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  const bool copied = glGetError() == GL_NO_ERROR;
  state->PopReadFramebufferBinding();
  // (refused by one target, e.g. a multisampled window, the blit is tried
  // again for another, e.g. the HDR target)
  this->RefusingFramebuffer = copied ? -1 : target;
  return copied;
}

void vtkFXCompositePass::DrawDepthPrepass(vtkOpenGLRenderer* ren)
{
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(state);
  state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  state->vtkglDisable(GL_BLEND);
  vtkShaderProgram* program = this->DepthQuad.Helper->Program;
  window->GetShaderCache()->ReadyShaderProgram(program);
  vtkTextureObject* depth = this->GBuffer->GetDepthTexture();
  depth->Activate();
  program->SetUniformi("fxHardwareDepth", depth->GetTextureUnit());
  this->DepthQuad.Helper->Render();
  window->GetShaderCache()->ReadyShaderProgram(this->Quad.Helper->Program);
}

void vtkFXCompositePass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  this->UsedDepthPrepass = false;
  this->UsedDepthBlit = false;
  vtkOpenGLRenderer* ren = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  if (!ren || !this->GBuffer || !this->GBuffer->GetDepthTexture() ||
    !this->GBuffer->GetChannelTexture(GB::Albedo))
  {
    vtkErrorMacro("vtkFXCompositePass needs a rendered G-buffer with an albedo channel.");
    return;
  }
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  this->UsedDepthPrepass = this->CanUseDepthPrepass(ren);
  // The light texture and its tiles first: how the tiles hold their
  // entries (copies of rows, or indices) decides the shader's loops, and
  // measuring the tiles' depths draws with a program of its own.
  this->UploadedLights = 0;
  if (this->UsesLightTexture(ren))
  {
    this->UploadedLights = this->UploadLightTexture(ren);
  }
  const std::string fragmentShader = this->BuildFragmentShader(ren);
  if (fragmentShader.empty())
  {
    if (!this->ReportedPositionalWithoutDepth)
    {
      vtkErrorMacro("Positional lights need the G-buffer's linear depth channel "
                    "(see GetRequiredChannels); the opaque props are not drawn.");
      this->ReportedPositionalWithoutDepth = true;
    }
    this->UsedDepthPrepass = false; // (nothing drawn)
    this->DeactivateLightTextures();
    return;
  }
  this->Quad.AtFarPlane = this->UsedDepthPrepass;
  vtkShaderProgram* program =
    vtkFXRenderUtilities::ReadyQuad(this->Quad, window, fragmentShader);
  if (!program)
  {
    this->UsedDepthPrepass = false;
    this->DeactivateLightTextures();
    return;
  }
  this->SetUniforms(program, ren);
  this->Draw(ren);

  for (int c = 0; c < GB::NumberOfChannels; ++c)
  {
    if (vtkTextureObject* t = this->GBuffer->GetChannelTexture(c))
    {
      t->Deactivate();
    }
  }
  this->GBuffer->GetDepthTexture()->Deactivate();
  this->DeactivateLightTextures();
  for (const auto& contributor : this->Contributors)
  {
    contributor->UnbindCompositeResources();
  }
}

void vtkFXCompositePass::DeactivateLightTextures()
{
  // (the upload activated them before the shader was built)
  if (this->LightTexture)
  {
    this->LightTexture->Deactivate();
  }
  if (this->LightTilesUsed && this->LightTiles && this->LightTiles->GetHeaderTexture())
  {
    this->LightTiles->GetHeaderTexture()->Deactivate();
    this->LightTiles->GetEntryTexture()->Deactivate();
  }
}

void vtkFXCompositePass::ReleaseGraphicsResources(vtkWindow* w)
{
  vtkFXRenderUtilities::ReleaseQuad(this->Quad, w);
  vtkFXRenderUtilities::ReleaseQuad(this->DepthQuad, w);
  vtkFXRenderUtilities::Release(this->DepthReadFrameBuffer, w);
  this->RefusingFramebuffer = -1;
  vtkFXRenderUtilities::Release(this->LightTexture, w);
  if (this->LightTiles)
  {
    this->LightTiles->ReleaseGraphicsResources(w);
  }
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
  os << indent << "UseEmission: " << this->UseEmission << "\n";
  os << indent << "MaximumUniformLights: " << this->MaximumUniformLights << "\n";
  os << indent << "UseDepthPrepass: " << this->UseDepthPrepass << "\n";
  os << indent << "UseDepthBlit: " << this->UseDepthBlit << "\n";
  os << indent << "Contributors:";
  for (const auto& contributor : this->Contributors)
  {
    os << " " << contributor->GetClassName();
  }
  os << "\n";
}
