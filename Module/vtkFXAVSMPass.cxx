#include "vtkFXAVSMPass.h"

#include "vtkFXAVSMCapture.h"
#include "vtkFXAVSMCurves.h"
#include "vtkFXAVSMLightDepth.h"
#include "vtkFXAVSMLists.h"
#include "vtkFXAVSMLookupFS.h"
#include "vtkFXAVSMResolveFS.h"
#include "vtkFXGBufferPass.h"
#include "vtkFXRenderUtilities.h"
#include "vtkFXViewPosition.h"

#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkCamera.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDataObject.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkMapper.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPixelBufferObject.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkPointGaussianMapper.h"
#include "vtkProp.h"
#include "vtkProp3D.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkShaderProgram.h"
#include "vtkShaderProperty.h"
#include "vtkTexture.h"
#include "vtkTextureObject.h"
#include "vtkTimerLog.h"
#include "vtkTranslucentPass.h"
#include "vtkUniforms.h"
#include "vtkFXOpenGL.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <sstream>

vtkStandardNewMacro(vtkFXAVSMPass);

namespace
{
using GB = vtkFXGBufferPass;

// Shader storage blocks of vtkFXAVSMLists.glsl, bound to points 0 to 3.
const char* const BlockNames[4] = { "FXAVSMHeads", "FXAVSMNodes", "FXAVSMCounter",
  "FXAVSMCounts" };
enum Buffer
{
  HeadsBuffer = 0,
  NodesBuffer = 1,
  CounterBuffer = 2,
  CountsBuffer = 3,
  NumberOfBuffers = 4
};
const GLsizeiptr NodeBytes = 16;
// FXAVSMCounter: the node counters' fragment counts, 64 bytes apart (each
// on a cache line of its own, see vtkFXAVSMLists.glsl), then the longest
// list.
const int NodeCounters = 8; // fxAVSMNodeCounters
const int CounterStrideWords = 16;
const GLintptr LongestListOffset = NodeCounters * CounterStrideWords * 4;
const GLsizeiptr CounterBytes = LongestListOffset + 4;

// log2 of the side of the tiles that pick a fragment's node counter: 64
// pixels (llvmpipe's tiles), smaller in an atlas of fewer than four tiles
// per counter, so that a small shadow map still spreads its fragments over
// all counters (a 64^2 map in one tile would take eight slots a fragment).
int CounterTileShift(const int atlas[2])
{
  int shift = 6;
  while (shift > 0 && (atlas[0] >> shift) * (atlas[1] >> shift) < 4 * NodeCounters)
  {
    --shift;
  }
  return shift;
}
const vtkIdType MaximumCapacity = vtkIdType(1) << 27; // 2 GiB of nodes
const int MaximumListPerTexel = 64; // segments one texel's resolve inserts in order

// After the version line (which VTK puts in place of the tag): storage
// buffers in GLSL 1.50.
const char* const StorageExtension =
  "//VTK::System::Dec\n#extension GL_ARB_shader_storage_buffer_object : require\n";
// The capture's flags of the tiles the resolve runs at (image stores).
const char* const TileFlagsExtension =
  "//VTK::System::Dec\n#extension GL_ARB_shader_image_load_store : require\n";
const int ResolveTileSize = 8; // texels
// Marks the shaders this pass extended (SetShaderParameters binds for them).
const char* const CaptureMarker = "// vtkFX AVSM capture";
const char* const ReceiverMarker = "// vtkFX AVSM receiver";

bool Contains(const std::string& s, const char* what)
{
  return s.find(what) != std::string::npos;
}

// Gives the buffer bound to `target` a store of `bytes` bytes; false when
// the driver could not (GL_OUT_OF_MEMORY leaves it without one). Read from
// the buffer's size, so that no other pass's pending GL error is taken.
bool AllocateBuffer(GLenum target, vtkIdType bytes, GLenum usage)
{
  glBufferData(target, static_cast<GLsizeiptr>(bytes), nullptr, usage);
  GLint64 size = 0;
  glGetBufferParameteri64v(target, GL_BUFFER_SIZE, &size);
  return size == static_cast<GLint64>(bytes);
}

// Lights that cast: not headlights (their shadows hide behind what casts
// them) and not those whose ShadowAttenuation (VTK's per-light shadow
// strength) is 0.
bool IsCasting(vtkLight* light)
{
  return !light->LightTypeIsHeadlight() && light->GetShadowAttenuation() > 0.0f &&
    vtkFXRenderUtilities::IsLightFinite(light);
}

// Props that can dim light: all but actors of opacity 0 (not a positive
// number: NaN too) whose every fragment VTK makes fully transparent:
// scalar, texture and point-gaussian alpha only multiply the property's
// opacity. Kept, as they may draw with alpha of their own: a back-face
// property that is not transparent, composite data (block opacities) and
// shader replacements.
bool CanCast(vtkProp* prop)
{
  vtkActor* actor = vtkActor::SafeDownCast(prop);
  if (!actor || !actor->GetProperty() || actor->GetProperty()->GetOpacity() > 0.0)
  {
    return true;
  }
  vtkProperty* back = actor->GetBackfaceProperty();
  vtkShaderProperty* shaders = actor->GetShaderProperty();
  return (back && !(back->GetOpacity() <= 0.0)) ||
    // (composite data whichever mapper draws it: VTK 9.3 replaced
    // vtkCompositePolyDataMapper2 with vtkCompositePolyDataMapper)
    (actor->GetMapper() &&
      vtkCompositeDataSet::SafeDownCast(actor->GetMapper()->GetInputDataObject(0, 0))) ||
    (shaders && (shaders->GetNumberOfShaderReplacements() > 0 || shaders->HasVertexShaderCode() ||
                  shaders->HasFragmentShaderCode() || shaders->HasGeometryShaderCode()));
}

// A spot light (one perspective view of its cone) rather than a light in
// every direction (six).
bool IsSpot(vtkLight* light)
{
  return light->GetConeAngle() > 0.0 && light->GetConeAngle() < 89.0;
}

// What decides which lights cast first.
double Brightness(vtkLight* light)
{
  const double* c = light->GetDiffuseColor();
  return light->GetIntensity() * std::max(c[0], std::max(c[1], c[2]));
}


// Storage buffers, their clears, program-interface queries and memory
// barriers: all of OpenGL 4.3 (llvmpipe has 4.5).
bool StorageBuffersSupported()
{
  return vtkFXRenderUtilities::IsOpenGLSupported("GL_VERSION_4_3");
}

// Whether a geometry shader may declare the exact lists' storage blocks
// (vtkFXAVSMLists.glsl declares four): OpenGL 4.3 guarantees fragment
// shaders 8 but geometry shaders none.
bool GeometryShaderReadsLists()
{
  GLint blocks = 0;
  glGetIntegerv(GL_MAX_GEOMETRY_SHADER_STORAGE_BLOCKS, &blocks);
  return blocks >= 4;
}

// VTK's point-gaussian splats (vtkPointGaussianGS.glsl: a triangle around
// each point, facing the camera, with the offset from the centre in scale
// units): the geometry shader gets `declarations`, `once` after it computes
// `radius` (view units per scale unit), and at each corner `perCorner`
// (with the corner's `offset` at hand, before it is used), the
// fragment shader `fragmentDeclarations`, FX_SPLAT, and VTK's gaussian
// falloff kept apart from the opacity (fxSplatFalloff). False, and nothing
// changed, for other shaders.
bool ExtendSplatShaders(std::string& geometryShader, std::string& fragmentShader,
  const std::string& declarations, const std::string& once, const std::string& perCorner,
  const std::string& fragmentDeclarations)
{
  const char* const radiusSet = "float radius = radiusVCVSOutput[0]/triangleScale;";
  const char* const offsetOut = "out vec2 offsetVCGSOutput;";
  const char* const offsetSet = "offsetVCGSOutput = offset.xy/radius;";
  // The fragment shader says VSOutput: VTK renames its inputs to GSOutput
  // when it compiles them with a geometry shader.
  const char* const offsetIn = "in vec2 offsetVCVSOutput;";
  if (!Contains(geometryShader, offsetOut) || !Contains(geometryShader, offsetSet) ||
    !Contains(geometryShader, radiusSet) || !Contains(fragmentShader, offsetIn))
  {
    return false;
  }
  vtkShaderProgram::Substitute(
    geometryShader, radiusSet, std::string(radiusSet) + "\n  " + once, false);
  vtkShaderProgram::Substitute(
    geometryShader, offsetOut, std::string(offsetOut) + "\n" + declarations, false);
  vtkShaderProgram::Substitute(
    geometryShader, offsetSet, perCorner + "\n  " + offsetSet, true);
  vtkShaderProgram::Substitute(fragmentShader, offsetIn,
    std::string("#define FX_SPLAT 1\n") + offsetIn + "\nfloat fxSplatFalloff = 1.0;\n" +
      fragmentDeclarations,
    false);
  vtkShaderProgram::Substitute(fragmentShader, "opacity = opacity*gaussian;",
    "opacity = opacity*gaussian;\n  fxSplatFalloff = gaussian;", false);
  return true;
}
}

vtkFXAVSMPass::vtkFXAVSMPass()
{
  this->Stage = AfterGBuffer;
  this->DeclareOutput("visibility");
  this->CasterPass = vtkSmartPointer<vtkTranslucentPass>::New();
  this->ResolveTiles.TileSize = ResolveTileSize;
  this->StaleTiles.TileSize = ResolveTileSize;
}

vtkFXAVSMPass::~vtkFXAVSMPass()
{
  this->ReleaseBuffers();
}

int vtkFXAVSMPass::Nodes() const
{
  return this->NumberOfNodes <= 4 ? 4 : this->NumberOfNodes <= 8 ? 8 : 16;
}

bool vtkFXAVSMPass::HasWork(const vtkFXSceneInfo& scene)
{
  // Every visible translucent prop casts, also one outside the viewer's
  // frustum whose shadow falls on what the viewer sees; one of opacity 0
  // would cast nothing at the cost of the whole pass.
  this->ReusedShadowMaps = false; // (of this frame, if it runs)
  this->Casters.clear();
  std::copy_if(scene.TranslucentViewProps.begin(), scene.TranslucentViewProps.end(),
    std::back_inserter(this->Casters), CanCast);
  // Where the look-up's receivers are drawn (CullLookUp only): the props
  // the G-buffer captures (forward-drawn ones are shaded without the
  // look-up).
  this->ReceiverBounds.clear();
  this->ReceiversAnywhere = false;
  for (vtkProp* prop : scene.OpaqueProps)
  {
    if (!this->CullLookUp)
    {
      break;
    }
    std::array<double, 6> bounds;
    const int kind = vtkFXRenderUtilities::GetReachedBounds(prop, -1.0, bounds.data());
    if (kind == vtkFXRenderUtilities::DrawsAnywhere)
    {
      this->ReceiversAnywhere = true;
    }
    else if (kind == vtkFXRenderUtilities::DrawsWithin)
    {
      this->ReceiverBounds.push_back(bounds);
    }
  }
  this->CastingLights.clear();
  for (size_t i = 0; i < scene.Lights.size(); ++i)
  {
    vtkLight* light = scene.Lights[i];
    if (IsCasting(light))
    {
      CastingLight casting;
      casting.Light = light;
      casting.Index = static_cast<int>(i);
      casting.Attenuation = std::min(1.0f, light->GetShadowAttenuation());
      this->CastingLights.push_back(casting);
    }
  }
  // The brightest first; among equals, the first.
  std::stable_sort(this->CastingLights.begin(), this->CastingLights.end(),
    [](const CastingLight& a, const CastingLight& b) {
      return Brightness(a.Light) > Brightness(b.Light);
    });
  if (static_cast<int>(this->CastingLights.size()) > this->MaximumNumberOfLights)
  {
    this->CastingLights.resize(this->MaximumNumberOfLights);
  }
  // Without opaque receivers only the translucent props can receive; the
  // look-up (and the G-buffer's depth it reads) is then left out and the
  // capture need not wait for the G-buffer.
  this->OpaqueReceivers = this->Superclass::HasWork(scene);
  this->Stage = this->OpaqueReceivers ? AfterGBuffer : LightSpace;
  return !this->CastingLights.empty() && !this->Casters.empty() &&
    (this->OpaqueReceivers || this->TranslucentReceivers);
}

int vtkFXAVSMPass::GetCastingLightIndex(int k) const
{
  return (k >= 0 && k < this->GetNumberOfCastingLights()) ? this->CastingLights[k].Index : -1;
}

vtkTextureObject* vtkFXAVSMPass::GetCurveTexture(int i)
{
  return (i >= 0 && i < this->GetNumberOfCurveTextures()) ? this->Curves[i].GetPointer() : nullptr;
}

vtkTextureObject* vtkFXAVSMPass::GetResolveTileMask()
{
  return this->ResolveTilesCulled ? this->ResolveTiles.Mask.GetPointer() : nullptr;
}

double vtkFXAVSMPass::GetListBytesPerTexel() const
{
  const double texels = double(this->AtlasSize[0]) * this->AtlasSize[1];
  return texels > 0.0 ? 8.0 + 16.0 * this->StoredFragments / texels : 0.0;
}

bool vtkFXAVSMPass::GetTexelFragments(int x, int y, std::vector<double>& depths,
  std::vector<double>& opticalDepths, std::vector<double>* exitDepths)
{
  depths.clear();
  opticalDepths.clear();
  if (exitDepths)
  {
    exitDepths->clear();
  }
  const int n = this->AtlasSize[0];
  if (!this->Buffers[HeadsBuffer] || x < 0 || y < 0 || x >= n || y >= this->AtlasSize[1] ||
    vtkIdType(n) * this->AtlasSize[1] != this->BufferTexels)
  {
    return false;
  }
  GLuint node = 0xFFFFFFFFu;
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Buffers[HeadsBuffer]);
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 4 * (GLintptr(y) * n + x), 4, &node);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Buffers[NodesBuffer]);
  for (vtkIdType step = 0; node != 0xFFFFFFFFu && node < this->StoredFragments &&
       step < this->StoredFragments;
       ++step)
  {
    struct
    {
      float Depth, OpticalDepth;
      GLuint Next;
      float ExitDepth;
    } record;
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, GLintptr(node) * NodeBytes, NodeBytes, &record);
    depths.push_back(record.Depth);
    opticalDepths.push_back(record.OpticalDepth);
    if (exitDepths)
    {
      exitDepths->push_back(record.ExitDepth);
    }
    node = record.Next;
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  return true;
}

bool vtkFXAVSMPass::GetTexelCurve(
  int x, int y, std::vector<double>& depths, std::vector<double>& opticalDepths)
{
  depths.clear();
  opticalDepths.clear();
  if (this->Curves.empty() || x < 0 || y < 0 || x >= this->AtlasSize[0] ||
    y >= this->AtlasSize[1])
  {
    return false;
  }
  const bool slices = this->Representation == RegularSlices;
  for (size_t k = 0; k < this->Curves.size(); ++k)
  {
    float texel[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
    if (glGetTextureSubImage) // GL 4.5 / ARB_get_texture_sub_image: one texel
    {
      glGetTextureSubImage(this->Curves[k]->GetHandle(), 0, x, y, 0, 1, 1, 1, GL_RGBA, GL_FLOAT,
        sizeof(texel), texel);
    }
    else if (!this->ReadTexel(this->Curves[k], x, y, texel)) // the whole texture
    {
      return false;
    }
    const bool depthTexture = !slices && k < this->Curves.size() / 2;
    for (float v : texel)
    {
      (depthTexture ? depths : opticalDepths).push_back(v);
    }
  }
  return true;
}

int vtkFXAVSMPass::VisibilityFormat() const
{
  const int channels = this->VisibilityChannels();
  return channels == 1 ? vtkFXRenderUtilities::R32F
    : channels == 2    ? vtkFXRenderUtilities::RG32F
                       : vtkFXRenderUtilities::RGBA32F;
}

bool vtkFXAVSMPass::ReadTexel(vtkTextureObject* texture, int x, int y, float texel[4])
{
  vtkPixelBufferObject* pbo = texture->Download();
  if (!pbo)
  {
    return false;
  }
  const bool floats = pbo->GetType() == VTK_FLOAT;
  if (floats)
  {
    const auto* values = static_cast<const float*>(pbo->MapPackedBuffer());
    const size_t first = 4 * (static_cast<size_t>(y) * texture->GetWidth() + x);
    std::copy_n(values + first, 4, texel);
    pbo->UnmapPackedBuffer();
  }
  pbo->Delete();
  return floats;
}

bool vtkFXAVSMPass::GetLongestListTexel(int& x, int& y)
{
  const int n = this->AtlasSize[0];
  if (!this->Buffers[CountsBuffer] || n <= 0 ||
    vtkIdType(n) * this->AtlasSize[1] != this->BufferTexels)
  {
    return false;
  }
  std::vector<GLuint> counts(static_cast<size_t>(this->BufferTexels));
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Buffers[CountsBuffer]);
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, counts.size() * 4, counts.data());
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  const auto longest = std::max_element(counts.begin(), counts.end());
  if (*longest == 0)
  {
    return false;
  }
  const size_t slot = static_cast<size_t>(longest - counts.begin());
  x = static_cast<int>(slot % n);
  y = static_cast<int>(slot / n);
  return true;
}

void vtkFXAVSMPass::GetCasterDepthRange(double range[2], int view) const
{
  const bool known = view >= 0 && view < this->GetNumberOfViews();
  range[0] = known ? this->Views[view].SliceRange[0] : 0.0;
  range[1] = known ? this->Views[view].SliceRange[1] : 1.0;
}

bool vtkFXAVSMPass::GetViewOrigin(int view, int origin[2]) const
{
  if (view < 0 || view >= this->GetNumberOfViews())
  {
    return false;
  }
  origin[0] = this->Views[view].Origin[0];
  origin[1] = this->Views[view].Origin[1];
  return true;
}

unsigned int vtkFXAVSMPass::GetRequiredChannels()
{
  return this->OpaqueReceivers ? GB::ChannelBit(GB::LinearDepth) : 0u;
}

vtkFXEffectPass::Output vtkFXAVSMPass::GetOutput(const char* name)
{
  Output out;
  if (name && std::string(name) == "visibility" && this->Visibility)
  {
    out.Texture = this->Visibility;
    out.Components = this->VisibilityChannels();
    out.Format = this->VisibilityFormat();
  }
  return out;
}

std::string vtkFXAVSMPass::GetCompositeCode(int hook)
{
  switch (hook)
  {
    case Declarations:
      return "uniform sampler2D @visibility;\nuniform int @lights[4]; // casting, -1: none";
    case LightVisibility:
      // Channel k holds the k-th casting light's visibility.
      return "      for (int k = 0; k < 4; ++k)\n"
             "      {\n"
             "        if (lightIndex == @lights[k]) { lightVisibility *= texture(@visibility, texCoord)[k]; }\n"
             "      }";
    default:
      return std::string();
  }
}

void vtkFXAVSMPass::BindCompositeResources(vtkShaderProgram* program, const std::string& prefix)
{
  const bool ready = this->Visibility && !this->CastingLights.empty();
  if (ready)
  {
    this->Visibility->Activate();
    program->SetUniformi((prefix + "visibility").c_str(), this->Visibility->GetTextureUnit());
  }
  int lights[4] = { -1, -1, -1, -1 };
  for (int k = 0; ready && k < this->GetNumberOfCastingLights(); ++k)
  {
    lights[k] = this->CastingLights[k].Index;
  }
  program->SetUniform1iv((prefix + "lights").c_str(), 4, lights);
}

void vtkFXAVSMPass::UnbindCompositeResources()
{
  if (this->Visibility)
  {
    this->Visibility->Deactivate();
  }
}

void vtkFXAVSMPass::AddView(const double position[3], const double direction[3],
  vtkMatrix4x4* projection, bool perspective, const double nearFar[2])
{
  LightView view;
  view.Camera = vtkSmartPointer<vtkCamera>::New();
  view.Projection = projection;
  view.ViewToLight = vtkSmartPointer<vtkMatrix4x4>::New();
  view.Perspective = perspective;
  view.NearFar[0] = nearFar[0];
  view.NearFar[1] = nearFar[1];
  // Any up vector not along the view.
  const double up[3] = { std::fabs(direction[1]) < 0.9 ? 0.0 : 1.0,
    std::fabs(direction[1]) < 0.9 ? 1.0 : 0.0, 0.0 };
  view.Camera->SetPosition(position);
  view.Camera->SetFocalPoint(
    position[0] + direction[0], position[1] + direction[1], position[2] + direction[2]);
  view.Camera->SetViewUp(up);
  // VTK's splats face a parallel camera along its axis (not its position).
  view.Camera->SetParallelProjection(!perspective);
  view.Camera->SetExplicitProjectionTransformMatrix(projection);
  view.Camera->UseExplicitProjectionTransformMatrixOn();
  const int index = static_cast<int>(this->Views.size());
  view.Origin[0] = (index % this->AtlasColumns) * this->ShadowMapSize;
  view.Origin[1] = (index / this->AtlasColumns) * this->ShadowMapSize;
  this->Views.push_back(view);
}

void vtkFXAVSMPass::FitLightViews(vtkOpenGLRenderer* ren)
{
  // Views from each light that hold every caster and receiver (the visible
  // props' bounding sphere): along a directional light, an orthographic
  // box around it; from a spot light, the perspective view of its cone;
  // from any other positional light, the six faces of a cube.
  double bounds[6];
  vtkFXRenderUtilities::ComputeVisiblePropBounds(ren, bounds);
  // The casters' own bounds, also of those the renderer's leave out
  // (UseBounds off: a large surface kept out of ResetCamera). A view keeps
  // the sphere's width (what can be shadowed) and reaches towards the
  // light as far as a caster lies (what can shadow it): fitted to the
  // sphere alone, such a caster above the props was clipped off and cast
  // nothing; widened to hold it, the whole scene's shadows would lose
  // resolution to a surface that is mostly elsewhere.
  std::vector<std::array<double, 6>> casterBoxes;
  for (vtkProp* caster : this->Casters)
  {
    std::array<double, 6> box;
    if (vtkFXRenderUtilities::GetDrawnBounds(caster, box.data()) == vtkFXRenderUtilities::DrawsWithin)
    {
      casterBoxes.push_back(box);
    }
  }
  // The smallest distance along `axis` from `origin` to a caster's box
  // corner (+inf without casters).
  const auto nearestCaster = [&casterBoxes](const double origin[3], const double axis[3]) {
    double nearest = HUGE_VAL;
    for (const auto& box : casterBoxes)
    {
      for (int i = 0; i < 8; ++i)
      {
        double corner[3];
        vtkFXRenderUtilities::BoxCorner(box.data(), i, corner);
        const double d[3] = { corner[0] - origin[0], corner[1] - origin[1], corner[2] - origin[2] };
        nearest = std::min(nearest, vtkMath::Dot(d, axis));
      }
    }
    return nearest;
  };
  double center[3] = { 0.0, 0.0, 0.0 };
  double radius = 1.0;
  if (vtkMath::AreBoundsInitialized(bounds))
  {
    radius = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      center[a] = 0.5 * (bounds[2 * a] + bounds[2 * a + 1]);
      radius += 0.25 * (bounds[2 * a + 1] - bounds[2 * a]) * (bounds[2 * a + 1] - bounds[2 * a]);
    }
    radius = std::sqrt(radius);
    radius = (std::isfinite(radius) && radius > 0.0) ? radius : 1.0;
  }
  this->BoundingDiameter = 2.0 * radius;
  // The atlas about square: columns for the square root of the views.
  // A positional light without a cone takes one perspective view aimed at
  // the props' bounding sphere, just holding it, from where the sphere
  // fits in 90 degrees (at least sqrt 2 radii away: a cube face 70 radii
  // away held the props in 4 of its 512 texels); nearer, the six faces of
  // a cube (a wider single view would spread its texels thinner than a
  // face's); beyond 1000 radii, one orthographic view (see below).
  const auto needsCube = [&center, radius, ren](vtkLight* light) {
    if (!light->GetPositional() || IsSpot(light))
    {
      return false;
    }
    double from[3], to[3];
    vtkFXRenderUtilities::GetShadingLightFrame(ren, light, from, to);
    const double d[3] = { center[0] - from[0], center[1] - from[1], center[2] - from[2] };
    return !(vtkMath::Norm(d) >= std::sqrt(2.0) * radius);
  };
  int views = 0;
  for (const CastingLight& casting : this->CastingLights)
  {
    views += needsCube(casting.Light) ? 6 : 1;
  }
  this->AtlasColumns = std::max(1, static_cast<int>(std::ceil(std::sqrt(double(views)))));
  this->Views.clear();
  for (CastingLight& casting : this->CastingLights)
  {
    vtkLight* light = casting.Light;
    casting.FirstView = static_cast<int>(this->Views.size());
    // (where VTK shades it from: a camera light moves with the renderer's
    // user light transform)
    double from[3], to[3];
    vtkFXRenderUtilities::GetShadingLightFrame(ren, light, from, to);
    double direction[3];
    vtkMath::Subtract(to, from, direction);
    if (vtkMath::Normalize(direction) <= 0.0)
    {
      direction[0] = 0.0;
      direction[1] = 0.0;
      direction[2] = -1.0;
    }
    vtkNew<vtkMatrix4x4> p;
    p->Zero();
    const double toCenter[3] = { center[0] - from[0], center[1] - from[1], center[2] - from[2] };
    const double distance = vtkMath::Norm(toCenter);
    // A positional light farther than 1000 radii from the props casts rays
    // parallel there to within 1e-3 rad (0.06 degrees) and gets a
    // directional light's view, aimed along its line to the centre. A
    // perspective view from it could not resolve the props: their depths,
    // distance +- radius, are a few float steps apart at 1e7 radii and
    // equal at 1e8 (near = far), and well before that a spot light's cone
    // spreads its map over far more than the props.
    const bool farAway = light->GetPositional() && radius < 1e-3 * distance;
    if (!light->GetPositional() || farAway)
    {
      if (farAway)
      {
        for (int a = 0; a < 3; ++a)
        {
          direction[a] = toCenter[a] / distance;
        }
      }
      // glOrtho(-r, r, -r, r, r, r + a + r) from a + r before the centre,
      // a = r or, where a caster lies farther towards the light, its
      // distance before the centre: the square map covers the bounding
      // sphere whatever the window's aspect, and depth every caster that
      // can shadow it.
      const double ahead = std::max(radius, -nearestCaster(center, direction));
      const double back = ahead + radius;
      const double position[3] = { center[0] - back * direction[0],
        center[1] - back * direction[1], center[2] - back * direction[2] };
      const double nearFar[2] = { radius, back + radius };
      p->SetElement(0, 0, 1.0 / radius);
      p->SetElement(1, 1, 1.0 / radius);
      p->SetElement(2, 2, -2.0 / (nearFar[1] - nearFar[0]));
      p->SetElement(2, 3, -(nearFar[1] + nearFar[0]) / (nearFar[1] - nearFar[0]));
      p->SetElement(3, 3, 1.0);
      this->AddView(position, direction, p, false, nearFar);
    }
    else
    {
      // Perspective views from the light, depth from just in front of it
      // (it may sit inside the data) to the far side of the props' bounding
      // sphere. Depth is the distance along a view's axis (clip w): the
      // sphere spans the centre's axial distance plus or minus r for a spot
      // light, wherever it is aimed; for a cube face, up to the centre's
      // distance plus r.
      // A spot light outside the props' bounding sphere, whose cone is
      // wider than the sphere seen from it, gets a point light's view,
      // aimed at the sphere and fitted to it: all its cone lights of the
      // props is in that view, at the map's whole resolution. (The cone's
      // view spread the map over the cone: from 500 radii under a cone of
      // 30 degrees the props fell on two texels, and the shadows went.)
      const bool spot = IsSpot(light) &&
        !(distance > std::sqrt(2.0) * radius &&
          std::asin(std::min(radius / distance, 1.0)) <
            vtkMath::RadiansFromDegrees(light->GetConeAngle()));
      const bool cube = needsCube(light);
      if (!spot && !cube)
      {
        // aimed at the sphere's centre
        for (int a = 0; a < 3; ++a)
        {
          direction[a] = toCenter[a] / distance;
        }
      }
      const double axial = spot ? vtkMath::Dot(toCenter, direction) : distance;
      const double farPlane = std::max(axial + radius, 1e-30);
      // (nearer where a caster lies between the light and the sphere)
      const double nearPlane = std::max(
        cube ? 0.0 : std::min(axial - radius, nearestCaster(from, direction)), 1e-3 * farPlane);
      // The cone's half angle; outside the sphere, the angle under which it
      // is seen: tan = r / sqrt(d^2 - r^2); a cube face: 45 degrees.
      const double f = spot
        ? 1.0 / std::tan(vtkMath::RadiansFromDegrees(std::max(0.5, light->GetConeAngle())))
        : cube ? 1.0
               : std::sqrt(std::max(distance * distance - radius * radius, 0.0)) / radius;
      p->SetElement(0, 0, f);
      p->SetElement(1, 1, f);
      p->SetElement(2, 2, -(farPlane + nearPlane) / (farPlane - nearPlane));
      p->SetElement(2, 3, -2.0 * farPlane * nearPlane / (farPlane - nearPlane));
      p->SetElement(3, 2, -1.0);
      const double nearFar[2] = { nearPlane, farPlane };
      if (!cube)
      {
        this->AddView(from, direction, p, true, nearFar);
      }
      else
      {
        const double faces[6][3] = { { 1, 0, 0 }, { -1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 },
          { 0, 0, 1 }, { 0, 0, -1 } };
        for (const auto& face : faces)
        {
          this->AddView(from, face, p, true, nearFar);
        }
      }
    }
    casting.NumberOfViews = static_cast<int>(this->Views.size()) - casting.FirstView;
  }
  views = static_cast<int>(this->Views.size());
  this->AtlasSize[0] = std::min(views, this->AtlasColumns) * this->ShadowMapSize;
  this->AtlasSize[1] =
    ((views + this->AtlasColumns - 1) / this->AtlasColumns) * this->ShadowMapSize;
}

namespace
{
// Whether every value in [begin, end) is finite.
bool AllFinite(const double* begin, const double* end)
{
  return std::all_of(begin, end, [](double v) { return std::isfinite(v); });
}

}

void vtkFXAVSMPass::MeasureCasters()
{
  // (once a frame: the views all use them)
  this->CasterExtents.clear();
  for (vtkProp* prop : this->Casters)
  {
    CasterExtent extent;
    extent.Kind = vtkFXRenderUtilities::GetDrawnBounds(prop, extent.Bounds);
    extent.ReachKind = vtkFXRenderUtilities::GetReachedBounds(prop, this->SplatRadius, extent.Reached);
    this->CasterExtents.push_back(extent);
  }
}

void vtkFXAVSMPass::ComputeCasterDepthRange(LightView& view) const
{
  // The casters' bounds seen from the light, in light depth (0..1, see
  // vtkFXAVSMLightDepth.glsl). A box reaching behind a spot or point light
  // (the light inside the data) starts at the near plane.
  using RU = vtkFXRenderUtilities;
  double lo = 1.0, hi = 0.0;
  double* box = view.ShadowedBox;
  box[0] = box[2] = box[4] = 1.0;
  box[1] = box[3] = -1.0;
  box[5] = 1.0;
  vtkNew<vtkMatrix4x4> toClip;
  vtkMatrix4x4::Multiply4x4(view.Projection, view.Camera->GetViewTransformMatrix(), toClip);
  const auto wholeView = [box]() {
    box[0] = box[2] = box[4] = -1.0;
    box[1] = box[3] = box[5] = 1.0;
  };
  for (const CasterExtent& extent : this->CasterExtents)
  {
    if (extent.Kind == RU::DrawsNothing)
    {
      continue;
    }
    if (extent.Kind == RU::DrawsAnywhere)
    {
      // (no bounds: it may be at any depth, and shadow anything)
      lo = 0.0;
      hi = 1.0;
      wholeView();
      continue;
    }
    double ndcMin[3], ndcMax[3];
    const int behind = RU::ProjectBox(extent.Bounds, &toClip->Element[0][0], ndcMin, ndcMax);
    if (behind != 8)
    {
      lo = std::min(lo, behind > 0 ? 0.0 : LightDepthFromNDC(view, ndcMin[2]));
      hi = std::max(hi, LightDepthFromNDC(view, ndcMax[2]));
    }
    // What it can shadow: where it is drawn, from its nearest depth on; a
    // box reaching behind the light, anything in its view.
    if (extent.ReachKind != RU::DrawsWithin)
    {
      wholeView();
      continue;
    }
    const int reachedBehind =
      RU::ProjectBox(extent.Reached, &toClip->Element[0][0], ndcMin, ndcMax);
    if (reachedBehind == 8)
    {
      continue;
    }
    if (reachedBehind > 0 || !AllFinite(ndcMin, ndcMin + 3) || !AllFinite(ndcMax, ndcMax + 3))
    {
      wholeView();
      continue;
    }
    for (int a = 0; a < 3; ++a)
    {
      box[2 * a] = std::min(box[2 * a], std::max(-1.0, ndcMin[a]));
      box[2 * a + 1] = std::max(box[2 * a + 1], a == 2 ? 1.0 : std::min(1.0, ndcMax[a]));
    }
  }
  view.SliceRange[0] = static_cast<float>(std::max(0.0, std::min(lo, hi)));
  view.SliceRange[1] = static_cast<float>(std::min(1.0, std::max(lo, hi)));
}

bool vtkFXAVSMPass::EnsureBuffers(vtkOpenGLRenderWindow* window)
{
  const vtkIdType texels = vtkIdType(this->AtlasSize[0]) * this->AtlasSize[1];
  if (this->Buffers[HeadsBuffer] && this->BuffersWindow != window)
  {
    this->ReleaseBuffers(); // (made in another window's context)
  }
  if (!this->Buffers[HeadsBuffer])
  {
    glGenBuffers(NumberOfBuffers, this->Buffers);
    this->BuffersWindow = window;
    this->BufferTexels = 0;
    this->Capacity = 0;
  }
  // A buffer larger than one storage block can address would be written
  // only in part, its lists pointing at nodes the shaders never stored.
  GLint64 blockBytes = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &blockBytes);
  this->CapacityLimit =
    std::max<vtkIdType>(1, std::min<vtkIdType>(MaximumCapacity, blockBytes / NodeBytes));
  if (texels * 4 > blockBytes)
  {
    std::ostringstream message;
    message << "AVSM: the list heads of " << texels << " shadow-map texels ("
            << this->GetNumberOfViews() << " views of " << this->ShadowMapSize << "^2) need "
            << (texels * 4) / (1 << 20) << " MiB, more than one OpenGL storage block holds ("
            << blockBytes / (1 << 20) << " MiB); no shadows of translucent props (lower "
            << "ShadowMapSize).";
    this->ReportError(message.str());
    return false;
  }
  bool allocated = true;
  if (this->BufferTexels != texels)
  {
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Buffers[HeadsBuffer]);
    allocated = AllocateBuffer(GL_SHADER_STORAGE_BUFFER, texels * 4, GL_DYNAMIC_DRAW);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Buffers[CountsBuffer]);
    allocated = AllocateBuffer(GL_SHADER_STORAGE_BUFFER, texels * 4, GL_DYNAMIC_DRAW) && allocated;
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Buffers[CounterBuffer]);
    allocated = AllocateBuffer(GL_SHADER_STORAGE_BUFFER, CounterBytes, GL_DYNAMIC_READ) && allocated;
    this->BufferTexels = allocated ? texels : 0; // retried next frame
  }
  const vtkIdType wanted =
    std::max(this->Capacity, std::min(this->CapacityLimit, texels * this->InitialNodesPerTexel));
  if (allocated && wanted != this->Capacity)
  {
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Buffers[NodesBuffer]);
    allocated = AllocateBuffer(GL_SHADER_STORAGE_BUFFER, wanted * NodeBytes, GL_DYNAMIC_DRAW);
    this->Capacity = allocated ? wanted : 0;
  }
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  if (!allocated)
  {
    std::ostringstream message;
    message << "AVSM: OpenGL could not allocate the fragment lists for " << texels
            << " texels and " << wanted << " fragments (" << (wanted * NodeBytes) / (1 << 20)
            << " MiB); no shadows of translucent props until it can (lower ShadowMapSize or "
               "InitialNodesPerTexel).";
    this->ReportError(message.str());
  }
  return allocated;
}

void vtkFXAVSMPass::BindBuffers(vtkShaderProgram* program)
{
  const GLuint handle = static_cast<GLuint>(program->GetHandle());
  for (GLuint i = 0; i < NumberOfBuffers; ++i)
  {
    const GLuint block = glGetProgramResourceIndex(handle, GL_SHADER_STORAGE_BLOCK, BlockNames[i]);
    if (block != GL_INVALID_INDEX)
    {
      glShaderStorageBlockBinding(handle, block, i);
    }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, i, this->Buffers[i]);
  }
  program->SetUniform2i("fxAVSMAtlas", this->AtlasSize);
  if (program->IsUniformUsed("fxAVSMTileMask") && this->ResolveTiles.Mask)
  {
    glBindImageTexture(
      0, this->ResolveTiles.Mask->GetHandle(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R8);
    program->SetUniformi("fxAVSMTileMask", 0);
  }
  this->SetCaptureViewUniforms(program);
  if (program->IsUniformUsed("fxAVSMCapacity"))
  {
    program->SetUniformi("fxAVSMCapacity", static_cast<int>(this->Capacity));
  }
  if (program->IsUniformUsed("fxAVSMWalk"))
  {
    program->SetUniformi("fxAVSMWalk", static_cast<int>(this->LongestList));
  }
  if (program->IsUniformUsed("fxAVSMCounterTileShift"))
  {
    program->SetUniformi("fxAVSMCounterTileShift", CounterTileShift(this->AtlasSize));
  }
  if (program->IsUniformUsed("fxAVSMCountersInUse"))
  {
    program->SetUniformi("fxAVSMCountersInUse", this->CountersInUse);
  }
}

bool vtkFXAVSMPass::PreReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper*, vtkProp*)
{
  // Polygonal shaders only (they have the texture tag); after the mapper's
  // texture code, gl_FragData[0] holds the fragment's final colour.
  if (!Contains(fragmentShader, "//VTK::TCoord::Impl"))
  {
    return true;
  }
  if (this->Receiving)
  {
    // A translucent prop lit by VTK: the casting light's terms get the
    // transmittance at the fragment (filled in after VTK's light code).
    if (this->Exact)
    {
      // The exact look-up walks the lists: storage buffers here too.
      vtkShaderProgram::Substitute(fragmentShader, "//VTK::System::Dec", StorageExtension, false);
    }
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::Output::Dec",
      std::string("//VTK::Output::Dec\n") + ReceiverMarker + "\n" +
        this->CurveDefines(this->Exact) + (this->Exact ? vtkFXAVSMLists : "") + this->CurveCode(),
      false);
    vtkShaderProgram::Substitute(
      fragmentShader, "//VTK::Light::Impl", "//VTK::FXAVSMReceive::Impl\n  //VTK::Light::Impl", false);
    return true;
  }
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::System::Dec", StorageExtension, false);
  vtkShaderProgram::Substitute(
    fragmentShader, "//VTK::Output::Dec", std::string("//VTK::Output::Dec\n") + vtkFXAVSMLists, false);
  if (this->FlagResolveTiles)
  {
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::System::Dec", TileFlagsExtension, false);
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::Output::Dec",
      "//VTK::Output::Dec\n#define FX_TILE_FLAGS " + std::to_string(ResolveTileSize) +
        "\nlayout(r8) uniform writeonly image2D fxAVSMTileMask;",
      false);
  }
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::Output::Dec",
    std::string("//VTK::Output::Dec\n") + vtkFXAVSMLightDepth, false);
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::TCoord::Impl",
    std::string("//VTK::TCoord::Impl\n") + CaptureMarker + "\n" + vtkFXAVSMCapture, false);
  return true;
}

bool vtkFXAVSMPass::PostReplaceShaderValues(
  std::string&, std::string& geometryShader, std::string& fragmentShader, vtkAbstractMapper*, vtkProp*)
{
  // After VTK's own replacements: they declare the splat's offset.
  if (Contains(fragmentShader, CaptureMarker))
  {
    // The capture's chord needs the splat's scale in units of light depth
    // along the view's axis: view units, times the cosine between the
    // light ray and the axis for a perspective view (the triangle faces
    // the light there); and, in a perspective view, the splat's centre in
    // scale units, for each fragment's ray's distance from it. The
    // triangle shrinks to hold just the sphere (VTK's holds triangleScale,
    // 3 by default, scale units: some 3x the fragments).
    ExtendSplatShaders(geometryShader, fragmentShader,
      "out float fxSplatScaleGSOutput;\nout vec3 fxSplatCenterGSOutput;\n"
      "uniform float fxSplatRadius;",
      "float fxAxial = cameraParallel != 0 ? 1.0\n"
      "    : -gl_in[0].gl_Position.z / max(length(gl_in[0].gl_Position.xyz), 1e-30);",
      "offset.xy *= min(1.0, fxSplatRadius / triangleScale);\n"
      "  fxSplatScaleGSOutput = radius * fxAxial;\n"
      "  fxSplatCenterGSOutput = gl_in[0].gl_Position.xyz / max(radius, 1e-30);",
      "in float fxSplatScaleVSOutput;\nin vec3 fxSplatCenterVSOutput;\nuniform float fxSplatRadius;");
  }
  if (!this->Receiving || !Contains(fragmentShader, ReceiverMarker))
  {
    return true;
  }
  // A splat takes the brightest casting light's visibility at its centre,
  // looked up once per splat rather than per fragment: a cloud's splats
  // overlap in many layers on screen. (Exact lists where a geometry shader
  // cannot read them: splats keep their colour, as unlit shaders do, where
  // the program would fail to link and the splats vanish.)
  if (this->Exact && Contains(geometryShader, "offsetVCGSOutput") && !GeometryShaderReadsLists())
  {
    if (!this->WarnedGeometryLists)
    {
      vtkWarningMacro("This OpenGL allows geometry shaders too few storage blocks for the exact "
                      "lists: translucent splats receive no shadow in Exact mode.");
      this->WarnedGeometryLists = true;
    }
    return true;
  }
  const bool splat = ExtendSplatShaders(geometryShader, fragmentShader,
    "out float fxSplatTransmittanceGSOutput;\n" + this->CurveDefines(this->Exact) +
      (this->Exact ? vtkFXAVSMLists : "") + this->CurveCode(),
    "float fxSplatT = fxLightTransmittance(0, gl_in[0].gl_Position.xyz, vec3(0.0));",
    "fxSplatTransmittanceGSOutput = fxSplatT;", "in float fxSplatTransmittanceVSOutput;");
  if (splat && this->Exact)
  {
    vtkShaderProgram::Substitute(geometryShader, "//VTK::System::Dec", StorageExtension, false);
  }

  // VTK 9.1's per-light statements (the ones vtkShadowMapPass rewrites
  // too) take each casting light's visibility; a shader without them
  // (unlit) keeps its colour, unless it draws splats.
  std::string receive;
  for (int k = 0; k < this->GetNumberOfCastingLights(); ++k)
  {
    const std::string n = std::to_string(this->CastingLights[k].Index);
    const std::string t = "fxAVSMT" + std::to_string(k);
    const std::string diffuse = "diffuse += (df * lightColor" + n + ");";
    const std::string specular = "specular += (sf * lightColor" + n + ");";
    if (Contains(fragmentShader, diffuse.c_str()))
    {
      // (a lit shader has the fragment's normal, faced to the viewer)
      receive += "float " + t + " = fxLightTransmittance(" + std::to_string(k) +
        ", vertexVC.xyz, normalVCVSOutput);\n  ";
      vtkShaderProgram::Substitute(
        fragmentShader, diffuse, "diffuse += (df * " + t + " * lightColor" + n + ");", false);
      vtkShaderProgram::Substitute(
        fragmentShader, specular, "specular += (sf * " + t + " * lightColor" + n + ");", false);
    }
  }
  if (splat && receive.empty())
  {
    // VTK draws splats unlit (ambient plus diffuse colour, set in place of
    // the light tag): the diffuse part is taken as the brightest casting
    // light's, so the cloud shadows itself.
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::Light::Impl",
      "gl_FragData[0].rgb = ambientColor + diffuseColor * fxSplatTransmittanceVSOutput;\n"
      "  //VTK::Light::Impl",
      false);
  }
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::FXAVSMReceive::Impl", receive, false);
  return true;
}

bool vtkFXAVSMPass::GetShadesForward()
{
  return this->TranslucentReceivers;
}

void vtkFXAVSMPass::BeginForwardShading(const vtkRenderState* s)
{
  // Nothing captured this frame (no casting light, no GL 4.3, or a G-buffer
  // that could not be made, which leaves this pass out of the frame and
  // its curves from an earlier one): no shadows.
  const bool ready = this->Exact ? this->Buffers[HeadsBuffer] != 0 : !this->Curves.empty();
  if (!ready || !this->FrameReady || this->CastingLights.empty() || this->Views.empty() ||
    (this->GBuffer && !this->GBuffer->GetFrameComplete()))
  {
    return;
  }
  this->Receiving = true;
  this->ShaderStageTime.Modified(); // the translucent props' shaders change
  this->PreRender(s);
}

void vtkFXAVSMPass::EndForwardShading(const vtkRenderState* s)
{
  if (!this->Receiving)
  {
    return;
  }
  this->PostRender(s);
  this->ReleaseCurveUnits();
  for (GLuint i = 0; i < NumberOfBuffers; ++i)
  {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, i, 0); // exact mode bound the lists
  }
  this->Receiving = false;
  this->ShaderStageTime.Modified();
}

vtkMTimeType vtkFXAVSMPass::GetShaderStageMTime()
{
  return this->ShaderStageTime.GetMTime();
}

bool vtkFXAVSMPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp*, vtkOpenGLVertexArrayObject*)
{
  if (this->Receiving)
  {
    if (program->IsUniformUsed("fxViewToLight"))
    {
      this->SetCurveUniforms(program);
    }
  }
  else if (program->IsUniformUsed("fxAVSMCapacity"))
  {
    this->BindBuffers(program);
    if (program->IsUniformUsed("fxSplatRadius"))
    {
      program->SetUniformf("fxSplatRadius", static_cast<float>(this->SplatRadius));
    }
  }
  return true;
}

void vtkFXAVSMPass::Capture(const vtkRenderState* s, vtkOpenGLRenderWindow* window)
{
  vtkOpenGLRenderer* ren = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  // Empty lists, nothing counted.
  const GLuint end = 0xFFFFFFFFu;
  const GLuint zeros[CounterBytes / 4] = {};
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Buffers[HeadsBuffer]);
  glClearBufferData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &end);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Buffers[CountsBuffer]);
  glClearBufferData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, zeros);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Buffers[CounterBuffer]);
  glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, CounterBytes, zeros);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  // The tiles the last resolve wrote become stale: this frame's resolve
  // empties them (their mask kept), and the capture flags its own in the
  // other mask.
  this->CurvesEmptyOutsideStale = this->ResolveTilesCulled && this->CurvesEmptyOutsideResolved;
  if (this->CurvesEmptyOutsideStale)
  {
    std::swap(this->StaleTiles.Mask, this->ResolveTiles.Mask);
  }
  this->CurvesEmptyOutsideResolved = false; // (until a resolve says so)
  // The capture flags the tiles that get lists, and the resolve runs
  // there only (exact lists have no resolve: no flags).
  const bool flag = !this->Exact && this->CullResolveTiles &&
    vtkFXRenderUtilities::CanFlagTiles(ResolveTileSize) &&
    vtkFXRenderUtilities::ClearTileMask(
      this->ResolveTiles, window, this->AtlasSize[0], this->AtlasSize[1]);
  if (!flag)
  {
    vtkFXRenderUtilities::Release(this->ResolveTiles.Mask, window);
  }
  this->ResolveTilesCulled = false; // (until a resolve draws them)
  if (flag != this->FlagResolveTiles)
  {
    this->FlagResolveTiles = flag;
    this->ShaderStageTime.Modified(); // the casters' shaders change
  }

  {
    // Every fragment counts: no depth test, no culling by depth; nothing
    // is drawn (the capture discards), so the framebuffer has no
    // attachment, only the atlas's size (GL 4.3's default width and
    // height): no texture nobody reads. Each view renders into its square
    // of the atlas (the viewport), from its camera.
    vtkFXRenderUtilities::RenderTargetScope target(
      window, this->CaptureFrameBuffer, this->AtlasSize[0], this->AtlasSize[1]);
    vtkOpenGLState::ScopedglDepthMask depthMask(window->GetState());
    window->GetState()->vtkglDepthMask(GL_FALSE);
    // The scissor box keeps each view's fragments in its square: a point
    // wider than a pixel (GL clips points by their centre) or a line
    // could reach the next view's (the scope restores the test's switch).
    vtkOpenGLState::ScopedglScissor scissor(window->GetState());
    window->GetState()->vtkglEnable(GL_SCISSOR_TEST);
    vtkCamera* viewer = ren->GetActiveCamera();
    viewer->Register(this);
    vtkRenderState state(ren);
    state.SetPropArrayAndCount(this->Casters.data(), static_cast<int>(this->Casters.size()));
    state.SetFrameBuffer(this->CaptureFrameBuffer);
    this->PreRender(&state);
    for (int v = 0; v < this->GetNumberOfViews(); ++v)
    {
      this->CaptureView = v;
      const LightView& view = this->Views[v];
      window->GetState()->vtkglViewport(
        view.Origin[0], view.Origin[1], this->ShadowMapSize, this->ShadowMapSize);
      window->GetState()->vtkglScissor(
        view.Origin[0], view.Origin[1], this->ShadowMapSize, this->ShadowMapSize);
      ren->SetActiveCamera(view.Camera);
      this->CasterPass->Render(&state);
    }
    this->PostRender(&state);
    ren->SetActiveCamera(viewer);
    viewer->UnRegister(this);
  }
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R8);
  // (the resolve reads the tile flags; the next capture clears them)
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT |
    GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);

  GLuint counters[CounterBytes / 4] = {};
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Buffers[CounterBuffer]);
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, CounterBytes, counters);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  const int n = this->CountersInUse;
  vtkIdType counted = 0;
  this->UsedSlots = 0;
  for (int k = 0; k < n; ++k)
  {
    // Counter k hands out slots k, k + n, k + 2n, ...
    const vtkIdType taken = counters[k * CounterStrideWords];
    counted += taken;
    this->UsedSlots = std::max(this->UsedSlots, taken > 0 ? n * (taken - 1) + k + 1 : 0);
  }
  this->CapturedFragments = counted;
  this->ChooseNodeCounters();
  // llvmpipe stops a shader's loops after some 65535 iterations in all:
  // the exact look-up's walks (four bilinear taps per casting light) stay
  // within 30000 steps (a deep shadow of more surfaces than that on one
  // texel is dark enough anyway).
  this->LongestList = std::min<vtkIdType>(counters[LongestListOffset / 4],
    30000 / (4 * std::max(1, this->GetNumberOfCastingLights())));
  if (this->UsedSlots > this->Capacity)
  {
    if (!this->WarnedOverflow)
    {
      vtkWarningMacro("AVSM capture: " << counted << " fragments took "
                                       << this->UsedSlots << " list slots of a buffer of "
                                       << this->Capacity
                                       << "; the extra ones are left out of this frame and "
                                          "the buffer grows for the next.");
      this->WarnedOverflow = true;
    }
    const vtkIdType grown =
      std::min(this->CapacityLimit, this->UsedSlots + this->UsedSlots / 4);
    this->StoredFragments = this->Capacity; // what this frame's lists hold
    if (grown <= this->Capacity)
    {
      return; // at the largest size already: nothing to grow (nor to copy)
    }
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, this->Buffers[NodesBuffer]);
    // Keep this frame's nodes: the resolve still reads them.
    GLuint bigger = 0;
    glGenBuffers(1, &bigger);
    glBindBuffer(GL_COPY_WRITE_BUFFER, bigger);
    if (AllocateBuffer(GL_COPY_WRITE_BUFFER, grown * NodeBytes, GL_DYNAMIC_DRAW))
    {
      glCopyBufferSubData(
        GL_SHADER_STORAGE_BUFFER, GL_COPY_WRITE_BUFFER, 0, 0, this->Capacity * NodeBytes);
      glDeleteBuffers(1, &this->Buffers[NodesBuffer]);
      this->Buffers[NodesBuffer] = bigger;
      this->Capacity = grown;
    }
    else
    {
      // The lists keep their size: later frames drop fragments too (their
      // shadows lighter), never write past the buffer.
      glDeleteBuffers(1, &bigger);
      std::ostringstream message;
      message << "AVSM: OpenGL could not grow the fragment lists to " << grown << " fragments ("
              << (grown * NodeBytes) / (1 << 20) << " MiB); fragments beyond " << this->Capacity
              << " stay left out.";
      this->ReportError(message.str());
    }
    glBindBuffer(GL_COPY_WRITE_BUFFER, 0);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  }
}

void vtkFXAVSMPass::ChooseNodeCounters()
{
  // Fragments crowded into few tiles crowd into few counters, and the
  // slots then span up to eight times the fragments (one tile of a 64
  // x 64-pixel shadow map, a small caster in a large map): such captures
  // go back to one counter, and eight are tried again after a while.
  const int retryAfter = 64; // captures
  if (this->CountersInUse > 1 && this->UsedSlots > 2 * this->CapturedFragments + 64)
  {
    this->CountersInUse = 1;
    this->CapturesSinceCountersChosen = 0;
  }
  else if (this->CountersInUse == 1 && ++this->CapturesSinceCountersChosen >= retryAfter)
  {
    this->CountersInUse = NodeCounters;
  }
}

bool vtkFXAVSMPass::Resolve(vtkOpenGLRenderWindow* window)
{
  const int nodes = this->Nodes();
  const int targets = nodes / 2;
  if (static_cast<int>(this->Curves.size()) != targets)
  {
    for (auto& t : this->Curves)
    {
      vtkFXRenderUtilities::Release(t, window);
    }
    this->Curves.assign(targets, nullptr);
    vtkFXRenderUtilities::Release(this->ResolveFrameBuffer, window);
  }
  bool allocated = false;
  for (auto& t : this->Curves)
  {
    allocated = vtkFXRenderUtilities::EnsureTexture(t, window, this->AtlasSize[0],
                  this->AtlasSize[1], vtkFXRenderUtilities::RGBA32F) ||
      allocated;
  }
  vtkFXRenderUtilities::CodeStream defines;
  const bool slices = this->Representation == RegularSlices;
  // (the empty curve differs between the representations: slices are 0,
  // adaptive nodes' depths 3e38)
  if (allocated || slices != this->CurvesHoldSlices)
  {
    this->CurvesEmptyOutsideStale = false;
  }
  this->CurvesHoldSlices = slices;
  defines << StorageExtension << "#define FX_NODES " << nodes << "\n#define FX_MAX_LIST "
          << MaximumListPerTexel << "\n#define FX_SLICES " << (slices ? 2 * nodes : 0)
          << "\n#define FX_VIEWS " << this->GetNumberOfViews() << "\n#define FX_ATLAS_COLUMNS "
          << this->AtlasColumns << "\n";
  vtkFXRenderUtilities::CodeStream sliceOutput;
  for (int k = 0; k < nodes / 2; ++k)
  {
    sliceOutput << "  gl_FragData[" << k << "] = vec4(bins[" << 4 * k << "], bins[" << 4 * k + 1
                << "], bins[" << 4 * k + 2 << "], bins[" << 4 * k + 3 << "]);\n";
  }
  vtkFXRenderUtilities::CodeStream output;
  for (int k = 0; k < nodes / 4; ++k)
  {
    output << "  gl_FragData[" << k << "] = vec4(fxZ[" << 4 * k << "], fxZ[" << 4 * k + 1
           << "], fxZ[" << 4 * k + 2 << "], fxZ[" << 4 * k + 3 << "]);\n";
  }
  for (int k = 0; k < nodes / 4; ++k)
  {
    output << "  gl_FragData[" << nodes / 4 + k << "] = vec4(fxTau[" << 4 * k << "], fxTau["
           << 4 * k + 1 << "], fxTau[" << 4 * k + 2 << "], fxTau[" << 4 * k + 3 << "]);\n";
  }
  // A texel without fragments (the shader's, or the clear's outside the
  // flagged tiles): AVSM depths 3e38, optical depths 0.
  const auto emptyValue = [nodes, slices](int target) {
    return target < nodes / 4 && !slices ? 3e38f : 0.0f;
  };
  vtkFXRenderUtilities::CodeStream empty;
  for (int k = 0; k < targets; ++k)
  {
    empty << "    gl_FragData[" << k << "] = vec4(" << emptyValue(k) << ");\n";
  }
  std::string fs = vtkFXAVSMResolveFS;
  vtkShaderProgram::Substitute(fs, "//VTK::FXAVSMResolve::Empty", empty.str(), false);
  vtkShaderProgram::Substitute(fs, "//VTK::System::Dec", defines.str(), false);
  vtkShaderProgram::Substitute(fs, "//VTK::FXAVSMLists::Dec", vtkFXAVSMLists, false);
  vtkShaderProgram::Substitute(fs, "//VTK::FXAVSMResolve::Output", output.str(), false);
  vtkShaderProgram::Substitute(fs, "//VTK::FXAVSMResolve::SliceOutput", sliceOutput.str(), false);

  std::vector<vtkTextureObject*> targetList;
  for (auto& t : this->Curves)
  {
    targetList.push_back(t);
  }
  vtkFXRenderUtilities::RenderTargetScope target(window, this->ResolveFrameBuffer, targetList);
  if (!target.IsComplete())
  {
    return false;
  }
  const int origin[2] = { 0, 0 };
  if (this->FlagResolveTiles && !this->EmptyStaleTiles(window, empty.str(), origin))
  {
    // Texels of tiles without lists keep the empty curve the clear gives.
    for (int k = 0; k < targets; ++k)
    {
      const float value[4] = { emptyValue(k), emptyValue(k), emptyValue(k), emptyValue(k) };
      glClearBufferfv(GL_COLOR, k, value);
    }
  }
  if (vtkShaderProgram* program = vtkFXRenderUtilities::ReadyTileProgram(window, fs))
  {
    this->BindBuffers(program);
    program->SetUniformi("fxAVSMCapacity", static_cast<int>(this->StoredFragments));
    this->SetViewUniforms(program);
    this->ResolveTilesCulled = vtkFXRenderUtilities::DrawTiles(
      this->ResolveTiles, program, window, origin, this->AtlasSize, this->FlagResolveTiles);
    // Outside the tiles just drawn the curves are empty: cleared, or
    // emptied tile by tile since.
    this->CurvesEmptyOutsideResolved = this->ResolveTilesCulled;
  }
  return true;
}

bool vtkFXAVSMPass::EmptyStaleTiles(
  vtkOpenGLRenderWindow* window, const std::string& emptyOutput, const int origin[2])
{
  if (!this->CurvesEmptyOutsideStale || !this->StaleTiles.Mask ||
    !vtkFXRenderUtilities::CanFlagTiles(ResolveTileSize))
  {
    return false;
  }
  const std::string fs =
    "//VTK::System::Dec\n//VTK::Output::Dec\nvoid main()\n{\n" + emptyOutput + "}\n";
  vtkShaderProgram* program = vtkFXRenderUtilities::ReadyTileProgram(window, fs);
  if (!program)
  {
    return false;
  }
  // (points over the stale tiles, or where DrawTiles cannot draw points,
  // one triangle over the whole map: emptied either way)
  vtkFXRenderUtilities::DrawTiles(this->StaleTiles, program, window, origin, this->AtlasSize, true);
  return true;
}

std::string vtkFXAVSMPass::CurveDefines(bool exact) const
{
  const int nodes = this->Nodes();
  vtkFXRenderUtilities::CodeStream defines;
  defines << "#define FX_EXACT " << (exact ? 1 : 0) << "\n#define FX_BILINEAR "
          << (this->Bilinear ? 1 : 0) << "\n#define FX_NODES " << nodes << "\n#define FX_SLICES "
          << (this->Representation == RegularSlices && !exact ? 2 * nodes : 0)
          << "\n#define FX_VIEWS " << std::max(1, this->GetNumberOfViews())
          << "\n#define FX_LIGHTS " << std::max(1, this->GetNumberOfCastingLights()) << "\n";
  return defines.str();
}

std::string vtkFXAVSMPass::CurveCode() const
{
  // vtkFXAVSMCurves.glsl with the curve textures' samplers and reads.
  const int nodes = this->Nodes();
  vtkFXRenderUtilities::CodeStream samplers, fetch, sliceFetch;
  for (int k = 0; k < nodes / 2; ++k)
  {
    samplers << "uniform sampler2D fxAVSMCurve" << k << ";\n";
    fetch << "  vec4 curve" << k << " = texelFetch(fxAVSMCurve" << k << ", texel, 0);\n";
    sliceFetch << "  vec4 curve" << k << " = texelFetch(fxAVSMCurve" << k << ", texel, 0);\n";
    for (int i = 0; i < 4; ++i)
    {
      sliceFetch << "  c[" << 4 * k + i << "] = curve" << k << "." << "xyzw"[i] << ";\n";
    }
    if (k == 0)
    {
      // At or in front of the texel's first node (or an empty texel, most
      // of the map): unshadowed, after one read instead of nodes / 2.
      fetch << "  if (!(depth > curve0.x))\n  {\n    return 0.0;\n  }\n";
    }
  }
  for (int i = 0; i < nodes; ++i)
  {
    const char c = "xyzw"[i % 4];
    fetch << "  z[" << i << "] = curve" << i / 4 << "." << c << ";\n";
    fetch << "  tau[" << i << "] = curve" << nodes / 4 + i / 4 << "." << c << ";\n";
  }
  std::string code = vtkFXAVSMCurves;
  vtkShaderProgram::Substitute(code, "//VTK::FXAVSMLightDepth::Dec", vtkFXAVSMLightDepth, false);
  vtkShaderProgram::Substitute(code, "//VTK::FXAVSMLookup::Samplers", samplers.str(), false);
  vtkShaderProgram::Substitute(code, "//VTK::FXAVSMLookup::Fetch", fetch.str(), false);
  vtkShaderProgram::Substitute(code, "//VTK::FXAVSMLookup::SliceFetch", sliceFetch.str(), false);
  return code;
}

void vtkFXAVSMPass::SetCaptureViewUniforms(vtkShaderProgram* program)
{
  if (program->IsUniformUsed("fxAVSMPerspective") && this->CaptureView < this->GetNumberOfViews())
  {
    const LightView& view = this->Views[this->CaptureView];
    program->SetUniformi("fxAVSMPerspective", view.Perspective ? 1 : 0);
    const float nearFar[2] = { static_cast<float>(view.NearFar[0]),
      static_cast<float>(view.NearFar[1]) };
    program->SetUniform2f("fxAVSMNearFar", nearFar);
  }
}

double vtkFXAVSMPass::LightDepthFromNDC(const LightView& view, double ndcZ)
{
  if (!view.Perspective)
  {
    return 0.5 * ndcZ + 0.5;
  }
  const double n = view.NearFar[0], f = view.NearFar[1];
  const double distance = 2.0 * n * f / (f + n - ndcZ * (f - n));
  return (distance - n) / (f - n);
}

void vtkFXAVSMPass::SetViewUniforms(vtkShaderProgram* program)
{
  // The views' and lights' arrays of vtkFXAVSMCurves.glsl (and the slice
  // ranges of the resolve); unused names are skipped by VTK.
  const int views = this->GetNumberOfViews();
  std::vector<float> toLight(16 * views), nearFar(2 * views), ranges(2 * views),
    origins(2 * views);
  std::vector<int> perspective(views);
  for (int v = 0; v < views; ++v)
  {
    const LightView& view = this->Views[v];
    // Column-major for glUniformMatrix4fv.
    for (int row = 0; row < 4; ++row)
    {
      for (int column = 0; column < 4; ++column)
      {
        toLight[16 * v + 4 * column + row] = static_cast<float>(view.ViewToLight->GetElement(row, column));
      }
    }
    for (int i = 0; i < 2; ++i)
    {
      nearFar[2 * v + i] = static_cast<float>(view.NearFar[i]);
      ranges[2 * v + i] = view.SliceRange[i];
      origins[2 * v + i] = static_cast<float>(view.Origin[i]);
    }
    perspective[v] = view.Perspective ? 1 : 0;
  }
  program->SetUniformi("fxViewSize", this->ShadowMapSize);
  program->SetUniform2fv("fxViewSliceRange", views, ranges.data());
  if (!program->IsUniformUsed("fxViewToLight"))
  {
    return; // the resolve
  }
  program->SetUniformMatrix4x4v("fxViewToLight", views, toLight.data());
  program->SetUniform2fv("fxViewNearFar", views, nearFar.data());
  // Bias is a fraction of the props' diameter: per view, in its light
  // depth (0..1 over the view's depth range).
  std::vector<float> biases(views);
  for (int v = 0; v < views; ++v)
  {
    const double range = this->Views[v].NearFar[1] - this->Views[v].NearFar[0];
    biases[v] = static_cast<float>(range > 0.0 ? this->Bias * this->BoundingDiameter / range : 0.0);
  }
  program->SetUniform1fv("fxViewBias", views, biases.data());
  program->SetUniform1iv("fxViewPerspective", views, perspective.data());
  program->SetUniform2fv("fxViewOrigin", views, origins.data());
  const int lights = this->GetNumberOfCastingLights();
  std::vector<int> first(lights), count(lights);
  std::vector<float> attenuation(lights);
  for (int k = 0; k < lights; ++k)
  {
    first[k] = this->CastingLights[k].FirstView;
    count[k] = this->CastingLights[k].NumberOfViews;
    attenuation[k] = this->CastingLights[k].Attenuation;
  }
  program->SetUniform1iv("fxLightFirstView", lights, first.data());
  program->SetUniform1iv("fxLightViewCount", lights, count.data());
  program->SetUniform1fv("fxLightAttenuation", lights, attenuation.data());
}

void vtkFXAVSMPass::SetCurveUniforms(vtkShaderProgram* program)
{
  this->SetViewUniforms(program);
  if (this->Exact)
  {
    this->BindBuffers(program);
    program->SetUniformi("fxAVSMCapacity", static_cast<int>(this->StoredFragments));
    return;
  }
  for (size_t k = 0; k < this->Curves.size(); ++k)
  {
    this->Curves[k]->Activate();
    program->SetUniformi(
      ("fxAVSMCurve" + std::to_string(k)).c_str(), this->Curves[k]->GetTextureUnit());
  }
}

void vtkFXAVSMPass::ReleaseCurveUnits()
{
  for (auto& t : this->Curves)
  {
    t->Deactivate();
  }
}

void vtkFXAVSMPass::ComputeViewToLight(vtkOpenGLRenderer* ren)
{
  // For each light view: the viewer's view -> world -> light view -> light
  // clip (the look-up's, kept for the translucent step).
  vtkNew<vtkMatrix4x4> worldFromView;
  worldFromView->DeepCopy(ren->GetActiveCamera()->GetViewTransformMatrix());
  worldFromView->Invert();
  for (LightView& view : this->Views)
  {
    vtkNew<vtkMatrix4x4> viewToLightView;
    vtkMatrix4x4::Multiply4x4(view.Camera->GetViewTransformMatrix(), worldFromView, viewToLightView);
    vtkMatrix4x4::Multiply4x4(view.Projection, viewToLightView, view.ViewToLight);
  }
}

namespace
{
using Point = std::array<double, 3>;
using Polygon = std::vector<Point>;
using Plane = std::array<double, 4>; // inside: a x + b y + c z + d >= 0

double Side(const Plane& plane, const Point& p)
{
  return plane[0] * p[0] + plane[1] * p[1] + plane[2] * p[2] + plane[3];
}

// Sutherland and Hodgman's clip of a convex polygon by a half-space.
Polygon ClipPolygon(const Polygon& polygon, const Plane& plane)
{
  Polygon kept;
  for (size_t i = 0; i < polygon.size(); ++i)
  {
    const Point& a = polygon[i];
    const Point& b = polygon[(i + 1) % polygon.size()];
    const double sa = Side(plane, a);
    const double sb = Side(plane, b);
    if (sa >= 0.0)
    {
      kept.push_back(a);
    }
    if ((sa >= 0.0) != (sb >= 0.0))
    {
      const double t = sa / (sa - sb);
      kept.push_back({ a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2]) });
    }
  }
  return kept;
}

// The six faces of a box given by its corners (corner i at x = i & 1,
// y = (i >> 1) & 1, z = (i >> 2) & 1), each in order around it.
std::vector<Polygon> BoxFaces(const Point corners[8])
{
  static const int faces[6][4] = { { 0, 2, 6, 4 }, { 1, 3, 7, 5 }, { 0, 1, 5, 4 }, { 2, 3, 7, 6 },
    { 0, 1, 3, 2 }, { 4, 5, 7, 6 } };
  std::vector<Polygon> polygons;
  for (const auto& face : faces)
  {
    polygons.push_back({ corners[face[0]], corners[face[1]], corners[face[2]], corners[face[3]] });
  }
  return polygons;
}

// The corners of the intersection of two convex bodies, each given by its
// faces and the half-spaces that bound it: every face of one clipped by the
// other's half-spaces.
void AddIntersectionCorners(const std::vector<Polygon>& facesA, const std::vector<Plane>& planesA,
  const std::vector<Polygon>& facesB, const std::vector<Plane>& planesB, std::vector<Point>& corners)
{
  const auto clipAll = [&corners](const std::vector<Polygon>& faces, const std::vector<Plane>& planes) {
    for (Polygon polygon : faces)
    {
      for (const Plane& plane : planes)
      {
        polygon = ClipPolygon(polygon, plane);
      }
      corners.insert(corners.end(), polygon.begin(), polygon.end());
    }
  };
  clipAll(facesA, planesB);
  clipAll(facesB, planesA);
}
}

void vtkFXAVSMPass::ComputeShadowedPixels(
  vtkOpenGLRenderer* ren, int width, int height, int rect[4]) const
{
  // Each view's ShadowedBox, wider by two texels (a bilinear look-up reads
  // up to a texel from its point, also just outside a view) and deep to
  // the farthest receiver (past the view's far plane a curve's last value
  // holds), in world coordinates, cut by each receiver's bounds (a tilted
  // ground would otherwise carry the box down to its lowest corner), then
  // seen by the viewer: the pieces' corners bound their image, unless one
  // reaches the viewer's plane. (Props drawn past what their bounds say
  // made the box the whole view, or set ReceiversAnywhere: vtkFXRenderUtilities::GetReachedBounds.)
  rect[0] = rect[1] = 0;
  rect[2] = width;
  rect[3] = height;
  if (this->ReceiversAnywhere)
  {
    return;
  }
  vtkCamera* camera = ren->GetActiveCamera();
  vtkNew<vtkMatrix4x4> worldToViewer;
  vtkMatrix4x4::Multiply4x4(
    camera->GetProjectionTransformMatrix(ren->GetTiledAspectRatio(), -1.0, 1.0),
    camera->GetViewTransformMatrix(), worldToViewer);
  std::vector<Point> corners;
  for (const LightView& view : this->Views)
  {
    const double* box = view.ShadowedBox;
    if (!(box[0] <= box[1] && box[2] <= box[3] && box[4] <= box[5]))
    {
      continue; // no caster in its view
    }
    vtkNew<vtkMatrix4x4> worldToLight;
    vtkMatrix4x4::Multiply4x4(view.Projection, view.Camera->GetViewTransformMatrix(), worldToLight);
    double farthest = box[5];
    for (const auto& b : this->ReceiverBounds)
    {
      double ndcMin[3], ndcMax[3];
      if (vtkFXRenderUtilities::ProjectBox(b.data(), &worldToLight->Element[0][0], ndcMin, ndcMax) < 8)
      {
        farthest = std::max(farthest, ndcMax[2]);
      }
    }
    if (!std::isfinite(farthest))
    {
      return;
    }
    const double margin = 2.0 * 2.0 / this->ShadowMapSize;
    const double region[6] = { box[0] - margin, box[1] + margin, box[2] - margin,
      box[3] + margin, box[4], farthest };
    vtkNew<vtkMatrix4x4> lightToWorld;
    vtkMatrix4x4::Invert(worldToLight, lightToWorld);
    // Its corners (in front of the light: w > 0) and bounding planes:
    // x >= x0 w is (row 0 - x0 row 3) . (p, 1) >= 0, and so on.
    Point prism[8];
    for (int i = 0; i < 8; ++i)
    {
      double p[4] = { 0.0, 0.0, 0.0, 1.0 };
      vtkFXRenderUtilities::BoxCorner(region, i, p);
      lightToWorld->MultiplyPoint(p, p);
      prism[i] = { p[0] / p[3], p[1] / p[3], p[2] / p[3] };
      if (!(p[3] > 0.0) || !AllFinite(prism[i].data(), prism[i].data() + 3))
      {
        return; // a receiver about as far as the light's depth reaches (w about 0)
      }
    }
    std::vector<Plane> prismPlanes;
    for (int a = 0; a < 3; ++a)
    {
      for (int end = 0; end < 2; ++end)
      {
        const double sign = end == 0 ? 1.0 : -1.0;
        Plane plane;
        for (int c = 0; c < 4; ++c)
        {
          plane[c] =
            sign * (worldToLight->GetElement(a, c) - region[2 * a + end] * worldToLight->GetElement(3, c));
        }
        prismPlanes.push_back(plane);
      }
    }
    const std::vector<Polygon> prismFaces = BoxFaces(prism);
    for (const auto& b : this->ReceiverBounds)
    {
      Point receiver[8];
      for (int i = 0; i < 8; ++i)
      {
        vtkFXRenderUtilities::BoxCorner(b.data(), i, receiver[i].data());
      }
      const std::vector<Plane> receiverPlanes = { { 1, 0, 0, -b[0] }, { -1, 0, 0, b[1] },
        { 0, 1, 0, -b[2] }, { 0, -1, 0, b[3] }, { 0, 0, 1, -b[4] }, { 0, 0, -1, b[5] } };
      AddIntersectionCorners(prismFaces, prismPlanes, BoxFaces(receiver), receiverPlanes, corners);
    }
  }
  // (one pixel more on each side for the rounding)
  const auto pixel = [](double ndc, int size, bool up) {
    const double at = 0.5 * (std::min(std::max(ndc, -2.0), 2.0) + 1.0) * size;
    return up ? static_cast<int>(std::ceil(at)) + 1 : static_cast<int>(std::floor(at)) - 1;
  };
  int image[4] = { width, height, 0, 0 };
  for (const Point& corner : corners)
  {
    double p[4] = { corner[0], corner[1], corner[2], 1.0 };
    worldToViewer->MultiplyPoint(p, p);
    const double x = p[0] / p[3];
    const double y = p[1] / p[3];
    if (!(p[3] > 0.0) || !std::isfinite(x) || !std::isfinite(y))
    {
      return; // at or behind the viewer's plane: anywhere on the screen
    }
    image[0] = std::min(image[0], std::max(0, pixel(x, width, false)));
    image[1] = std::min(image[1], std::max(0, pixel(y, height, false)));
    image[2] = std::max(image[2], std::min(width, pixel(x, width, true)));
    image[3] = std::max(image[3], std::min(height, pixel(y, height, true)));
  }
  std::copy(image, image + 4, rect);
}

bool vtkFXAVSMPass::LookUp(vtkOpenGLRenderer* ren, vtkOpenGLRenderWindow* window)
{
  vtkTextureObject* depth = this->GBuffer->GetChannelTexture(GB::LinearDepth);
  vtkFXRenderUtilities::EnsureTexture(this->Visibility, window, static_cast<int>(depth->GetWidth()),
    static_cast<int>(depth->GetHeight()),
    this->VisibilityFormat());
  std::string fs = vtkFXAVSMLookupFS;
  vtkShaderProgram::Substitute(fs, "//VTK::System::Dec",
    (this->Exact ? StorageExtension : std::string("//VTK::System::Dec\n")) +
      this->CurveDefines(this->Exact),
    false);
  vtkShaderProgram::Substitute(fs, "//VTK::FXAVSMLists::Dec", vtkFXAVSMLists, false);
  vtkShaderProgram::Substitute(fs, "//VTK::FXViewPosition::Dec", vtkFXViewPosition, false);
  vtkShaderProgram::Substitute(fs, "//VTK::FXAVSMCurves::Dec", this->CurveCode(), false);

  this->ComputeViewToLight(ren);

  vtkFXRenderUtilities::RenderTargetScope target(window, this->LookUpFrameBuffer, this->Visibility);
  if (!target.IsComplete())
  {
    return false;
  }
  // Unshadowed where the shader cannot run, and where the G-buffer's depth
  // (1: no surface) keeps it from running (SkipBackground).
  vtkTextureObject* surfaces = this->SkipBackground ? this->GBuffer->GetDepthTexture() : nullptr;
  this->LookUpQuad.AtFarPlane = surfaces != nullptr;
  vtkShaderProgram* program =
    vtkFXRenderUtilities::ReadyQuad(this->LookUpQuad, window, fs);
  // And where no caster can shadow (CullLookUp: the scissor box).
  const int width = static_cast<int>(depth->GetWidth());
  const int height = static_cast<int>(depth->GetHeight());
  int rect[4] = { 0, 0, width, height };
  if (this->CullLookUp)
  {
    this->ComputeShadowedPixels(ren, width, height, rect);
  }
  std::copy(rect, rect + 4, this->LookUpPixels);
  const bool culled = rect[0] > 0 || rect[1] > 0 || rect[2] < width || rect[3] < height;
  const float unshadowed[4] = { 1.0f, 1.0f, 1.0f, 1.0f };
  if (!program)
  {
    vtkFXRenderUtilities::ClearTargets(1, unshadowed);
    return true;
  }
  vtkFXRenderUtilities::ScissorScope scissor(
    window->GetState(), rect, surfaces || culled ? unshadowed : nullptr);
  target.SkipWhereDepthIsOne(surfaces);
  depth->Activate();
  program->SetUniformi("fxLinearDepth", depth->GetTextureUnit());
  vtkFXRenderUtilities::SetFrustumRayUniforms(program, ren);
  this->SetCurveUniforms(program);
  if (rect[0] < rect[2] && rect[1] < rect[3])
  {
    this->LookUpQuad.Helper->Render();
  }
  depth->Deactivate();
  this->ReleaseCurveUnits();
  return true;
}

void vtkFXAVSMPass::Render(const vtkRenderState* s)
{
  this->ReusedShadowMaps = false; // (also when the frame is abandoned)
  this->NumberOfRenderedProps = 0;
  this->ErrorThisFrame = false;
  vtkOpenGLRenderer* ren = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  this->FrameReady = false;
  const bool opaqueReceivers = this->OpaqueReceivers;
  if ((opaqueReceivers &&
        (!this->GBuffer || !this->GBuffer->GetChannelTexture(GB::LinearDepth))) ||
    this->CastingLights.empty())
  {
    this->ReportError("vtkFXAVSMPass needs a casting light, and for opaque receivers a "
                      "G-buffer with linear depth.");
    this->AbandonFrame(window);
    return;
  }
  if (!StorageBuffersSupported())
  {
    if (!this->WarnedUnsupported)
    {
      vtkErrorMacro("AVSM needs OpenGL 4.3 (shader storage buffers); translucent props "
                    "cast no shadows.");
      this->WarnedUnsupported = true;
    }
    this->AbandonFrame(window);
    return;
  }
  this->FitLightViews(ren);
  this->MeasureCasters();
  // Kept for the frame: the casters are forgotten after Render, and VTK's
  // translucent step (translucent receivers) comes later.
  for (LightView& view : this->Views)
  {
    this->ComputeCasterDepthRange(view);
  }
  const int largest = vtkTextureObject::GetMaximumTextureSize(window);
  if (this->AtlasSize[0] > largest || this->AtlasSize[1] > largest)
  {
    std::ostringstream message;
    message << "AVSM: " << this->GetNumberOfViews() << " light views of " << this->ShadowMapSize
            << " texels need an atlas of " << this->AtlasSize[0] << " x " << this->AtlasSize[1]
            << ", above this OpenGL's " << largest
            << "; no shadows (lower ShadowMapSize or MaximumNumberOfLights).";
    this->ReportError(message.str());
    this->AbandonFrame(window);
    return;
  }
  if (!this->EnsureBuffers(window))
  {
    this->AbandonFrame(window);
    return;
  }
  // The shadow maps of the last frame stand when they were made from the
  // same casters, lights and settings; kept again below once this frame's
  // are whole.
  const std::vector<double> key = this->CaptureKey();
  this->ReusedShadowMaps =
    this->ReuseShadowMaps && !this->KeptKey.empty() && key == this->KeptKey;
  this->KeptKey.clear();
  // With Profile on, each phase is finished before the clock reads it.
  vtkNew<vtkTimerLog> clock;
  const auto phase = [this, &clock](int which) {
    if (this->Profile)
    {
      glFinish();
      clock->StopTimer();
      this->PhaseMilliseconds[which] = 1000.0 * clock->GetElapsedTime();
      clock->StartTimer();
    }
  };
  std::fill(this->PhaseMilliseconds, this->PhaseMilliseconds + 3, 0.0);
  if (this->Profile)
  {
    glFinish();
    clock->StartTimer();
  }
  bool drawn = true; // the curves and the visibility had their storage
  if (!this->ReusedShadowMaps)
  {
    this->StoredFragments = this->Capacity;
    this->Capture(s, window);
    this->StoredFragments = std::min<vtkIdType>(this->StoredFragments, this->UsedSlots);
    phase(0);
    if (!this->Exact)
    {
      drawn = this->Resolve(window);
    }
    else
    {
      // The lists are the map: no curves are kept.
      for (auto& t : this->Curves)
      {
        vtkFXRenderUtilities::Release(t, window);
      }
      this->Curves.clear();
      vtkFXRenderUtilities::Release(this->ResolveFrameBuffer, window);
    }
    phase(1);
  }
  if (opaqueReceivers)
  {
    drawn = drawn && this->LookUp(ren, window);
  }
  else
  {
    // Only translucent props receive: the look-up has no one to shade.
    vtkFXRenderUtilities::Release(this->Visibility, window);
    vtkFXRenderUtilities::Release(this->LookUpFrameBuffer, window);
    this->ComputeViewToLight(ren);
  }
  phase(2);
  // The casters and lights are the frame's (HasWork sets them again); the
  // lights' indices and views stay for the translucent step.
  this->Casters.clear();
  this->CasterExtents.clear();
  for (CastingLight& casting : this->CastingLights)
  {
    casting.Light = nullptr;
  }
  for (GLuint i = 0; i < NumberOfBuffers; ++i)
  {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, i, 0);
  }
  if (!drawn)
  {
    std::ostringstream message;
    message << "AVSM: OpenGL could not allocate the "
            << (this->Exact ? "visibility texture" : "curve or visibility textures") << " ("
            << this->AtlasSize[0] << " x " << this->AtlasSize[1] << " texels of curves, "
            << this->Nodes() / 2 << " RGBA32F textures); no shadows (lower ShadowMapSize, "
            << "NumberOfNodes or MaximumNumberOfLights).";
    this->ReportError(message.str());
    this->AbandonFrame(window);
    return;
  }
  this->FrameReady = true;
  // Lists that dropped fragments (the buffer grows for the next frame) are
  // made again.
  if (this->UsedSlots <= this->StoredFragments)
  {
    this->KeptKey = key;
  }
  if (!this->ErrorThisFrame)
  {
    this->LastError.clear(); // (a frame without trouble: a later failure is news)
  }
}

void vtkFXAVSMPass::ReportError(const std::string& message)
{
  this->ErrorThisFrame = true;
  if (message != this->LastError)
  {
    vtkErrorMacro(<< message);
    this->LastError = message;
  }
}

namespace
{
// When an algorithm's output, or anything upstream that will change it,
// last changed: the output's MTime and the pipeline's (brought up to date
// without running anything: an Update() here would run the pipeline with
// a request of its own, the whole data, where a parallel render asks for
// its piece). A change upstream is seen before it runs.
double OutputTime(vtkAlgorithm* algorithm, vtkDataObject* output)
{
  vtkMTimeType time = output ? output->GetMTime() : 0;
  if (auto* pipeline =
        vtkDemandDrivenPipeline::SafeDownCast(algorithm ? algorithm->GetExecutive() : nullptr))
  {
    pipeline->UpdatePipelineMTime();
    time = std::max(time, pipeline->GetPipelineMTime());
  }
  return static_cast<double>(time);
}

// A texture's settings and image.
void AddTextureKey(vtkTexture* texture, std::vector<double>& key)
{
  key.push_back(static_cast<double>(reinterpret_cast<std::uintptr_t>(texture)));
  if (texture)
  {
    key.push_back(static_cast<double>(texture->GetMTime()));
    vtkAlgorithm* producer =
      texture->GetNumberOfInputConnections(0) > 0 ? texture->GetInputAlgorithm() : nullptr;
    key.push_back(OutputTime(producer, texture->GetInput()));
  }
}

// A prop that picks, as it renders, which of its mappers draws (by the
// time the renderer allocates it, or ParaView's EnableLOD): what it drew
// into the last maps is not known before the capture, so maps it casts
// into are made every frame. (Keyed on its full-resolution mapper, the
// coarse shadow of the last interactive frame stayed under the still
// render.)
bool SwitchesLevelOfDetail(vtkProp* prop)
{
  return prop->IsA("vtkLODActor") || prop->IsA("vtkQuadricLODActor") ||
    prop->IsA("vtkLODProp3D") || prop->IsA("vtkPVLODActor");
}

// What an actor draws from its property, textures, shaders, mapper and
// data; its transform is keyed apart (CaptureKey). Not its redraw time:
// an assembly modifies its parts every frame (vtkAssembly pokes their
// matrices), and vtkActor::GetRedrawMTime sees no composite input.
void AddActorKey(vtkActor* actor, std::vector<double>& key)
{
  const auto add = [&key](vtkObject* object) {
    key.push_back(static_cast<double>(reinterpret_cast<std::uintptr_t>(object)));
    key.push_back(object ? static_cast<double>(object->GetMTime()) : 0.0);
  };
  add(actor->GetProperty());
  add(actor->GetBackfaceProperty());
  AddTextureKey(actor->GetTexture(), key);
  if (vtkProperty* property = actor->GetProperty())
  {
    for (const auto& named : property->GetAllTextures())
    {
      AddTextureKey(named.second, key);
    }
  }
  if (vtkShaderProperty* shaders = actor->GetShaderProperty())
  {
    add(shaders);
    key.push_back(static_cast<double>(shaders->GetShaderMTime()));
    add(shaders->GetVertexCustomUniforms());
    add(shaders->GetGeometryCustomUniforms());
    add(shaders->GetFragmentCustomUniforms());
  }
  vtkMapper* mapper = actor->GetMapper();
  add(mapper);
  if (!mapper)
  {
    return;
  }
  if (mapper->GetNumberOfInputPorts() > 0 && mapper->GetNumberOfInputConnections(0) > 0)
  {
    key.push_back(OutputTime(mapper->GetInputAlgorithm(), mapper->GetInputDataObject(0, 0)));
  }
  if (vtkPlaneCollection* planes = mapper->GetClippingPlanes())
  {
    vtkCollectionSimpleIterator it;
    planes->InitTraversal(it);
    while (vtkPlane* plane = planes->GetNextPlane(it))
    {
      add(plane);
    }
  }
  // (the splat helper rebuilds from these, which the mapper's MTime leaves out)
  if (vtkPointGaussianMapper* splats = vtkPointGaussianMapper::SafeDownCast(mapper))
  {
    add(splats->GetScaleFunction());
    add(splats->GetScalarOpacityFunction());
  }
}
}

std::vector<double> vtkFXAVSMPass::CaptureKey()
{
  std::vector<double> key;
  const auto add = [&key](double value) { key.push_back(value); };
  // The settings, and the storage the maps live in (new buffers hold none).
  add(static_cast<double>(this->GetMTime()));
  add(static_cast<double>(this->Capacity));
  add(static_cast<double>(this->BufferTexels));
  for (unsigned int buffer : this->Buffers)
  {
    add(buffer);
  }
  add(this->AtlasSize[0]);
  add(this->AtlasSize[1]);
  // The lights' views: where each light sees the props from.
  for (const CastingLight& casting : this->CastingLights)
  {
    add(casting.Index);
    add(casting.NumberOfViews);
  }
  for (const LightView& view : this->Views)
  {
    const double* toView = view.Camera->GetViewTransformMatrix()->GetData();
    const double* toClip = view.Projection->GetData();
    key.insert(key.end(), toView, toView + 16);
    key.insert(key.end(), toClip, toClip + 16);
    add(view.SliceRange[0]);
    add(view.SliceRange[1]);
    add(view.Origin[0]);
    add(view.Origin[1]);
  }
  // The casters, down to the parts of assemblies: each part's transform
  // (its matrix's values, which a follower takes from the camera) and what
  // it draws.
  for (vtkProp* prop : this->Casters)
  {
    add(static_cast<double>(reinterpret_cast<std::uintptr_t>(prop)));
    prop->InitPathTraversal();
    while (vtkAssemblyPath* path = prop->GetNextPath())
    {
      vtkProp* part = path->GetLastNode()->GetViewProp();
      add(static_cast<double>(reinterpret_cast<std::uintptr_t>(part)));
      vtkMatrix4x4* matrix = vtkFXRenderUtilities::PathMatrix(prop, path);
      if (matrix)
      {
        key.insert(key.end(), matrix->GetData(), matrix->GetData() + 16);
      }
      if (SwitchesLevelOfDetail(part))
      {
        return std::vector<double>(); // (no key: never reused)
      }
      if (vtkActor* actor = vtkActor::SafeDownCast(part))
      {
        AddActorKey(actor, key);
      }
      else
      {
        add(static_cast<double>(part->GetRedrawMTime()));
      }
    }
  }
  return key;
}

void vtkFXAVSMPass::ReleaseBuffers()
{
  if (this->Buffers[HeadsBuffer] && this->BuffersWindow)
  {
    // (in their own context, then back to whichever was current)
    this->BuffersWindow->PushContext();
    glDeleteBuffers(NumberOfBuffers, this->Buffers);
    this->BuffersWindow->PopContext();
  }
  std::fill(this->Buffers, this->Buffers + NumberOfBuffers, 0u);
  this->KeptKey.clear();
  this->BufferTexels = 0;
  this->Capacity = 0;
  this->BuffersWindow = nullptr;
}

void vtkFXAVSMPass::AbandonFrame(vtkOpenGLRenderWindow* window)
{
  // Nothing for the composite or the translucent step to read, and no
  // pointers into the scene kept.
  vtkFXRenderUtilities::Release(this->Visibility, window);
  this->FrameReady = false;
  this->KeptKey.clear();
  this->Views.clear();
  this->Casters.clear();
  this->CasterExtents.clear();
  this->CastingLights.clear();
}

void vtkFXAVSMPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->CasterPass->ReleaseGraphicsResources(w);
  vtkFXRenderUtilities::ReleaseTilePoints(this->ResolveTiles, w);
  vtkFXRenderUtilities::ReleaseTilePoints(this->StaleTiles, w);
  this->CurvesEmptyOutsideResolved = this->CurvesEmptyOutsideStale = false;
  vtkFXRenderUtilities::ReleaseQuad(this->LookUpQuad, w);
  for (auto& t : this->Curves)
  {
    vtkFXRenderUtilities::Release(t, w);
  }
  this->Curves.clear();
  vtkFXRenderUtilities::Release(this->Visibility, w);
  vtkFXRenderUtilities::Release(this->CaptureFrameBuffer, w);
  vtkFXRenderUtilities::Release(this->ResolveFrameBuffer, w);
  vtkFXRenderUtilities::Release(this->LookUpFrameBuffer, w);
  this->ReleaseBuffers();
  this->LastError.clear();
}

void vtkFXAVSMPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ShadowMapSize: " << this->ShadowMapSize << "\n";
  os << indent << "SkipBackground: " << this->SkipBackground << "\n";
  os << indent << "CullLookUp: " << this->CullLookUp << "\n";
  os << indent << "CullResolveTiles: " << this->CullResolveTiles << "\n";
  os << indent << "NumberOfNodes: " << this->NumberOfNodes << " (" << this->Nodes() << " used)\n";
  os << indent << "Exact: " << this->Exact << "\n";
  os << indent << "Representation: "
     << (this->Representation == RegularSlices ? "RegularSlices" : "AdaptiveNodes") << "\n";
  os << indent << "Bilinear: " << this->Bilinear << "\n";
  os << indent << "TranslucentReceivers: " << this->TranslucentReceivers << "\n";
  os << indent << "Bias: " << this->Bias << "\n";
  os << indent << "SplatRadius: " << this->SplatRadius << "\n";
  os << indent << "MaximumNumberOfLights: " << this->MaximumNumberOfLights << "\n";
  os << indent << "InitialNodesPerTexel: " << this->InitialNodesPerTexel << "\n";
  os << indent << "ReuseShadowMaps: " << this->ReuseShadowMaps
     << " (last frame reused them: " << this->ReusedShadowMaps << ")\n";
  os << indent << "CapturedFragments: " << this->CapturedFragments << " in "
     << this->UsedSlots << " list slots (capacity " << this->Capacity << "; "
     << this->CountersInUse << " node counters)\n";
}
