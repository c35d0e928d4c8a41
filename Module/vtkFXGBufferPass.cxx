#include "vtkFXGBufferPass.h"

#include "vtkFXGBufferDec.h"
#include "vtkFXNormalCoding.h"
#include "vtkFXRenderUtilities.h"

#include "vtkActor.h"
#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkCamera.h"
#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleKey.h"
#include "vtkInformationDoubleVectorKey.h"
#include "vtkInformationStringKey.h"
#include "vtkNew.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkShader.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLShaderProperty.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLState.h"
#include "vtkProperty.h"
#include "vtkTexture.h"
#include "vtkRenderState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkFXOpenGL.h"

#include <algorithm>
#include <iterator>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

// (a factory can replace it: TestRobustness simulates a driver that
// cannot make the G-buffer)
vtkObjectFactoryNewMacro(vtkFXGBufferPass);

namespace
{
const char* const ChannelNames[vtkFXGBufferPass::NumberOfChannels] = { "albedo", "normal", "depth",
  "specular", "ambient", "emission", "geometric-normal" };

const int ChannelFormats[vtkFXGBufferPass::NumberOfChannels] = { vtkFXRenderUtilities::RGBA8,
  vtkFXRenderUtilities::RG16F, vtkFXRenderUtilities::R32F, vtkFXRenderUtilities::RGBA8,
  vtkFXRenderUtilities::RGBA8, vtkFXRenderUtilities::RGBA8, vtkFXRenderUtilities::RG16F };

// Value of each channel where no surface is: the normal channel holds the
// "unlit" sentinel of vtkFXNormalCoding.glsl, so that pixels no hooked
// mapper wrote are never lit with a made-up normal.
const float ClearValues[vtkFXGBufferPass::NumberOfChannels][4] = { { 0, 0, 0, 0 }, { 4, 4, 0, 1 },
  { 0, 0, 0, 0 }, { 0, 0, 0, 0 }, { 0, 0, 0, 0 }, { 0, 0, 0, 0 }, { 4, 4, 0, 1 } };

// The vertex attribute a bumped prop's scalar arrives in, and its varying.
const char* const BumpAttribute = "fxBumpMC";

// Tags planted in the mapper's fragment shader before its own substitutions.
const char* const TexBeginTag = "//VTK::FXGBuffer::TexBegin";
const char* const TexEndTag = "//VTK::FXGBuffer::TexEnd";
const char* const ImplTag = "//VTK::FXGBuffer::Impl";
// Left in the shaders that write every channel (see SetShaderParameters).
const char* const HookedMarker = "// vtkFX G-buffer channel writes";

bool Contains(const std::string& s, const char* what)
{
  return s.find(what) != std::string::npos;
}

// The code the mapper substituted for its texture tag, between our markers.
std::string ExtractTextureCode(const std::string& fs)
{
  const size_t begin = fs.find(TexBeginTag);
  const size_t end = fs.find(TexEndTag);
  if (begin == std::string::npos || end == std::string::npos || end < begin)
  {
    return std::string();
  }
  const size_t start = begin + std::string(TexBeginTag).size();
  return fs.substr(start, end - start);
}

bool IsBlank(const std::string& s)
{
  return s.find_first_not_of(" \t\r\n") == std::string::npos;
}

// fxShadingNormal: the normal VTK lights with, tilted by the bump when the
// shader receives one; fxGeometricNormal: the mesh normal before either
// (captured before VTK's normal-texture code where it has some). Mikkelsen, "Bump Mapping Unparametrized Surfaces on
// the GPU" (2010), eq. 2-4: with the screen derivatives of the position
// and of the height h, the surface gradient of h is
//   (dh/dx (dp/dy x n) + dh/dy (n x dp/dx)) / det, det = dp/dx . (dp/dy x n),
// and the bumped normal is n - gradient (scaled by |det| to avoid the
// division). Degenerate derivatives (a triangle seen edge-on, NaN scalars)
// leave the normal as it was.
std::string ShadingNormalGLSL(bool bump, bool normalTexture)
{
  std::string code = normalTexture ? "" : "  vec3 fxGeometricNormal = normalVCVSOutput;\n";
  code += "  vec3 fxShadingNormal = normalVCVSOutput;\n";
  if (bump)
  {
    code += "  {\n"
            "    vec3 dpdx = dFdx(vertexVC.xyz);\n"
            "    vec3 dpdy = dFdy(vertexVC.xyz);\n"
            // (the height is along the mesh's front normal: seen from
            // behind, a bump is a dent)
            "    float h = (gl_FrontFacing ? 1.0 : -1.0) * fxBumpScale * fxBumpVSOutput;\n"
            "    vec3 r1 = cross(dpdy, fxShadingNormal);\n"
            "    vec3 r2 = cross(fxShadingNormal, dpdx);\n"
            "    float det = dot(dpdx, r1);\n"
            "    vec3 gradient = sign(det) * (dFdx(h) * r1 + dFdy(h) * r2);\n"
            "    vec3 bumped = abs(det) * fxShadingNormal - gradient;\n"
            "    float len = length(bumped);\n"
            "    if (len > 0.0 && !isinf(len) && !isnan(len))\n"
            "    {\n"
            "      fxShadingNormal = bumped / len;\n"
            "    }\n"
            "  }\n";
  }
  return code;
}
}

vtkFXGBufferPass::vtkFXGBufferPass()
  : RequiredChannels((1u << NumberOfChannels) - 1)
{
}

vtkFXGBufferPass::~vtkFXGBufferPass()
{
  this->SetDelegatePass(nullptr);
}

vtkCxxSetObjectMacro(vtkFXGBufferPass, DelegatePass, vtkRenderPass);

const char* vtkFXGBufferPass::GetChannelName(int channel)
{
  return (channel >= 0 && channel < NumberOfChannels) ? ChannelNames[channel] : "unknown";
}

int vtkFXGBufferPass::GetChannelFromName(const char* name)
{
  for (int c = 0; name && c < NumberOfChannels; ++c)
  {
    if (std::string(name) == ChannelNames[c])
    {
      return c;
    }
  }
  return -1;
}

int vtkFXGBufferPass::GetChannelFormat(int channel) const
{
  if (channel == Emission && this->HDREmission)
  {
    return vtkFXRenderUtilities::RGBA16F;
  }
  if ((channel == Albedo || channel == Specular || channel == Ambient) && this->HDRMaterial)
  {
    return vtkFXRenderUtilities::RGBA16F;
  }
  return (channel >= 0 && channel < NumberOfChannels) ? ChannelFormats[channel] : -1;
}

vtkInformationKeyRestrictedMacro(vtkFXGBufferPass, EMISSIVE_COLOR, DoubleVector, 3);
vtkInformationKeyMacro(vtkFXGBufferPass, BUMP_ARRAY, String);
vtkInformationKeyMacro(vtkFXGBufferPass, BUMP_SCALE, Double);

namespace
{
// VTK 9.1's composite mapper draws its blocks through helpers it gives
// only vtkMapper's settings: a vertex-attribute mapping never reaches
// their shaders.
bool IsCompositeMapper(vtkMapper* mapper)
{
  return mapper && mapper->IsA("vtkCompositePolyDataMapper2");
}
}

void vtkFXGBufferPass::SetBump(vtkActor* actor, const char* arrayName, double scale)
{
  if (!actor)
  {
    return;
  }
  const bool remove = !arrayName || !*arrayName;
  vtkInformation* keys = actor->GetPropertyKeys();
  if (!keys && remove)
  {
    return;
  }
  if (!keys)
  {
    vtkNew<vtkInformation> created;
    actor->SetPropertyKeys(created);
    keys = created;
  }
  if (remove)
  {
    keys->Remove(BUMP_ARRAY());
    keys->Remove(BUMP_SCALE());
  }
  else
  {
    if (!std::isfinite(scale))
    {
      vtkGenericWarningMacro("vtkFXGBufferPass::SetBump: scale " << scale << " is not finite; no bump.");
      scale = 0.0;
    }
    keys->Set(BUMP_ARRAY(), arrayName);
    keys->Set(BUMP_SCALE(), scale);
  }
  // The mapper sends the array to the shader as a vertex attribute (only
  // programs that declare it read it).
  if (!remove && IsCompositeMapper(actor->GetMapper()))
  {
    vtkGenericWarningMacro("vtkFXGBufferPass::SetBump: vtkCompositePolyDataMapper2 does not hand "
                           "vertex attributes to the helpers that draw its blocks (VTK 9.1); "
                           "no bump. Draw the blocks with vtkPolyDataMapper to bump them.");
  }
  else if (auto* mapper = vtkOpenGLPolyDataMapper::SafeDownCast(actor->GetMapper()))
  {
    if (remove)
    {
      mapper->RemoveVertexAttributeMapping(BumpAttribute);
    }
    else
    {
      mapper->MapDataArrayToVertexAttribute(
        BumpAttribute, arrayName, vtkDataObject::FIELD_ASSOCIATION_POINTS, 0);
    }
  }
  else if (!remove)
  {
    vtkGenericWarningMacro("vtkFXGBufferPass::SetBump: the actor's mapper is not a "
                           "vtkOpenGLPolyDataMapper; set one before SetBump. No bump.");
  }
  actor->Modified();
}

bool vtkFXGBufferPass::HasBump(vtkProp* prop)
{
  vtkInformation* keys = prop ? prop->GetPropertyKeys() : nullptr;
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  if (!keys || !keys->Has(BUMP_ARRAY()) || !keys->Has(BUMP_SCALE()) || !actor ||
    !vtkOpenGLPolyDataMapper::SafeDownCast(actor->GetMapper()) ||
    IsCompositeMapper(actor->GetMapper()))
  {
    return false;
  }
  const double scale = keys->Get(BUMP_SCALE());
  return std::isfinite(scale) && scale != 0.0 && keys->Get(BUMP_ARRAY()) &&
    *keys->Get(BUMP_ARRAY());
}

bool vtkFXGBufferPass::GetEmissiveColor(vtkProp* prop, double color[3])
{
  vtkInformation* keys = prop ? prop->GetPropertyKeys() : nullptr;
  if (!keys || !keys->Has(EMISSIVE_COLOR()) || keys->Length(EMISSIVE_COLOR()) != 3)
  {
    return false;
  }
  keys->Get(EMISSIVE_COLOR(), color);
  for (int i = 0; i < 3; ++i)
  {
    // Negative, NaN and infinite emission would spread into every effect
    // that reads the channel: keep it finite and non-negative.
    color[i] = std::isfinite(color[i]) ? std::min(std::max(color[i], 0.0), 65504.0) : 0.0;
  }
  return color[0] > 0.0 || color[1] > 0.0 || color[2] > 0.0;
}

vtkTextureObject* vtkFXGBufferPass::GetChannelTexture(int channel)
{
  if (channel < 0 || channel >= NumberOfChannels || !(this->AllocatedChannels & ChannelBit(channel)))
  {
    return nullptr;
  }
  return this->Textures[channel];
}

vtkTextureObject* vtkFXGBufferPass::GetGeometricNormalTexture()
{
  vtkTextureObject* geometric = this->GetChannelTexture(GeometricNormal);
  return geometric ? geometric : this->GetChannelTexture(Normal);
}

bool vtkFXGBufferPass::PerturbsNormal(vtkProp* prop)
{
  if (HasBump(prop))
  {
    return true;
  }
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  if (!actor || !actor->GetMapper() || !actor->GetProperty()->GetTexture("normalTex"))
  {
    return false;
  }
  // VTK applies the texture where the mesh has tangents and texture
  // coordinates: look at the data the mapper will draw (brought up to date,
  // as the render would), every block of a composite dataset.
  actor->GetMapper()->Update();
  vtkDataObject* data = actor->GetMapper()->GetInputDataObject(0, 0);
  const auto mapped = [](vtkDataObject* object) {
    vtkPolyData* mesh = vtkPolyData::SafeDownCast(object);
    return mesh && mesh->GetPointData()->GetTangents() && mesh->GetPointData()->GetTCoords();
  };
  const std::vector<vtkDataObject*> leaves = vtkFXRenderUtilities::Leaves(data);
  return std::any_of(leaves.begin(), leaves.end(), mapped);
}

vtkTextureObject* vtkFXGBufferPass::GetDepthTexture()
{
  return this->DepthTexture;
}

int vtkFXGBufferPass::GetBytesPerPixel() const
{
  int bytes = this->DepthTexture ? vtkFXRenderUtilities::GetBytesPerTexel(this->DepthFormat) : 0; // (4 for every depth format)
  for (int c = 0; c < NumberOfChannels; ++c)
  {
    if (this->AllocatedChannels & ChannelBit(c))
    {
      bytes += vtkFXRenderUtilities::GetBytesPerTexel(this->GetChannelFormat(c));
    }
  }
  return bytes;
}

namespace
{
// Whether the actor's own fragment code can decide its colour where the
// G-buffer cannot keep it: a fragment shader of its own; a replacement at
// VTK's lighting or a tag after it (which runs after the lighting, and
// for a lit surface the G-buffer stores the material, which the composite
// lights again: what the code made of the colour was lost); or one whose
// code writes the fragment's colour. Replacements elsewhere (declarations,
// //VTK::Color::Impl setting diffuseColor, //VTK::Normal::Impl) come
// before the lighting, which the G-buffer reproduces from what they
// compute. (Mapper-level replacements, deprecated in VTK 9, reach the
// shader property only once the mapper builds its shaders.)
bool HasOwnFragmentColour(vtkActor* actor)
{
  // (vtkProp makes its shader property on first request: never nullptr)
  vtkShaderProperty* property = actor->GetShaderProperty();
  if (property->HasFragmentShaderCode())
  {
    return true;
  }
  auto* shaders = vtkOpenGLShaderProperty::SafeDownCast(property);
  if (!shaders)
  {
    return false;
  }
  // vtkPolyDataFS.glsl's tags from the lighting on, in the order they run
  static const char* const fromLighting[] = { "//VTK::Light::Impl", "//VTK::TCoord::Impl",
    "//VTK::DepthPeeling::Impl", "//VTK::Picking::Impl", "//VTK::Coincident::Impl",
    "//VTK::ZBuffer::Impl", "//VTK::RenderPassFragmentShader::Impl" };
  for (const auto& replacement : shaders->GetAllShaderReplacements())
  {
    const vtkShader::ReplacementSpec& spec = replacement.first;
    if (spec.ShaderType != vtkShader::Fragment)
    {
      continue;
    }
    const bool late = std::any_of(std::begin(fromLighting), std::end(fromLighting),
      [&spec](const char* tag) { return spec.OriginalValue == tag; });
    if (late || Contains(replacement.second.Replacement, "gl_FragData") ||
      Contains(replacement.second.Replacement, "gl_FragColor"))
    {
      return true;
    }
  }
  return false;
}

// An actor VTK draws in its opaque step (ForceOpaque) although its opacity,
// its colours' or its texture's alpha is below 1 (vtkActor::GetIsOpaque's
// tests): VTK blends it there over what the step drew before it, which a
// G-buffer, one surface per pixel, does not hold; drawn forward, after the
// composite, it blends over the lit image as in VTK (captured, it showed
// the background through it).
bool IsForcedOpaqueBlend(vtkActor* actor)
{
  if (!actor->GetForceOpaque())
  {
    return false;
  }
  vtkProperty* property = actor->GetProperty();
  vtkTexture* texture = actor->GetTexture();
  return (property && property->GetOpacity() < 1.0) ||
    actor->GetMapper()->HasTranslucentPolygonalGeometry() ||
    (texture && texture->IsTranslucent());
}

// An actor the G-buffer's hooks shade. Not a vtkSkybox: VTK draws the sky at
// the far plane (window depth 1, the composite's background), through an
// actor of its own that carries no render-pass keys; drawn forward, after
// the composite, it shows where nothing else does, as VTK shows it. Nor an
// actor whose fragment code decides its colour past the hook
// (HasOwnFragmentColour): drawn forward too. Nor an actor without a mapper
// that still has geometry (vtkPolarAxesActor, vtkCubeAxesActor): it draws
// through actors of its own that carry none of the hooks' keys, whose
// colour would land in the G-buffer's first channel (garbled, recoloured
// labels and axis lines); drawn forward, it shows as VTK draws it. (A
// plain vtkActor without a mapper draws nothing: captured, so that an
// empty placeholder does not send its assembly forward.) Nor an actor
// forced opaque whose fragments are not (IsForcedOpaqueBlend).
bool IsCapturedActor(vtkProp* prop)
{
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  if (!actor)
  {
    return false;
  }
  if (!actor->GetMapper())
  {
    const std::string type = actor->GetClassName();
    return type == "vtkActor" || type == "vtkOpenGLActor";
  }
  return !prop->IsA("vtkSkybox") && !HasOwnFragmentColour(actor) && !IsForcedOpaqueBlend(actor);
}
}

bool vtkFXGBufferPass::CanCapture(vtkProp* prop)
{
  if (IsCapturedActor(prop))
  {
    return true;
  }
  if (!prop || !prop->IsA("vtkAssembly"))
  {
    return false;
  }
  // An assembly is captured when every part VTK draws (visibility on) is
  // an actor it can capture.
  bool all = true;
  prop->InitPathTraversal();
  while (vtkAssemblyPath* path = prop->GetNextPath())
  {
    vtkProp* part = path->GetLastNode()->GetViewProp();
    all = all && (!part->GetVisibility() || IsCapturedActor(part));
  }
  return all;
}

bool vtkFXGBufferPass::FrameBufferComplete()
{
  return glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
}

bool vtkFXGBufferPass::UpdateTargets(vtkOpenGLRenderWindow* window, int width, int height)
{
  const unsigned int wanted = this->RequiredChannels & ((1u << NumberOfChannels) - 1);
  if (wanted != this->AllocatedChannels)
  {
    // A different set of channels changes the code the mappers must run.
    this->ShaderStageTime.Modified();
  }
  if (!this->FrameBuffer)
  {
    this->FrameBuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    this->FrameBuffer->SetContext(window);
  }
  for (int c = 0; c < NumberOfChannels; ++c)
  {
    if (wanted & ChannelBit(c))
    {
      vtkFXRenderUtilities::EnsureTexture(
        this->Textures[c], window, width, height, this->GetChannelFormat(c));
    }
    else
    {
      // Rule: a channel nobody reads is never kept.
      vtkFXRenderUtilities::Release(this->Textures[c], window);
    }
  }
  // The renderer's own depth format (its framebuffer is still bound), so
  // that the composite can copy this depth into it with one blit.
  this->DepthFormat = vtkFXRenderUtilities::GetReadDepthFormat(window);
  vtkFXRenderUtilities::EnsureTexture(
    this->DepthTexture, window, width, height, this->DepthFormat);
  this->AllocatedChannels = wanted;

  // Attach the allocated channels in channel order, packed from attachment 0.
  this->FrameBuffer->Bind();
  this->FrameBuffer->RemoveColorAttachments(NumberOfChannels);
  unsigned int attachment = 0;
  for (int c = 0; c < NumberOfChannels; ++c)
  {
    if (wanted & ChannelBit(c))
    {
      this->FrameBuffer->AddColorAttachment(attachment++, this->Textures[c]);
    }
  }
  this->FrameBuffer->AddDepthAttachment(this->DepthTexture);
  this->NumberOfTargets = attachment;
  this->FrameBuffer->ActivateDrawBuffers(attachment);
  const bool complete = this->FrameBufferComplete();
  if (!complete && !this->WarnedIncomplete)
  {
    // (say, no memory for this many channels at this size)
    vtkErrorMacro("The G-buffer of " << width << " x " << height << " pixels, " << attachment
                                     << " channels, could not be made: the opaque props are "
                                        "drawn without the effects that read it.");
    this->WarnedIncomplete = true;
  }
  return complete;
}

std::vector<vtkProp*> vtkFXGBufferPass::CapturedProps(const vtkRenderState* s)
{
  // Only props whose shaders we can extend; the pipeline draws the rest.
  std::vector<vtkProp*> props;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    if (CanCapture(s->GetPropArray()[i]))
    {
      props.push_back(s->GetPropArray()[i]);
    }
  }
  return props;
}

void vtkFXGBufferPass::RenderForward(const vtkRenderState* s, std::vector<vtkProp*>& props)
{
  if (!this->DelegatePass)
  {
    return;
  }
  // No shader hooks (no PreRender): the mappers draw as they would without
  // vtkFX, depth-tested against and writing the target's depth.
  vtkRenderState forward(s->GetRenderer());
  forward.SetPropArrayAndCount(props.data(), static_cast<int>(props.size()));
  forward.SetFrameBuffer(s->GetFrameBuffer());
  this->DelegatePass->Render(&forward);
  this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
}

void vtkFXGBufferPass::ClearTargets()
{
  // glClearBuffer leaves the clear colour and depth of the GL state alone.
  GLint target = 0;
  for (int c = 0; c < NumberOfChannels; ++c)
  {
    if (this->AllocatedChannels & ChannelBit(c))
    {
      glClearBufferfv(GL_COLOR, target++, ClearValues[c]);
    }
  }
  const GLfloat far = 1.0f;
  glClearBufferfv(GL_DEPTH, 0, &far);
}

void vtkFXGBufferPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  vtkOpenGLRenderer* ren = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  if (!ren)
  {
    vtkErrorMacro("vtkFXGBufferPass needs a vtkOpenGLRenderer.");
    return;
  }
  if (!this->DelegatePass)
  {
    vtkWarningMacro("No delegate pass: the G-buffer stays empty.");
  }
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  vtkOpenGLState* state = window->GetState();

  int width, height;
  vtkFXRenderUtilities::GetViewportSize(s, width, height);

  state->PushFramebufferBindings();
  this->FrameComplete = this->UpdateTargets(window, width, height);
  std::vector<vtkProp*> props = CapturedProps(s);
  if (!this->FrameComplete)
  {
    this->FrameBuffer->UnBind();
    state->PopFramebufferBindings();
    this->RenderForward(s, props);
    return;
  }

  {
    vtkOpenGLState::ScopedglViewport viewportSaver(state);
    vtkOpenGLState::ScopedglScissor scissorSaver(state);
    vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable depthSaver(state, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable scissorTestSaver(state, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
    vtkOpenGLState::ScopedglColorMask colorMaskSaver(state);

    state->vtkglViewport(0, 0, width, height);
    state->vtkglScissor(0, 0, width, height);
    state->vtkglDisable(GL_SCISSOR_TEST);
    // Channels are data, not colours: blending would corrupt them.
    state->vtkglDisable(GL_BLEND);
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglDepthMask(GL_TRUE);
    state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    this->ClearTargets();

    // Third and fourth rows of the projection, for unlit primitives' depth.
    vtkMatrix4x4* projection = ren->GetActiveCamera()->GetProjectionTransformMatrix(
      ren->GetTiledAspectRatio(), -1, 1);
    this->ProjectionZ[0] = static_cast<float>(projection->GetElement(2, 2));
    this->ProjectionZ[1] = static_cast<float>(projection->GetElement(2, 3));
    this->ProjectionZ[2] = static_cast<float>(projection->GetElement(3, 2));
    this->ProjectionZ[3] = static_cast<float>(projection->GetElement(3, 3));

    if (this->DelegatePass)
    {
      // Draws that never reach SetShaderParameters write their colour only.
      this->HookedPrograms.clear();
      this->FrameBuffer->ActivateDrawBuffers(1);
      vtkRenderState delegateState(ren);
      delegateState.SetPropArrayAndCount(props.data(), static_cast<int>(props.size()));
      delegateState.SetFrameBuffer(this->FrameBuffer);
      this->PreRender(&delegateState);
      this->DelegatePass->Render(&delegateState);
      this->PostRender(&delegateState);
      this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
    }
  }
  this->FrameBuffer->UnBind();
  state->PopFramebufferBindings();
  // Hand the G-buffer's draws to the rasteriser now. On llvmpipe, leaving
  // them queued until a later pass samples the channels made scenes with
  // many triangles several times slower (vtkfx-bench do, scene:bumps at
  // 640x480: 65 -> 17 ms for directional occlusion, and 65 -> 24 ms for
  // the next window's vtkSSAOPass frame); a GPU driver only submits.
  glFlush();
}

bool vtkFXGBufferPass::PreReplaceShaderValues(std::string& vertexShader,
  std::string& geometryShader, std::string& fragmentShader, vtkAbstractMapper*, vtkProp* prop)
{
  // Volumes and other non-polydata shaders have no texture tag: leave them.
  if (!Contains(fragmentShader, "//VTK::TCoord::Impl"))
  {
    return true;
  }
  if (HasBump(prop) && geometryShader.empty() && Contains(vertexShader, "//VTK::Normal::Impl") &&
    Contains(fragmentShader, "//VTK::Normal::Dec"))
  {
    // The bump's scalar, from the mapped vertex attribute to the fragment.
    vtkShaderProgram::Substitute(vertexShader, "//VTK::Normal::Dec",
      std::string("//VTK::Normal::Dec\nin float ") + BumpAttribute + ";\nout float fxBumpVSOutput;",
      false);
    vtkShaderProgram::Substitute(vertexShader, "//VTK::Normal::Impl",
      std::string("//VTK::Normal::Impl\n  fxBumpVSOutput = ") + BumpAttribute + ";", false);
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::Normal::Dec",
      "//VTK::Normal::Dec\nin float fxBumpVSOutput;\nuniform float fxBumpScale;", false);
  }
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::TCoord::Impl",
    std::string(TexBeginTag) + "\n  //VTK::TCoord::Impl\n  " + TexEndTag + "\n  " + ImplTag, false);
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::Output::Dec",
    std::string("//VTK::Output::Dec\n") + vtkFXGBufferDec, false);
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::FXNormalCoding::Dec", vtkFXNormalCoding, false);
  return true;
}

std::string vtkFXGBufferPass::ChannelWritesGLSL(
  FragmentLighting lighting, bool unlitEmits, const char* linearDepth) const
{
  const bool lit = lighting == Phong;
  const bool prelit = lighting == Prelit;
  // (a pre-lit fragment's normal is flagged: see vtkFXNormalCoding.glsl)
  const auto normal = [&](const char* name) {
    return lit ? std::string("vec4(fxEncodeNormal(") + name + "), 0.0, 1.0);\n"
               : prelit ? std::string("vec4(fxEncodePrelitNormal(") + name + "), 0.0, 1.0);\n"
                        : std::string("vec4(fxUnlitNormal, 0.0, 1.0);\n");
  };
  vtkFXRenderUtilities::CodeStream code;
  int target = 0;
  for (int c = 0; c < NumberOfChannels; ++c)
  {
    if (!(this->AllocatedChannels & ChannelBit(c)))
    {
      continue;
    }
    code << "  gl_FragData[" << target++ << "] = ";
    switch (c)
    {
      case Normal:
        code << normal("fxShadingNormal");
        break;
      case LinearDepth:
        code << "vec4(" << linearDepth << ", 0.0, 0.0, 1.0);\n";
        break;
      case Albedo:
        // (pre-lit: VTK's colour and the prop's own emission, as an unlit
        // prop carries its colour: whatever the composite does with the
        // pixel, the emission is in it; the occlusion takes it out again
        // where it reads the emission channel, vtkFXCompositeFS)
        code << (lit ? "vec4(fxDiffuse, fxColor.a);\n"
                     : prelit ? "vec4(fxColor.rgb + fxEmissive, fxColor.a);\n" : "fxColor;\n");
        break;
      case Specular:
        // The power (VTK's 0..128) as sqrt(power / 128) in 8 bits: small
        // powers keep two digits (0.2 comes back 0.197; linear, it was 0).
        code << (lit ? "vec4(fxSpecular, sqrt(clamp(fxSpecularPower / 128.0, 0.0, 1.0)));\n"
                     : "vec4(0.0);\n");
        break;
      case Ambient:
        code << (lit ? "vec4(fxAmbient, 1.0);\n" : "vec4(0.0, 0.0, 0.0, 1.0);\n");
        break;
      case Emission:
        code << (lit || prelit || !unlitEmits ? "vec4(fxEmissive, 1.0);\n"
                                              : "fxFiniteEmission(fxColor);\n");
        break;
      case GeometricNormal:
        code << normal("fxGeometricNormal");
        break;
    }
  }
  return code.str();
}

bool vtkFXGBufferPass::PostReplaceShaderValues(std::string&, std::string&,
  std::string& fragmentShader, vtkAbstractMapper*, vtkProp* prop)
{
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  if (!Contains(fragmentShader, ImplTag))
  {
    return true;
  }
  // VTK 9.1 lights a primitive (light complexity > 0) only when its shader
  // computes "vec3 diffuse" (Phong) or "vec3 Lo" (PBR) from a normal; the
  // light uniforms alone are declared for unlit primitives too. PBR
  // materials keep their forward colour (the composite reproduces VTK's
  // Phong model only) with their normal: they receive occlusion and carry
  // feature lines.
  const bool pbr = actor && actor->GetProperty()->GetInterpolation() == VTK_PBR;
  const bool normals = Contains(fragmentShader, "normalVCVSOutput");
  const bool lit = !pbr && normals && Contains(fragmentShader, "vec3 diffuse = ");
  const bool prelit = pbr && normals && Contains(fragmentShader, "vec3 Lo = ");
  // Linear depth: -z of the view-space position where the shader has one.
  // Points drawn as spheres and lines drawn as tubes move the surface off
  // that position (to gl_FragDepth): fxImpostorLinearDepth. Unlit
  // primitives have none: fxLinearDepthOfFragment.
  // (VTK's uniform, not the word: comments may name it)
  const bool impostor = Contains(fragmentShader, "uniform float ZCalcR;");
  // (VTK 9.1's perspective depth of its impostors, the same line for
  // points and tubes; where it is not found, the window depth is inverted)
  const bool impostorScaled = impostor &&
    vtkShaderProgram::Substitute(fragmentShader,
      "gl_FragDepth = (ZCalcS - gl_FragCoord.z) / ZCalcQ + ZCalcS;",
      "fxImpostorScale = -ZCalcQ;\n    gl_FragDepth = (ZCalcS - gl_FragCoord.z) / ZCalcQ + ZCalcS;",
      true);
  const char* linearDepth = impostor
    ? (impostorScaled ? "fxImpostorLinearDepth()" : "fxLinearDepthFromWindow(gl_FragDepth)")
    : Contains(fragmentShader, "vec4 vertexVC =") ? "-vertexVC.z"
                                                   : "fxLinearDepthOfFragment()";

  // VTK 9.1 applies actor textures after lighting: lit RGBA * texel, with no
  // clamp, so texel x (ambient + diffuse + specular) distributes exactly over
  // the terms. Replay the mapper's own texture code on white to learn the
  // per-fragment texel, and store the textured terms.
  const std::string textureCode = ExtractTextureCode(fragmentShader);
  vtkFXRenderUtilities::CodeStream impl;
  impl << HookedMarker << "\n  vec4 fxColor = gl_FragData[0];\n";
  impl << "  vec4 fxTexture = vec4(1.0);\n";
  if (!IsBlank(textureCode))
  {
    impl << "  {\n    gl_FragData[0] = vec4(1.0);\n" << textureCode
         << "\n    fxTexture = gl_FragData[0];\n    gl_FragData[0] = fxColor;\n  }\n";
  }
  if (lit)
  {
    // A lit shader always declares these (ReplaceShaderColor, 9.1).
    impl << "  vec3 fxDiffuse = diffuseColor * fxTexture.rgb;\n"
            "  vec3 fxAmbient = ambientColor * fxTexture.rgb;\n"
            "  vec3 fxSpecular = specularColor * fxTexture.rgb;\n"
            "  float fxSpecularPower = clamp(specularPower, 0.0, 128.0);\n";
  }
  if (lit || prelit)
  {
    // VTK's normal-texture code replaces normalVCVSOutput: keep the mesh
    // normal from just before it.
    const char* const normalTextureCode = "mat3 tbn = mat3(";
    const bool normalTexture = Contains(fragmentShader, normalTextureCode);
    if (normalTexture)
    {
      vtkShaderProgram::Substitute(fragmentShader, normalTextureCode,
        std::string("vec3 fxGeometricNormal = normalVCVSOutput;\n  ") + normalTextureCode, false);
    }
    // (no bump on a pre-lit colour: VTK's lighting did not see it)
    impl << ShadingNormalGLSL(lit && Contains(fragmentShader, "in float fxBumpVSOutput;") &&
        Contains(fragmentShader, "vec4 vertexVC ="),
      normalTexture);
  }
  // The mapper discards fully transparent fragments after this point; do it
  // here too, before our writes replace gl_FragData[0].
  impl << "  if (fxColor.a <= 0.0) { discard; }\n";
  // (as the pipeline's scene analysis counts emissive props: a prop with
  // Lighting off glows with its colour, a lit one with its emissive colour
  // only, also where VTK leaves its primitives unlit)
  const bool unlitEmits = !actor || !actor->GetProperty()->GetLighting();
  impl << this->ChannelWritesGLSL(lit ? Phong : prelit ? Prelit : Unlit, unlitEmits, linearDepth);
  // Remove the markers; keep the mapper's code where it was.
  vtkShaderProgram::Substitute(fragmentShader, TexBeginTag, "", false);
  vtkShaderProgram::Substitute(fragmentShader, TexEndTag, "", false);
  vtkShaderProgram::Substitute(fragmentShader, ImplTag, impl.str(), false);
  return true;
}

bool vtkFXGBufferPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp* prop, vtkOpenGLVertexArrayObject*)
{
  if (program->IsUniformUsed("fxProjectionZ"))
  {
    program->SetUniform4f("fxProjectionZ", this->ProjectionZ);
  }
  if (program->IsUniformUsed("fxBumpScale"))
  {
    vtkInformation* keys = prop ? prop->GetPropertyKeys() : nullptr;
    const double scale = keys && keys->Has(BUMP_SCALE()) ? keys->Get(BUMP_SCALE()) : 0.0;
    program->SetUniformf("fxBumpScale", std::isfinite(scale) ? static_cast<float>(scale) : 0.0f);
  }
  if (program->IsUniformUsed("fxEmissive"))
  {
    double emissive[3] = { 0.0, 0.0, 0.0 };
    GetEmissiveColor(prop, emissive);
    const float value[3] = { static_cast<float>(emissive[0]), static_cast<float>(emissive[1]),
      static_cast<float>(emissive[2]) };
    program->SetUniform3f("fxEmissive", value);
  }
  if (this->FrameBuffer)
  {
    // A shader the hooks did not extend writes its colour only: the other
    // attachments must not receive undefined values from it.
    // (Looked up once per program and frame: the source comes as a copy.)
    auto known = this->HookedPrograms.find(program);
    if (known == this->HookedPrograms.end())
    {
      const bool writes = program->GetFragmentShader() &&
        Contains(program->GetFragmentShader()->GetSource(), HookedMarker);
      known = this->HookedPrograms.emplace(program, writes).first;
    }
    const bool hooked = known->second;
    this->FrameBuffer->ActivateDrawBuffers(hooked ? this->NumberOfTargets : 1);
  }
  return true;
}

vtkMTimeType vtkFXGBufferPass::GetShaderStageMTime()
{
  return this->ShaderStageTime.GetMTime();
}

void vtkFXGBufferPass::ReleaseGraphicsResources(vtkWindow* w)
{
  if (this->DelegatePass)
  {
    this->DelegatePass->ReleaseGraphicsResources(w);
  }
  for (auto& texture : this->Textures)
  {
    vtkFXRenderUtilities::Release(texture, w);
  }
  vtkFXRenderUtilities::Release(this->DepthTexture, w);
  vtkFXRenderUtilities::Release(this->FrameBuffer, w);
  this->AllocatedChannels = 0;
  this->NumberOfTargets = 0;
  this->HookedPrograms.clear();
}

void vtkFXGBufferPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RequiredChannels: " << this->RequiredChannels << "\n";
  os << indent << "HDREmission: " << this->HDREmission << "\n";
  os << indent << "HDRMaterial: " << this->HDRMaterial << "\n";
  os << indent << "AllocatedChannels: " << this->AllocatedChannels << "\n";
  os << indent << "BytesPerPixel: " << this->GetBytesPerPixel() << "\n";
  os << indent << "DelegatePass: " << this->DelegatePass << "\n";
}
