#include "vtkFXRenderUtilities.h"

#include "vtkActor.h"
#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkBoundingBox.h"
#include "vtkCamera.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPointGaussianMapper.h"
#include "vtkProperty.h"
#include "vtkPropAssembly.h"
#include "vtkPropCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTransform.h"
#include "vtkFXOpenGL.h"
#include "vtkFXTilePointsVS.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <mutex>
#include <map>

vtkStandardNewMacro(vtkFXRenderUtilities);

namespace
{
struct FormatInfo
{
  int InternalFormat;
  int Format;
  int Components;
  int VTKType;
  int Bytes;
};

const FormatInfo& Info(int format)
{
  static const FormatInfo table[vtkFXRenderUtilities::NumberOfTextureFormats] = {
    { GL_R32F, GL_RED, 1, VTK_FLOAT, 4 },
    { GL_RG16F, GL_RG, 2, VTK_FLOAT, 4 },
    { GL_RGBA8, GL_RGBA, 4, VTK_UNSIGNED_CHAR, 4 },
    { GL_RGBA16F, GL_RGBA, 4, VTK_FLOAT, 8 },
    { GL_R8, GL_RED, 1, VTK_UNSIGNED_CHAR, 1 },
    { GL_RG8, GL_RG, 2, VTK_UNSIGNED_CHAR, 2 },
    { GL_RG32F, GL_RG, 2, VTK_FLOAT, 8 },
    { GL_RGBA32F, GL_RGBA, 4, VTK_FLOAT, 16 },
    { GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, 1, VTK_FLOAT, 4 },
    { GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, 1, VTK_UNSIGNED_INT, 4 },
    { GL_DEPTH_COMPONENT32, GL_DEPTH_COMPONENT, 1, VTK_UNSIGNED_INT, 4 },
    { GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL, 1, VTK_UNSIGNED_INT, 4 },
  };
  return table[format];
}
}

int vtkFXRenderUtilities::GetBytesPerTexel(int format)
{
  if (format < 0 || format >= NumberOfTextureFormats)
  {
    return 0;
  }
  return Info(format).Bytes;
}

const char* vtkFXRenderUtilities::GatherDefines(bool useTextureGather)
{
  return useTextureGather ? "//VTK::System::Dec\n"
                            "#if __VERSION__ >= 400\n"
                            "#define FX_GATHER 1\n"
                            "#elif defined(GL_ARB_gpu_shader5)\n"
                            "#extension GL_ARB_gpu_shader5 : enable\n"
                            "#define FX_GATHER 1\n"
                            "#else\n"
                            "#define FX_GATHER 0\n"
                            "#endif\n"
                          : "//VTK::System::Dec\n#define FX_GATHER 0\n";
}

namespace
{
// Finite also as the float OpenGL receives (1e39 is not).
bool FiniteAsFloat(double value)
{
  return std::isfinite(static_cast<float>(value));
}
}

vtkTransform* vtkFXRenderUtilities::GetUserLightTransform(vtkRenderer* renderer, vtkLight* light)
{
  vtkOpenGLRenderer* gl = vtkOpenGLRenderer::SafeDownCast(renderer);
  return gl && !light->LightTypeIsSceneLight() ? gl->GetUserLightTransform() : nullptr;
}

void vtkFXRenderUtilities::GetShadingLightFrame(
  vtkRenderer* renderer, vtkLight* light, double position[3], double focalPoint[3])
{
  light->GetTransformedPosition(position);
  light->GetTransformedFocalPoint(focalPoint);
  vtkTransform* user = GetUserLightTransform(renderer, light);
  if (!user)
  {
    return;
  }
  vtkMatrix4x4* view = renderer->GetActiveCamera()->GetModelViewTransformMatrix();
  vtkNew<vtkMatrix4x4> back;
  vtkMatrix4x4::Invert(view, back);
  vtkNew<vtkTransform> move;
  move->PostMultiply();
  move->SetMatrix(view);
  move->Concatenate(user->GetMatrix());
  move->Concatenate(back);
  move->TransformPoint(position, position);
  move->TransformPoint(focalPoint, focalPoint);
}

bool vtkFXRenderUtilities::IsLightFinite(vtkLight* light)
{
  // What VTK's light uniforms carry (vtkOpenGLRenderer::UpdateLightingUniforms):
  // diffuse colour x intensity, the direction from position to focal point;
  // for a positional light its position and attenuation, and for a spot
  // light (a cone under 90 degrees, so finite; a NaN cone is no spot) its
  // exponent.
  double position[3], focalPoint[3];
  light->GetTransformedPosition(position);
  light->GetTransformedFocalPoint(focalPoint);
  const double* color = light->GetDiffuseColor();
  const double intensity = light->GetIntensity();
  bool finite = true;
  for (int i = 0; i < 3; ++i)
  {
    finite = finite && FiniteAsFloat(color[i] * intensity) && FiniteAsFloat(position[i]) &&
      FiniteAsFloat(focalPoint[i]) && FiniteAsFloat(focalPoint[i] - position[i]);
  }
  if (light->GetPositional())
  {
    const double* attenuation = light->GetAttenuationValues();
    finite = finite && FiniteAsFloat(attenuation[0]) && FiniteAsFloat(attenuation[1]) &&
      FiniteAsFloat(attenuation[2]);
    if (light->GetConeAngle() < 90.0)
    {
      finite = finite && FiniteAsFloat(light->GetExponent());
    }
  }
  return finite;
}

void vtkFXRenderUtilities::DarkenNonFiniteLights(vtkRenderer* renderer, vtkShaderProgram* program)
{
  // (only the uniforms the program declares: which depends on the lighting
  // complexity)
  const auto set3 = [program](const std::string& name, float x, float y, float z) {
    const float value[3] = { x, y, z };
    if (program->IsUniformUsed(name.c_str()))
    {
      program->SetUniform3f(name.c_str(), value);
    }
  };
  const auto set1 = [program](const std::string& name, float value) {
    if (program->IsUniformUsed(name.c_str()))
    {
      program->SetUniformf(name.c_str(), value);
    }
  };
  vtkCollectionSimpleIterator it;
  renderer->GetLights()->InitTraversal(it);
  int place = -1;
  while (vtkLight* light = renderer->GetLights()->GetNextLight(it))
  {
    if (light->GetSwitch() <= 0)
    {
      continue;
    }
    ++place;
    if (IsLightFinite(light))
    {
      continue;
    }
    const std::string n = std::to_string(place);
    set3("lightColor" + n, 0.0f, 0.0f, 0.0f);
    set3("lightDirectionVC" + n, 0.0f, 0.0f, -1.0f);
    set3("lightPositionVC" + n, 0.0f, 0.0f, 0.0f);
    set3("lightAttenuation" + n, 1.0f, 0.0f, 0.0f);
    set1("lightConeAngle" + n, 180.0f);
    set1("lightExponent" + n, 1.0f);
    if (program->IsUniformUsed(("lightPositional" + n).c_str()))
    {
      program->SetUniformi(("lightPositional" + n).c_str(), 0);
    }
  }
}

bool vtkFXRenderUtilities::EnsureTexture(vtkSmartPointer<vtkTextureObject>& texture,
  vtkOpenGLRenderWindow* window, int width, int height, int format)
{
  const FormatInfo& info = Info(format);
  width = std::max(width, 1);
  height = std::max(height, 1);
  if (texture && texture->GetHandle() && texture->GetContext() == window &&
    static_cast<int>(texture->GetWidth()) == width &&
    static_cast<int>(texture->GetHeight()) == height &&
    static_cast<int>(texture->GetInternalFormat(info.VTKType, info.Components, false)) ==
      info.InternalFormat)
  {
    return false;
  }
  if (texture && texture->GetHandle() &&
    static_cast<int>(texture->GetInternalFormat(info.VTKType, info.Components, false)) !=
      info.InternalFormat)
  {
    // vtkTextureObject keeps its first internal format for depth textures:
    // another format needs another object.
    texture->ReleaseGraphicsResources(window);
    texture = nullptr;
  }
  if (!texture)
  {
    texture = vtkSmartPointer<vtkTextureObject>::New();
  }
  texture->SetContext(window);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  if (format == Depth24Stencil8)
  {
    texture->AllocateDepthStencil(width, height);
    return true;
  }
  if (format == Depth32F || format == Depth24 || format == Depth32)
  {
    texture->AllocateDepth(width, height,
      format == Depth32F ? vtkTextureObject::Float32
                         : format == Depth24 ? vtkTextureObject::Fixed24 : vtkTextureObject::Fixed32);
    return true;
  }
  texture->SetInternalFormat(info.InternalFormat);
  texture->SetFormat(info.Format);
  texture->SetDataType(info.VTKType == VTK_FLOAT ? GL_FLOAT : GL_UNSIGNED_BYTE);
  texture->Allocate2D(width, height, info.Components, info.VTKType);
  return true;
}

int vtkFXRenderUtilities::GetReadDepthFormat(vtkOpenGLRenderWindow* window)
{
  // A depth blit needs the same depth format on both sides: read what the
  // framebuffer being read keeps (VTK 9.1's window framebuffer: 32-bit
  // fixed point; others: 24-bit fixed, with or without stencil, or 32-bit
  // float). A multisampled source is fine: the blit resolves it.
  // (an attachment point that holds nothing answers only its object type:
  // any other query of it is a GL error, so it is asked first)
  GLint readFramebuffer = 0;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer);
  const GLenum attachment = readFramebuffer ? GL_DEPTH_ATTACHMENT : GL_DEPTH;
  const GLenum stencilAttachment = readFramebuffer ? GL_STENCIL_ATTACHMENT : GL_STENCIL;
  const auto holdsIn = [](GLenum framebuffer, GLenum point) {
    GLint object = GL_NONE;
    glGetFramebufferAttachmentParameteriv(
      framebuffer, point, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &object);
    return object != GL_NONE;
  };
  const auto holds = [&holdsIn](GLenum point) { return holdsIn(GL_READ_FRAMEBUFFER, point); };
  GLint bits = 0, type = GL_NONE, stencil = 0;
  if (holds(attachment))
  {
    glGetFramebufferAttachmentParameteriv(
      GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &bits);
    glGetFramebufferAttachmentParameteriv(
      GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &type);
    // (a packed depth-stencil texture attached as depth only, as VTK 9.1
    // attaches its own, reports its stencil bits here)
    glGetFramebufferAttachmentParameteriv(
      GL_READ_FRAMEBUFFER, attachment, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, &stencil);
  }
  if (stencil == 0 && holds(stencilAttachment))
  {
    glGetFramebufferAttachmentParameteriv(
      GL_READ_FRAMEBUFFER, stencilAttachment, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, &stencil);
  }
  if (bits == 32 && type == GL_FLOAT && stencil == 0)
  {
    return Depth32F;
  }
  if (bits == 32 && type == GL_UNSIGNED_NORMALIZED && stencil == 0)
  {
    return Depth32;
  }
  if (bits == 24)
  {
    return stencil == 8 ? Depth24Stencil8 : Depth24;
  }
  // Not one to copy: the one VTK 9.1's translucent pass allocates for this
  // window (vtkOrderIndependentTranslucentPass), which copies the target's
  // depth into it. (GetDepthBufferSize asks the bound draw framebuffer's
  // depth attachment for its size, a GL error where it has none, as in a
  // caller's colour-only framebuffer: 24 bits then.)
  if (window->GetStencilCapable())
  {
    return Depth24Stencil8;
  }
  GLint drawFramebuffer = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer);
  const bool drawHoldsDepth =
    holdsIn(GL_DRAW_FRAMEBUFFER, drawFramebuffer ? GL_DEPTH_ATTACHMENT : GL_DEPTH);
  return drawHoldsDepth && window->GetDepthBufferSize() == 32 ? Depth32 : Depth24;
}

void vtkFXRenderUtilities::FitFramebuffer(vtkSmartPointer<vtkOpenGLFramebufferObject>& framebuffer,
  vtkOpenGLRenderWindow* window, int width, int height)
{
  if (framebuffer)
  {
    int last[2] = { -1, -1 };
    framebuffer->GetLastSize(last[0], last[1]);
    if (last[0] >= 0 && (last[0] != width || last[1] != height))
    {
      Release(framebuffer, window);
    }
  }
  if (!framebuffer)
  {
    framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    framebuffer->SetContext(window);
  }
}

bool vtkFXRenderUtilities::MakeDepthOnlyFramebuffer(
  vtkSmartPointer<vtkOpenGLFramebufferObject>& framebuffer, vtkOpenGLRenderWindow* window,
  vtkTextureObject* depth)
{
  vtkOpenGLState* state = window->GetState();
  FitFramebuffer(framebuffer, window, static_cast<int>(depth->GetWidth()),
    static_cast<int>(depth->GetHeight()));
  state->PushFramebufferBindings();
  framebuffer->Bind();
  framebuffer->AddDepthAttachment(depth);
  // (through VTK: without colour buffers, complete before GL 4.1 too)
  framebuffer->DeactivateDrawBuffers();
  framebuffer->DeactivateReadBuffer();
  const bool complete = glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  state->PopFramebufferBindings();
  return complete;
}

void vtkFXRenderUtilities::ClearTargets(int targets, const float value[4])
{
  // (glClearBuffer ignores the clear colour, so vtkOpenGLState's copy of
  // it stays right)
  const float zero[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
  for (int i = 0; i < targets; ++i)
  {
    glClearBufferfv(GL_COLOR, i, i == 0 ? value : zero);
  }
}

vtkShaderProgram* vtkFXRenderUtilities::ReadyQuad(
  FullScreenQuad& quad, vtkOpenGLRenderWindow* window, const std::string& fragmentSource)
{
  // VTK's quad is a strip over the corners (1,1), (-1,1), (1,-1), (-1,-1)
  // (texture 0..1), its diagonal from (-1,1) to (1,-1); doubled and moved
  // by +1, its second triangle (-1,3), (3,-1), (-1,-1) holds the whole
  // viewport and its first lies beyond the corner (1,1). (Were the strip's
  // diagonal the other one, the quad would be split as before: TestAVSM's
  // AVSM-16 against exact comparisons would show it.)
  // At the far plane, z = w: window depth 1 exactly (the clip test keeps
  // z = w).
  const int vertexShader = (quad.OneTriangle ? 1 : 0) + (quad.AtFarPlane ? 2 : 0);
  if (!quad.Helper || quad.Source != fragmentSource || quad.BuiltVertexShader != vertexShader)
  {
    // (built only with the quad: ReadyQuad runs every frame)
    const std::string vertexSource = vertexShader == 0
      ? vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader()
      : std::string("//VTK::System::Dec\n"
                    "in vec4 ndCoordIn;\n"
                    "in vec2 texCoordIn;\n"
                    "out vec2 texCoord;\n"
                    "void main()\n"
                    "{\n") +
        (quad.OneTriangle ? "  gl_Position = vec4(2.0 * ndCoordIn.xy + 1.0, "
                          : "  gl_Position = vec4(ndCoordIn.xy, ") +
        (quad.AtFarPlane ? "1.0, 1.0);\n" : "0.0, 1.0);\n") +
        (quad.OneTriangle ? "  texCoord = 2.0 * texCoordIn;\n" : "  texCoord = texCoordIn;\n") +
        "}\n";
    quad.Helper.reset(
      new vtkOpenGLQuadHelper(window, vertexSource.c_str(), fragmentSource.c_str(), ""));
    quad.Source = fragmentSource;
    quad.BuiltVertexShader = vertexShader;
  }
  else
  {
    window->GetShaderCache()->ReadyShaderProgram(quad.Helper->Program);
  }
  if (!quad.Helper->Program || !quad.Helper->Program->GetCompiled())
  {
    vtkGenericWarningMacro("vtkFX: a full-screen shader failed to compile.");
    return nullptr;
  }
  return quad.Helper->Program;
}

void vtkFXRenderUtilities::ReleaseQuad(FullScreenQuad& quad, vtkWindow* window)
{
  if (quad.Helper)
  {
    quad.Helper->ReleaseGraphicsResources(window);
    quad.Helper.reset();
  }
  quad.Source.clear();
  quad.BuiltVertexShader = -1;
}

vtkFXRenderUtilities::RenderTargetScope::RenderTargetScope(vtkOpenGLRenderWindow* window,
  vtkSmartPointer<vtkOpenGLFramebufferObject>& framebuffer, vtkTextureObject* target)
  : RenderTargetScope(window, framebuffer, std::vector<vtkTextureObject*>{ target })
{
}

bool vtkFXRenderUtilities::IsOpenGLSupported(const char* name)
{
  if (!name)
  {
    return false;
  }
  // Answered once per driver and name: passes ask every frame, and a
  // missing extension means walking every extension string.
  const GLubyte* renderer = glGetString(GL_RENDERER);
  const GLubyte* version = glGetString(GL_VERSION);
  if (!renderer || !version)
  {
    return false; // no current context
  }
  const std::string key = std::string(reinterpret_cast<const char*>(renderer)) + '|' +
    reinterpret_cast<const char*>(version) + '|' + name;
  static std::mutex mutex;
  static std::map<std::string, bool> answers;
  std::lock_guard<std::mutex> lock(mutex);
  const auto known = answers.find(key);
  if (known != answers.end())
  {
    return known->second;
  }
  bool supported = false;
  int major = 0, minor = 0;
  if (std::sscanf(name, "GL_VERSION_%d_%d", &major, &minor) == 2)
  {
    GLint has[2] = { 0, 0 };
    glGetIntegerv(GL_MAJOR_VERSION, &has[0]);
    glGetIntegerv(GL_MINOR_VERSION, &has[1]);
    supported = has[0] > major || (has[0] == major && has[1] >= minor);
  }
  else
  {
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count && !supported; ++i)
    {
      const char* extension = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, i));
      supported = extension && std::strcmp(extension, name) == 0;
    }
  }
  answers[key] = supported;
  return supported;
}

void vtkFXRenderUtilities::ClearPendingErrors(vtkObject* caller, const char* step, bool& warned)
{
  GLenum earlier = glGetError();
  if (earlier != GL_NO_ERROR && !warned)
  {
    // (formatted apart: VTK's message stream prints std::hex as a number)
    std::ostringstream code;
    code << "0x" << std::hex << earlier;
    vtkWarningWithObjectMacro(caller, "An OpenGL error ("
        << code.str() << ") was pending before " << step
        << ": a step before it (VTK's or an effect's) failed.");
    warned = true;
  }
  for (int i = 0; i < 16 && earlier != GL_NO_ERROR; ++i)
  {
    earlier = glGetError();
  }
}

vtkFXRenderUtilities::RenderTargetScope::RenderTargetScope(vtkOpenGLRenderWindow* window,
  vtkSmartPointer<vtkOpenGLFramebufferObject>& framebuffer,
  const std::vector<vtkTextureObject*>& targets)
  : RenderTargetScope(window, framebuffer, targets, static_cast<int>(targets[0]->GetWidth()),
      static_cast<int>(targets[0]->GetHeight()))
{
}

vtkFXRenderUtilities::RenderTargetScope::RenderTargetScope(vtkOpenGLRenderWindow* window,
  vtkSmartPointer<vtkOpenGLFramebufferObject>& framebuffer, int width, int height)
  : RenderTargetScope(window, framebuffer, std::vector<vtkTextureObject*>(), width, height)
{
}

vtkFXRenderUtilities::RenderTargetScope::RenderTargetScope(vtkOpenGLRenderWindow* window,
  vtkSmartPointer<vtkOpenGLFramebufferObject>& framebuffer,
  const std::vector<vtkTextureObject*>& targets, int width, int height)
  : State(window->GetState())
  , FrameBuffer(nullptr)
  , Size{ width, height }
  , Viewport(window->GetState())
  , DepthFunc(window->GetState())
  , DepthMask(window->GetState())
  , DepthTest(window->GetState(), GL_DEPTH_TEST)
  , Blend(window->GetState(), GL_BLEND)
  , Scissor(window->GetState(), GL_SCISSOR_TEST)
{
  this->State->PushFramebufferBindings();
  FitFramebuffer(framebuffer, window, width, height);
  framebuffer->Bind();
  this->FrameBuffer = framebuffer;
  // A framebuffer without attachments takes its size from these (OpenGL
  // 4.3 or ARB_framebuffer_no_attachments; without them it stays
  // incomplete, which its users check). One with a depth attachment (the
  // masks of DrawDepthMask) has that size and needs neither.
  if (targets.empty() &&
    (IsOpenGLSupported("GL_VERSION_4_3") ||
      IsOpenGLSupported("GL_ARB_framebuffer_no_attachments")))
  {
    glFramebufferParameteri(GL_DRAW_FRAMEBUFFER, GL_FRAMEBUFFER_DEFAULT_WIDTH, width);
    glFramebufferParameteri(GL_DRAW_FRAMEBUFFER, GL_FRAMEBUFFER_DEFAULT_HEIGHT, height);
  }
  for (size_t i = 0; i < targets.size(); ++i)
  {
    framebuffer->AddColorAttachment(static_cast<unsigned int>(i), targets[i]);
  }
  framebuffer->ActivateDrawBuffers(static_cast<unsigned int>(targets.size()));
  this->State->vtkglViewport(0, 0, width, height);
  this->State->vtkglDisable(GL_DEPTH_TEST);
  this->State->vtkglDisable(GL_BLEND);
  this->State->vtkglDisable(GL_SCISSOR_TEST);
}

vtkFXRenderUtilities::RenderTargetScope::~RenderTargetScope()
{
  if (this->DepthAttached)
  {
    // (the framebuffer outlives the scope; the depth texture may not)
    this->FrameBuffer->RemoveDepthAttachment();
  }
  this->State->PopFramebufferBindings();
}

bool vtkFXRenderUtilities::DrawDepthMask(vtkOpenGLRenderWindow* window, DepthMask& mask,
  int width, int height, const std::string& fragmentShader,
  const std::function<void(vtkShaderProgram*)>& setUniforms)
{
  EnsureTexture(mask.Texture, window, width, height, Depth32F);
  if (!MakeDepthOnlyFramebuffer(mask.FrameBuffer, window, mask.Texture))
  {
    return false;
  }
  // (the scope saves and restores the framebuffer, viewport and depth
  // state; its framebuffer keeps the mask as its depth)
  RenderTargetScope target(window, mask.FrameBuffer, width, height);
  vtkShaderProgram* program = ReadyQuad(mask.Quad, window, fragmentShader);
  if (!program)
  {
    return false;
  }
  vtkOpenGLState* state = window->GetState();
  state->vtkglEnable(GL_DEPTH_TEST); // (depth is written only with the test on)
  state->vtkglDepthFunc(GL_ALWAYS);
  state->vtkglDepthMask(GL_TRUE);
  setUniforms(program);
  mask.Quad.Helper->Render();
  return true;
}

void vtkFXRenderUtilities::ReleaseDepthMask(DepthMask& mask, vtkWindow* window)
{
  ReleaseQuad(mask.Quad, window);
  Release(mask.Texture, window);
  Release(mask.FrameBuffer, window);
}

bool vtkFXRenderUtilities::CanFlagTiles(int tileSize)
{
  // The shaders are GLSL 1.50 (VTK's version line) and enable the
  // extension by name: GL 4.2 alone is not enough.
  const bool imageStores = IsOpenGLSupported("GL_ARB_shader_image_load_store");
  const bool textureClears =
    IsOpenGLSupported("GL_VERSION_4_4") || IsOpenGLSupported("GL_ARB_clear_texture");
  float pointSizes[2] = { 1.0f, 1.0f };
  glGetFloatv(GL_POINT_SIZE_RANGE, pointSizes);
  return imageStores && textureClears && pointSizes[1] >= tileSize;
}

bool vtkFXRenderUtilities::ClearTileMask(
  TilePoints& tiles, vtkOpenGLRenderWindow* window, int width, int height)
{
  const int t = tiles.TileSize;
  EnsureTexture(tiles.Mask, window, (width + t - 1) / t, (height + t - 1) / t, R8);
  if (!tiles.Mask || tiles.Mask->GetHandle() == 0)
  {
    return false;
  }
  // (Clearing it as a framebuffer's attachment made llvmpipe wait for the
  // frame's queued draws: the next G-buffer took 40 ms longer.)
  const unsigned char zero = 0;
  glClearTexImage(tiles.Mask->GetHandle(), 0, GL_RED, GL_UNSIGNED_BYTE, &zero);
  return true;
}

vtkShaderProgram* vtkFXRenderUtilities::ReadyTileProgram(
  vtkOpenGLRenderWindow* window, const std::string& fragmentShader)
{
  return window->GetShaderCache()->ReadyShaderProgram(
    vtkFXTilePointsVS, fragmentShader.c_str(), "");
}

bool vtkFXRenderUtilities::DrawTiles(TilePoints& tiles, vtkShaderProgram* program,
  vtkOpenGLRenderWindow* window, const int origin[2], const int size[2], bool flagged)
{
  if (!tiles.Points)
  {
    tiles.Points = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
  }
  // A point's square has no rule for samples on its sides, so a
  // multisampled target gets the triangle over the whole image.
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  const bool points = flagged && tiles.Mask && samples <= 1;
  program->SetUniformi("fxEveryTile", points ? 0 : 1);
  tiles.Points->Bind();
  if (!points)
  {
    glDrawArrays(GL_TRIANGLES, 0, 3);
    tiles.Points->Release();
    return false;
  }
  const int t = tiles.TileSize;
  const int count[2] = { (size[0] + t - 1) / t, (size[1] + t - 1) / t };
  const int padded[2] = { count[0] * t, count[1] * t };
  tiles.Mask->Activate();
  program->SetUniformi("fxTileMask", tiles.Mask->GetTextureUnit());
  program->SetUniformi("fxTileSize", t);
  program->SetUniformi("fxTilesPerRow", count[0]);
  program->SetUniform2i("fxPaddedSize", padded);
  // One point per tile in a viewport padded to whole tiles; the scissor
  // box is the image (within the caller's, where it has one).
  vtkOpenGLState* state = window->GetState();
  vtkOpenGLState::ScopedglViewport savedViewport(state);
  vtkOpenGLState::ScopedglScissor savedScissor(state);
  vtkOpenGLState::ScopedglEnableDisable savedScissorTest(state, GL_SCISSOR_TEST);
  float pointSize = 1.0f;
  state->vtkglGetFloatv(GL_POINT_SIZE, &pointSize);
  int box[4] = { origin[0], origin[1], origin[0] + size[0], origin[1] + size[1] };
  if (state->GetEnumState(GL_SCISSOR_TEST))
  {
    int scissor[4];
    state->vtkglGetIntegerv(GL_SCISSOR_BOX, scissor);
    box[0] = std::max(box[0], scissor[0]);
    box[1] = std::max(box[1], scissor[1]);
    box[2] = std::min(box[2], scissor[0] + scissor[2]);
    box[3] = std::min(box[3], scissor[1] + scissor[3]);
  }
  state->vtkglViewport(origin[0], origin[1], padded[0], padded[1]);
  state->vtkglScissor(box[0], box[1], std::max(box[2] - box[0], 0), std::max(box[3] - box[1], 0));
  state->vtkglEnable(GL_SCISSOR_TEST);
  // (the size the shader writes, and the one GL takes where VTK left
  // GL_PROGRAM_POINT_SIZE off)
  state->vtkglPointSize(static_cast<float>(t));
  glDrawArrays(GL_POINTS, 0, count[0] * count[1]);
  state->vtkglPointSize(pointSize);
  tiles.Mask->Deactivate();
  tiles.Points->Release();
  return true;
}

void vtkFXRenderUtilities::ReleaseTilePoints(TilePoints& tiles, vtkWindow* window)
{
  Release(tiles.Mask, window);
  if (tiles.Points)
  {
    tiles.Points->ReleaseGraphicsResources();
  }
}

bool vtkFXRenderUtilities::RenderTargetScope::SkipWhereDepthIsOne(vtkTextureObject* depth)
{
  if (!depth || static_cast<int>(depth->GetWidth()) != this->Size[0] ||
    static_cast<int>(depth->GetHeight()) != this->Size[1])
  {
    return false;
  }
  this->FrameBuffer->AddDepthAttachment(depth);
  this->DepthAttached = true;
  this->State->vtkglEnable(GL_DEPTH_TEST);
  this->State->vtkglDepthFunc(GL_GREATER);
  this->State->vtkglDepthMask(GL_FALSE);
  return true;
}

bool vtkFXRenderUtilities::RenderTargetScope::IsComplete() const
{
  return glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
}

void vtkFXRenderUtilities::BoxCorner(const double box[6], int i, double corner[3])
{
  corner[0] = box[i & 1];
  corner[1] = box[2 + ((i >> 1) & 1)];
  corner[2] = box[4 + ((i >> 2) & 1)];
}

std::string vtkFXRenderUtilities::GLSLFloat(double value)
{
  if (!std::isfinite(value))
  {
    return "0.0";
  }
  CodeStream text;
  text.precision(9);
  text << value;
  const std::string literal = text.str();
  return literal.find_first_of(".e") == std::string::npos ? literal + ".0" : literal;
}

std::vector<vtkDataObject*> vtkFXRenderUtilities::Leaves(vtkDataObject* data)
{
  std::vector<vtkDataObject*> leaves;
  if (auto* blocks = vtkCompositeDataSet::SafeDownCast(data))
  {
    vtkSmartPointer<vtkCompositeDataIterator> leaf;
    leaf.TakeReference(blocks->NewIterator());
    for (leaf->InitTraversal(); !leaf->IsDoneWithTraversal(); leaf->GoToNextItem())
    {
      leaves.push_back(leaf->GetCurrentDataObject());
    }
  }
  else if (data)
  {
    leaves.push_back(data);
  }
  return leaves;
}

namespace
{
// Adds to `box` the points of the point-gaussian actors of `prop` (see
// vtkFXRenderUtilities::GetDrawnBounds).
void AddSplatCentres(vtkProp* prop, vtkBoundingBox& box)
{
  prop->InitPathTraversal();
  while (vtkAssemblyPath* path = prop->GetNextPath())
  {
    auto* actor = vtkActor::SafeDownCast(path->GetLastNode()->GetViewProp());
    auto* splats = actor ? vtkPointGaussianMapper::SafeDownCast(actor->GetMapper()) : nullptr;
    if (!splats || (actor != prop && (!actor->GetVisibility() || !actor->GetUseBounds())))
    {
      continue;
    }
    vtkBoundingBox centres;
    for (vtkDataObject* leaf : vtkFXRenderUtilities::Leaves(splats->GetInputDataObject(0, 0)))
    {
      auto* data = vtkPolyData::SafeDownCast(leaf); // (VTK draws no other blocks)
      if (data && data->GetNumberOfPoints() > 0)
      {
        centres.AddBounds(data->GetPoints()->GetBounds());
      }
    }
    if (!centres.IsValid())
    {
      continue;
    }
    double local[6];
    centres.GetBounds(local);
    vtkMatrix4x4* matrix = vtkFXRenderUtilities::PathMatrix(prop, path);
    for (int i = 0; i < 8; ++i)
    {
      double corner[4] = { 0.0, 0.0, 0.0, 1.0 };
      vtkFXRenderUtilities::BoxCorner(local, i, corner);
      if (matrix)
      {
        matrix->MultiplyPoint(corner, corner);
        for (int a = 0; a < 3; ++a)
        {
          corner[a] /= corner[3];
        }
      }
      box.AddPoint(corner);
    }
  }
}
}

int vtkFXRenderUtilities::GetDrawnBounds(vtkProp* prop, double bounds[6])
{
  vtkMath::UninitializeBounds(bounds);
  if (auto* group = vtkPropAssembly::SafeDownCast(prop))
  {
    // Its parts' (VTK's vtkPropAssembly::GetBounds takes a part's
    // uninitialized bounds for a box).
    return GetPartsBounds(group, bounds);
  }
  const double* own = prop ? prop->GetBounds() : nullptr;
  if (!own)
  {
    return vtkProp3D::SafeDownCast(prop) ? DrawsAnywhere : DrawsNothing;
  }
  vtkBoundingBox box;
  if (vtkMath::AreBoundsInitialized(own))
  {
    box.AddBounds(own);
  }
  AddSplatCentres(prop, box);
  if (!box.IsValid())
  {
    return DrawsNothing;
  }
  box.GetBounds(bounds);
  return DrawsWithin;
}

namespace
{
// The largest scale of a point-gaussian mapper's splats (the scale array's
// largest value, or its magnitude's when the component is out of range,
// 1 where a piece lacks the array, through the scale function when there
// is one, times the scale factor).
double SplatScale(vtkPointGaussianMapper* splats)
{
  const double factor = std::fabs(splats->GetScaleFactor());
  if (!splats->GetScaleArray())
  {
    return factor;
  }
  double largest = 0.0;
  for (vtkDataObject* leaf : vtkFXRenderUtilities::Leaves(splats->GetInputDataObject(0, 0)))
  {
    auto* set = vtkDataSet::SafeDownCast(leaf);
    if (!set)
    {
      continue;
    }
    vtkDataArray* values = set->GetPointData()->GetArray(splats->GetScaleArray());
    if (!values || values->GetNumberOfTuples() == 0)
    {
      // (VTK sizes the splats of a piece without the array as 1, through
      // the scale function)
      largest = std::max(largest, set->GetNumberOfPoints() > 0 ? 1.0 : 0.0);
      continue;
    }
    const int component = splats->GetScaleArrayComponent();
    const bool one = values->GetNumberOfComponents() == 1 ||
      (component >= 0 && component < values->GetNumberOfComponents());
    const double* range = values->GetRange(one ? std::max(0, component) : -1);
    largest = std::max({ largest, std::fabs(range[0]), std::fabs(range[1]) });
  }
  if (vtkPiecewiseFunction* function = splats->GetScaleFunction())
  {
    largest = 0.0;
    for (int i = 0; i < function->GetSize(); ++i)
    {
      double node[4];
      function->GetNodeValue(i, node);
      largest = std::max(largest, std::fabs(node[1]));
    }
  }
  return largest * factor;
}

// How far along any world axis `matrix` takes a point at distance 1 from
// another: its rows' largest length (a sphere's box grows by the radius
// times row i's length along axis i, sheared or not; 1 without a matrix).
double Stretch(vtkMatrix4x4* matrix)
{
  double stretch = matrix ? 0.0 : 1.0;
  for (int r = 0; matrix && r < 3; ++r)
  {
    stretch = std::max(stretch,
      std::sqrt(matrix->GetElement(r, 0) * matrix->GetElement(r, 0) +
        matrix->GetElement(r, 1) * matrix->GetElement(r, 1) +
        matrix->GetElement(r, 2) * matrix->GetElement(r, 2)));
  }
  return stretch;
}
}

int vtkFXRenderUtilities::GetReachedBounds(vtkProp* prop, double splatReach, double bounds[6])
{
  const int kind = GetDrawnBounds(prop, bounds);
  if (kind != DrawsWithin)
  {
    return kind;
  }
  double reach = 0.0;
  prop->InitPathTraversal();
  while (vtkAssemblyPath* path = prop->GetNextPath())
  {
    vtkProp* part = path->GetLastNode()->GetViewProp();
    if (part != prop && !part->GetVisibility())
    {
      continue; // (not drawn)
    }
    double partBounds[6];
    const int partKind = part == prop ? kind : GetDrawnBounds(part, partBounds);
    if (partKind == DrawsNothing)
    {
      continue;
    }
    if (!part->GetUseBounds() || partKind == DrawsAnywhere)
    {
      vtkMath::UninitializeBounds(bounds);
      return DrawsAnywhere;
    }
    vtkActor* actor = vtkActor::SafeDownCast(part);
    if (!actor)
    {
      continue;
    }
    if (actor->GetProperty()->GetPointSize() > 1.0f || actor->GetProperty()->GetLineWidth() > 1.0f)
    {
      vtkMath::UninitializeBounds(bounds);
      return DrawsAnywhere;
    }
    if (auto* splats = vtkPointGaussianMapper::SafeDownCast(actor->GetMapper()))
    {
      const double scale = SplatScale(splats);
      const double perScale = splatReach < 0.0 ? 2.0 * splats->GetTriangleScale() : splatReach;
      reach = std::max(reach, perScale * scale * Stretch(PathMatrix(prop, path)));
    }
  }
  for (int i = 0; i < 6; ++i)
  {
    bounds[i] += i % 2 ? reach : -reach;
  }
  if (!std::all_of(bounds, bounds + 6, [](double v) { return std::isfinite(v); }))
  {
    vtkMath::UninitializeBounds(bounds);
    return DrawsAnywhere;
  }
  return DrawsWithin;
}

std::vector<vtkProp*> vtkFXRenderUtilities::GetVolumesDrawn(vtkProp* prop)
{
  if (prop->IsA("vtkLODProp3D"))
  {
    return { prop };
  }
  std::vector<vtkProp*> volumes;
  prop->InitPathTraversal();
  while (vtkAssemblyPath* path = prop->GetNextPath())
  {
    vtkProp* part = path->GetLastNode()->GetViewProp();
    if (part && part->IsA("vtkVolume") && (part == prop || part->GetVisibility()))
    {
      volumes.push_back(part);
    }
  }
  return volumes;
}

bool vtkFXRenderUtilities::KeepsEarlierDepth(vtkRenderer* renderer)
{
  return renderer->GetPreserveDepthBuffer() || !renderer->GetErase() ||
    (renderer->GetRenderWindow() && !renderer->GetRenderWindow()->GetErase());
}

int vtkFXRenderUtilities::GetPartsBounds(vtkPropAssembly* group, double bounds[6])
{
  vtkBoundingBox box;
  vtkPropCollection* parts = group->GetParts();
  vtkCollectionSimpleIterator it;
  parts->InitTraversal(it);
  while (vtkProp* part = parts->GetNextProp(it))
  {
    if (!part->GetVisibility() || !part->GetUseBounds())
    {
      continue;
    }
    double b[6];
    const int kind = GetDrawnBounds(part, b);
    if (kind == DrawsAnywhere)
    {
      vtkMath::UninitializeBounds(bounds);
      return DrawsAnywhere;
    }
    if (kind == DrawsWithin)
    {
      box.AddBounds(b);
    }
  }
  if (!box.IsValid())
  {
    return DrawsNothing;
  }
  box.GetBounds(bounds);
  return DrawsWithin;
}

void vtkFXRenderUtilities::ComputeVisiblePropBounds(vtkRenderer* renderer, double bounds[6])
{
  renderer->ComputeVisiblePropBounds(bounds);
  vtkBoundingBox box;
  if (vtkMath::AreBoundsInitialized(bounds))
  {
    box.AddBounds(bounds);
  }
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (prop->GetVisibility() && prop->GetUseBounds())
    {
      AddSplatCentres(prop, box);
    }
  }
  if (box.IsValid())
  {
    box.GetBounds(bounds);
  }
}

vtkMatrix4x4* vtkFXRenderUtilities::PathMatrix(vtkProp* prop, vtkAssemblyPath* path)
{
  vtkAssemblyNode* node = path->GetLastNode();
  vtkProp3D* part = vtkProp3D::SafeDownCast(node->GetViewProp());
  if (node->GetViewProp() == prop || !node->GetMatrix())
  {
    return part ? part->GetMatrix() : nullptr;
  }
  return node->GetMatrix();
}

int vtkFXRenderUtilities::ProjectBox(
  const double box[6], const double m[16], double ndcMin[3], double ndcMax[3])
{
  int behind = 0;
  for (int a = 0; a < 3; ++a)
  {
    ndcMin[a] = VTK_DOUBLE_MAX;
    ndcMax[a] = -VTK_DOUBLE_MAX;
  }
  for (int corner = 0; corner < 8; ++corner)
  {
    double p[3];
    BoxCorner(box, corner, p);
    const double w = m[12] * p[0] + m[13] * p[1] + m[14] * p[2] + m[15];
    if (!(w > 0.0))
    {
      ++behind;
      continue;
    }
    for (int a = 0; a < 3; ++a)
    {
      const double c = m[4 * a] * p[0] + m[4 * a + 1] * p[1] + m[4 * a + 2] * p[2] + m[4 * a + 3];
      ndcMin[a] = std::min(ndcMin[a], c / w);
      ndcMax[a] = std::max(ndcMax[a], c / w);
    }
  }
  return behind;
}

vtkFXRenderUtilities::ScissorScope::ScissorScope(
  vtkOpenGLState* state, const int rect[4], const float* clearColor)
  : Enable(state, GL_SCISSOR_TEST)
  , Box(state)
  , Clear(state)
{
  if (clearColor)
  {
    state->vtkglDisable(GL_SCISSOR_TEST);
    state->vtkglClearColor(clearColor[0], clearColor[1], clearColor[2], clearColor[3]);
    state->vtkglClear(GL_COLOR_BUFFER_BIT);
  }
  state->vtkglEnable(GL_SCISSOR_TEST);
  state->vtkglScissor(
    rect[0], rect[1], std::max(0, rect[2] - rect[0]), std::max(0, rect[3] - rect[1]));
}

vtkFXRenderUtilities::BlendOntoScope::BlendOntoScope(vtkOpenGLRenderWindow* window,
  unsigned int srcRGB, unsigned int dstRGB, unsigned int srcAlpha, unsigned int dstAlpha)
  : Blend(window->GetState(), GL_BLEND)
  , DepthTest(window->GetState(), GL_DEPTH_TEST)
  , BlendFunc(window->GetState())
  , DepthMask(window->GetState())
{
  vtkOpenGLState* state = window->GetState();
  state->vtkglEnable(GL_BLEND);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_FALSE);
  state->vtkglBlendFuncSeparate(srcRGB, dstRGB, srcAlpha, dstAlpha);
}

void vtkFXRenderUtilities::GetViewportSize(const vtkRenderState* s, int& width, int& height)
{
  // (as vtkCameraPass tells the two apart)
  if (vtkOpenGLFramebufferObject::SafeDownCast(s->GetFrameBuffer()))
  {
    int size[2];
    s->GetWindowSize(size);
    width = size[0];
    height = size[1];
  }
  else
  {
    int x, y;
    s->GetRenderer()->GetTiledSizeAndOrigin(&width, &height, &x, &y);
  }
  width = std::max(width, 1);
  height = std::max(height, 1);
}

namespace
{
// The rows of the projection matrix VTK draws `renderer` with.
const double (*ProjectionRows(vtkRenderer* renderer))[4]
{
  return renderer->GetActiveCamera()
    ->GetProjectionTransformMatrix(renderer->GetTiledAspectRatio(), -1, 1)
    ->Element;
}

bool IsParallelRow(const double row[4])
{
  return row[0] == 0.0 && row[1] == 0.0 && row[2] == 0.0 && row[3] == 1.0;
}
}

bool vtkFXRenderUtilities::ComputeParallelHalfHeight(vtkRenderer* renderer, double& halfHeight)
{
  const double (*m)[4] = ProjectionRows(renderer);
  if (!IsParallelRow(m[3]) || !(std::isfinite(m[1][1]) && m[1][1] != 0.0))
  {
    return false;
  }
  halfHeight = std::fabs(1.0 / m[1][1]);
  return true;
}

bool vtkFXRenderUtilities::ComputeViewDepthRange(vtkRenderer* renderer, double range[2])
{
  const double (*m)[4] = ProjectionRows(renderer);
  // With z = -d: perspective (last row 0, 0, -1, 0) gives z_ndc =
  // (m22 z + m23) / d, which is -1 at d = m23 / (m22 - 1) and 1 at
  // m23 / (m22 + 1); parallel (last row 0, 0, 0, 1) gives m22 z + m23, at
  // d = (1 + m23) / m22 and (m23 - 1) / m22.
  const bool perspective = m[3][0] == 0.0 && m[3][1] == 0.0 && m[3][2] == -1.0 && m[3][3] == 0.0;
  const bool parallel = IsParallelRow(m[3]);
  double nearDepth = 0.0, farDepth = 0.0;
  if (perspective)
  {
    nearDepth = m[2][3] / (m[2][2] - 1.0);
    farDepth = m[2][3] / (m[2][2] + 1.0);
  }
  else if (parallel)
  {
    nearDepth = (1.0 + m[2][3]) / m[2][2];
    farDepth = (m[2][3] - 1.0) / m[2][2];
  }
  if (!(std::isfinite(nearDepth) && std::isfinite(farDepth) && nearDepth < farDepth))
  {
    return false;
  }
  range[0] = nearDepth;
  range[1] = farDepth;
  return true;
}

void vtkFXRenderUtilities::ComputeFrustumRay(
  vtkRenderer* renderer, double origin[3][3], double direction[3][3])
{
  // VTK's projection matrix P maps view coordinates to clip coordinates
  // (row-major, acting on column vectors). Both of VTK's projections have
  // P[3] = (0,0,-1,0) (perspective) or (0,0,0,1) (parallel) and no x/y
  // coupling into z, so x and y of a point at depth d = -z solve
  //   ndc.x * w = P00 x + P01 y + P02 z + P03,  w = P32 z + P33.
  const double (*m)[4] = ProjectionRows(renderer);
  // With z = -d and w = -P32 d + P33, for each axis i (0 = x, 1 = y):
  //   P_ii * c_i = ndc_i * (P33 - P32 d) - P_i2 * (-d) - P_i3
  //   c_i = [ndc_i*P33 - P_i3] / P_ii  +  d * [P_i2 - ndc_i*P32] / P_ii
  for (int k = 0; k < 3; ++k)
  {
    for (int i = 0; i < 3; ++i)
    {
      origin[k][i] = 0.0;
      direction[k][i] = 0.0;
    }
  }
  for (int i = 0; i < 2; ++i)
  {
    const double pii = m[i][i];
    if (!(std::isfinite(pii) && pii != 0.0))
    {
      // A projection that maps the axis nowhere (a parallel camera of
      // scale 0, a singular explicit matrix): VTK draws nothing there
      // either; the rays keep that axis at 0 rather than inf or NaN.
      continue;
    }
    // constant terms
    origin[0][i] = -m[i][3] / pii;
    direction[0][i] = m[i][2] / pii;
    // ndc_i coefficient (row k = 1 + i)
    origin[1 + i][i] = m[3][3] / pii;
    direction[1 + i][i] = -m[3][2] / pii;
  }
  direction[0][2] = -1.0;
}

bool vtkFXRenderUtilities::IsRenderingTiles(vtkRenderer* renderer)
{
  vtkRenderWindow* window = renderer->GetRenderWindow();
  return window && (window->GetTileScale()[0] > 1 || window->GetTileScale()[1] > 1);
}

int vtkFXRenderUtilities::GetImageRows(vtkRenderer* renderer, int viewportRows)
{
  vtkRenderWindow* window = renderer->GetRenderWindow();
  if (!window || window->GetTileScale()[1] <= 1)
  {
    return viewportRows;
  }
  // The viewport's height in the scaled window (vtkWindow::GetSize counts
  // the tiles), in the units of `viewportRows`: those of this tile's part
  // of the viewport (more than the window's pixels inside a pass such as
  // vtkSSAAPass, which renders into a larger framebuffer).
  int tiledWidth, tiledHeight, x, y;
  renderer->GetTiledSizeAndOrigin(&tiledWidth, &tiledHeight, &x, &y);
  if (tiledHeight <= 0)
  {
    return viewportRows;
  }
  const double* viewport = renderer->GetViewport();
  const double scaledRows = (viewport[3] - viewport[1]) * window->GetSize()[1];
  const long rows = std::lround(viewportRows * scaledRows / tiledHeight);
  return static_cast<int>(std::max(1L, rows));
}

void vtkFXRenderUtilities::SetFrustumRayUniforms(vtkShaderProgram* program, vtkRenderer* renderer)
{
  double origin[3][3], direction[3][3];
  ComputeFrustumRay(renderer, origin, direction);
  float o[9], d[9];
  for (int k = 0; k < 3; ++k)
  {
    for (int i = 0; i < 3; ++i)
    {
      o[3 * k + i] = static_cast<float>(origin[k][i]);
      d[3 * k + i] = static_cast<float>(direction[k][i]);
    }
  }
  if (program->IsUniformUsed("fxRayOrigin"))
  {
    program->SetUniform3fv("fxRayOrigin", 3, reinterpret_cast<float(*)[3]>(o));
  }
  if (program->IsUniformUsed("fxRayDirection"))
  {
    program->SetUniform3fv("fxRayDirection", 3, reinterpret_cast<float(*)[3]>(d));
  }
  if (program->IsUniformUsed("fxParallelDepth"))
  {
    // (parallel or not by the matrix VTK draws with: an explicit one decides;
    // at VTK's default view angle, 30 degrees, whatever the camera's, which
    // a parallel image does not depend on)
    const double tanHalfAngle = std::tan(vtkMath::RadiansFromDegrees(15.0));
    double halfHeight = 0.0;
    program->SetUniformf("fxParallelDepth",
      ComputeParallelHalfHeight(renderer, halfHeight)
        ? static_cast<float>(halfHeight / tanHalfAngle)
        : 0.0f);
  }
}
