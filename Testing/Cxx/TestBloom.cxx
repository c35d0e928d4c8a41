// vtkFXBloomPass:
// - energy: with firefly suppression off, the glow's total (its half-
//   resolution texture summed, times 4) equals the emission channel's
//   total within 2% (every filter of the pyramid is normalised; the rest is
//   half-float rounding and bilinear reads at the object's rim), and the
//   8-bit image gains Intensity times that total within 5% (glow below
//   half a level rounds away far out);
// - no emission and no threshold: the effect is left out, with the HDR
//   target and the emission channel, and the image is bit-identical to
//   the one without it;
// - a 1e30 pixel and a NaN pixel in the lit HDR image, with a threshold:
//   the glow stays finite, and with firefly suppression the 1e30 pixel
//   adds at most about what one pixel of value 1 adds (no bright square);
// - light above a threshold glows by the soft knee's weights.
#include "vtkFXBloomPass.h"
#include "vtkFXHDRTargetPass.h"
#include "vtkToneMappingPass.h"
#include "vtkPolyData.h"
#include "vtkCellArray.h"
#include "vtkPoints.h"
#include "vtkPointGaussianMapper.h"
#include "vtkFXEffectPass.h"
#include "vtkFXGBufferPass.h"
#include "vtkFXPipelinePass.h"
#include "vtkFXRenderUtilities.h"
#include "vtkFXScenes.h"
#include "vtkFXTestUtilities.h"

#include "vtkActorCollection.h"
#include "vtkAssembly.h"
#include "vtkCamera.h"
#include "vtkInformation.h"
#include "vtkLineSource.h"
#include "vtkLight.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRendererCollection.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkColorTransferFunction.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlaneSource.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkTextActor.h"
#include "vtkOpenGLState.h"
#include "vtkFXOpenGL.h"

#include <functional>
#include <limits>

namespace
{
using GB = vtkFXGBufferPass;

// Paints the image it is drawn onto (the HDR target), at the post-process
// stage, with `Paint`: GLSL that sets `color` (vec4) for pixel `p` or
// discards; `big` is 1e30 and `zero` 0, both known only at run time, so a
// compiler cannot fold them into a half float or NaN away.
class PaintProbe : public vtkFXEffectPass
{
public:
  static PaintProbe* New();
  vtkTypeMacro(PaintProbe, vtkFXEffectPass);
  PaintProbe() { this->Stage = PostProcess; }
  unsigned int GetRequiredChannels() override { return 0; }
  bool HasWork(const vtkFXSceneInfo&) override { return true; }
  void Render(const vtkRenderState* s) override
  {
    auto* window = vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow());
    const std::string fs = "//VTK::System::Dec\nin vec2 texCoord;\nuniform float big;\n"
                           "//VTK::Output::Dec\n"
                           "void main() {\n"
                           // (texCoord read, so that the quad's attribute stays in the
                           // program whatever the paint does with `color`)
                           "  if (texCoord.x < -1.0) discard;\n"
                           "  ivec2 p = ivec2(gl_FragCoord.xy);\n"
                           "  float zero = texCoord.x < -1.0 ? 1.0 : 0.0;\n"
                           "  vec4 color = vec4(zero * big);\n" +
      this->Paint + "\n  gl_FragData[0] = color;\n}\n";
    vtkShaderProgram* program = vtkFXRenderUtilities::ReadyQuad(this->Quad, window, fs);
    if (program)
    {
      // Over whatever the image shows, depth or not.
      vtkOpenGLState* state = window->GetState();
      vtkOpenGLState::ScopedglEnableDisable depth(state, GL_DEPTH_TEST);
      vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
      state->vtkglDisable(GL_DEPTH_TEST);
      state->vtkglDisable(GL_BLEND);
      program->SetUniformf("big", 1e30f);
      this->Quad.Helper->Render();
    }
  }
  void ReleaseGraphicsResources(vtkWindow* w) override
  {
    vtkFXRenderUtilities::ReleaseQuad(this->Quad, w);
  }
  std::string Paint;
  vtkFXRenderUtilities::FullScreenQuad Quad;
};
vtkStandardNewMacro(PaintProbe);

// A black scene (no light, black background) with a sphere whose only
// light is its EMISSIVE_COLOR, or no emission at all.
// A black sphere (no highlight), emitting `emission` if given.
vtkSmartPointer<vtkActor> Sphere(double x, double radius, const double emission[3])
{
  vtkNew<vtkSphereSource> source;
  source->SetCenter(x, 0.0, 0.0);
  source->SetRadius(radius);
  source->SetThetaResolution(64);
  source->SetPhiResolution(64);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.0, 0.0, 0.0);
  actor->GetProperty()->SetSpecular(0.0);
  if (emission)
  {
    vtkNew<vtkInformation> keys;
    keys->Set(GB::EMISSIVE_COLOR(), emission, 3);
    actor->SetPropertyKeys(keys);
  }
  return actor;
}

vtkRenderer* MakeScene(vtkRenderWindow* window, const double emission[3])
{
  window->GetRenderers()->RemoveAllItems();
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  renderer->SetBackground(0.0, 0.0, 0.0);
  renderer->AddActor(Sphere(0.0, 0.3, emission));
  renderer->ResetCamera();
  return renderer;
}

double Sum(const std::vector<float>& values, int components, int used)
{
  double sum = 0.0;
  for (size_t i = 0; i < values.size(); ++i)
  {
    sum += (static_cast<int>(i % components) < used) ? values[i] : 0.0;
  }
  return sum;
}

double ImageSum(const std::vector<unsigned char>& image)
{
  double sum = 0.0;
  for (unsigned char v : image)
  {
    sum += v / 255.0;
  }
  return sum;
}

// The scene of MakeScene rendered through `pipeline` without, then with
// `bloom`.
void RenderWithoutAndWith(vtkRenderWindow* window, const double emission[3],
  vtkFXPipelinePass* pipeline, vtkFXBloomPass* bloom, std::vector<unsigned char>& without,
  std::vector<unsigned char>& with, const std::function<void(vtkRenderer*)>& arrange = nullptr)
{
  vtkRenderer* renderer = MakeScene(window, emission);
  if (arrange)
  {
    arrange(renderer);
  }
  renderer->SetPass(pipeline);
  window->Render();
  without = vtkFXScenes::Capture(window);
  pipeline->AddEffect("bloom", bloom);
  window->Render();
  with = vtkFXScenes::Capture(window);
}

// The glow's total (firefly suppression off), with the bloom given.
double GlowTotal(vtkFXBloomPass* bloom)
{
  return 4.0 * Sum(vtkFXTest::Download(bloom->GetGlowTexture(), 4), 4, 3);
}

// Energy kept: the glow's total equals the emission's (firefly
// suppression off), and the image gains Intensity times it (8-bit: 5%).
// Also at an odd size (the last half-resolution texel covers one column),
// and with the emitter at the image's border, where the filters reach past
// it (mirrored reads give away what they take).
int CheckEnergy(vtkRenderWindow* window)
{
  struct Case
  {
    const char* Name;
    int Width, Height;
    double ShiftX; // camera pan, world units (the view is about 1.4 wide)
  };
  const Case cases[] = { { "400x300", 400, 300, 0.0 }, { "401x301", 401, 301, 0.0 },
    { "400x300, at the border", 400, 300, 0.6 } };
  for (const Case& c : cases)
  {
    window->SetSize(c.Width, c.Height);
    const double emission[3] = { 0.5, 0.4, 0.3 };
    vtkNew<vtkFXPipelinePass> pipeline;
    vtkNew<vtkFXBloomPass> bloom;
    bloom->FireflySuppressionOff();
    bloom->SetIntensity(0.5);
    std::vector<unsigned char> without, with;
    RenderWithoutAndWith(window, emission, pipeline, bloom, without, with, [&c](vtkRenderer* renderer) {
      // Pan the camera: the sphere's centre moves towards the left edge.
      vtkCamera* camera = renderer->GetActiveCamera();
      double focal[3], position[3];
      camera->GetFocalPoint(focal);
      camera->GetPosition(position);
      focal[0] += c.ShiftX;
      position[0] += c.ShiftX;
      camera->SetFocalPoint(focal);
      camera->SetPosition(position);
    });
    FX_CHECK(vtkFXTest::Passes(pipeline).find("bloom") != std::string::npos, vtkFXTest::Passes(pipeline));
    const double source = Sum(
      vtkFXTest::Download(pipeline->GetGBufferPass()->GetChannelTexture(GB::Emission), 4), 4, 3);
    const double glow = GlowTotal(bloom);
    const double added = ImageSum(with) - ImageSum(without);
    std::cout << "energy, " << c.Name << ": emission " << source << ", glow " << glow << " (ratio "
              << glow / source << "), added to the image " << added
              << " (ratio to intensity x emission " << added / (0.5 * source) << "), "
              << bloom->GetNumberOfLevels(c.Width, c.Height) << " levels" << std::endl;
    FX_CHECK(source > 1000.0, "the sphere emits " << source);
    if (c.Width % 2 == 0 && c.Height % 2 == 0)
    {
      // (at odd sizes the last half-resolution texels cover one pixel and
      // its mirror image, so 4 x their sum is not the total)
      FX_CHECK(std::fabs(glow / source - 1.0) < 0.02, "glow " << glow << " for emission " << source);
    }
    FX_CHECK(std::fabs(added / (0.5 * source) - 1.0) < 0.05, "image gained " << added);
    window->GetRenderers()->GetFirstRenderer()->SetPass(nullptr);
  }
  return EXIT_SUCCESS;
}

// What emits is drawn past the emissive props' bounds: a splat reaches its
// radius past its centre (the bounds VTK gives), a wide point a few pixels.
// The glow is drawn in a rectangle around what they reach; around the
// centres alone it cut the glow off in a square (a splat of radius 0.4
// lost most of its glow). One unlit, opaque splat (its colour is its
// emission) at a small glow radius: the glow's total is the emission's.
int CheckSplatGlow(vtkRenderWindow* window)
{
  window->SetSize(400, 300);
  for (const bool widePoint : { false, true })
  {
    window->GetRenderers()->RemoveAllItems();
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(0.0, 0.0, 0.0);
    vtkNew<vtkPolyData> poly;
    poly->SetPoints(points);
    vtkNew<vtkActor> actor;
    if (widePoint)
    {
      vtkNew<vtkCellArray> vertex;
      const vtkIdType id = 0;
      vertex->InsertNextCell(1, &id);
      poly->SetVerts(vertex);
      vtkNew<vtkPolyDataMapper> mapper;
      mapper->SetInputData(poly);
      actor->SetMapper(mapper);
      actor->GetProperty()->SetPointSize(40.0f);
    }
    else
    {
      vtkNew<vtkPointGaussianMapper> mapper;
      mapper->SetInputData(poly);
      mapper->EmissiveOff();
      mapper->SetScaleFactor(0.4);
      mapper->SetSplatShaderCode("//VTK::Color::Impl\n"
                                 "  if (dot(offsetVCVSOutput.xy, offsetVCVSOutput.xy) > 1.0) { discard; }\n");
      actor->SetMapper(mapper);
    }
    actor->GetProperty()->LightingOff();
    actor->GetProperty()->SetColor(0.5, 0.4, 0.3);
    renderer->AddActor(actor);
    renderer->SetBackground(0.0, 0.0, 0.0);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetPosition(0.0, 0.0, 3.0);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    renderer->ResetCameraClippingRange(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
    vtkNew<vtkFXPipelinePass> pipeline;
    vtkNew<vtkFXBloomPass> bloom;
    bloom->FireflySuppressionOff();
    bloom->SetRadius(0.005);
    pipeline->AddEffect("bloom", bloom);
    renderer->SetPass(pipeline);
    window->Render();
    FX_CHECK(vtkFXTest::Passes(pipeline).find("bloom") != std::string::npos,
      vtkFXTest::Passes(pipeline));
    const double source = Sum(
      vtkFXTest::Download(pipeline->GetGBufferPass()->GetChannelTexture(GB::Emission), 4), 4, 3);
    const double glow = GlowTotal(bloom);
    std::cout << (widePoint ? "a 40-pixel point" : "a splat of radius 0.4")
              << ": emission " << source << ", glow " << glow << " (ratio " << glow / source
              << ")" << std::endl;
    FX_CHECK(source > 100.0, "the splat emits " << source);
    FX_CHECK(std::fabs(glow / source - 1.0) < 0.02, "glow " << glow << " for " << source);
    renderer->SetPass(nullptr);
  }
  return EXIT_SUCCESS;
}

// A lit sphere, `color`, at depth z, in front of the camera at z = 3.
vtkSmartPointer<vtkActor> LitSphere(double z, double r, double g, double b)
{
  auto actor = Sphere(0.0, 0.5, nullptr);
  actor->SetPosition(0.0, 0.0, z);
  actor->GetProperty()->SetColor(r, g, b);
  return actor;
}

// The HDR target keeps what the frame around the pipeline expects of it.
// - Inside vtkToneMappingPass, whose framebuffer is float: the lit values
//   above 1 reach the tone mapping with a post-process effect on as
//   without (the write-back clamped them to 1: highlights flattened).
// - With the window's Erase off (multiple exposures): an earlier frame's
//   depth hides what lies behind it with the effect on as without (the
//   target cleared the depth unless the renderer's own Erase was off).
// The effect: bloom with a threshold nothing reaches (the target is kept,
// no glow is added).
int CheckTargetKeepsFrame(vtkRenderWindow* window)
{
  window->SetSize(200, 150);
  std::vector<unsigned char> images[2];
  for (const bool effect : { false, true })
  {
    window->GetRenderers()->RemoveAllItems();
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    renderer->AddActor(LitSphere(0.0, 1.0, 1.0, 1.0));
    vtkNew<vtkLight> light;
    light->SetLightTypeToCameraLight();
    light->SetIntensity(3.0);
    renderer->AddLight(light);
    renderer->ResetCamera();
    vtkNew<vtkFXPipelinePass> pipeline;
    vtkNew<vtkFXBloomPass> bloom;
    bloom->SetThreshold(1e4);
    if (effect)
    {
      pipeline->AddEffect("bloom", bloom);
    }
    vtkNew<vtkToneMappingPass> toneMapping;
    toneMapping->SetToneMappingType(vtkToneMappingPass::Reinhard);
    toneMapping->SetDelegatePass(pipeline);
    renderer->SetPass(toneMapping);
    window->Render();
    FX_CHECK((vtkFXTest::Passes(pipeline).find("hdr-target") != std::string::npos) == effect,
      vtkFXTest::Passes(pipeline));
    images[effect ? 1 : 0] = vtkFXScenes::Capture(window);
    renderer->SetPass(nullptr);
    toneMapping->ReleaseGraphicsResources(window);
  }
  const int toneMapped = vtkFXScenes::MaxDifference(images[0], images[1]);
  std::cout << "tone mapping around the pipeline: largest difference with the HDR target "
            << toneMapped << "/255" << std::endl;
  FX_CHECK(toneMapped <= 1, "the HDR target changed the tone-mapped frame by " << toneMapped);

  // Two exposures with the window's Erase off: a red sphere near the
  // camera, then a green one behind it, drawn where the red one does not hide it.
  for (const bool effect : { false, true })
  {
    window->GetRenderers()->RemoveAllItems();
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    auto front = LitSphere(0.5, 1.0, 0.0, 0.0);
    renderer->AddActor(front);
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetPosition(0.0, 0.0, 3.0);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetClippingRange(0.5, 10.0);
    vtkNew<vtkFXPipelinePass> pipeline;
    vtkNew<vtkFXBloomPass> bloom;
    bloom->SetThreshold(1e4);
    if (effect)
    {
      pipeline->AddEffect("bloom", bloom);
    }
    renderer->SetPass(pipeline);
    window->EraseOn();
    window->Render();
    renderer->RemoveActor(front);
    auto back = LitSphere(-0.5, 0.0, 1.0, 0.0);
    back->SetPosition(0.3, 0.0, -0.5);
    renderer->AddActor(back);
    window->EraseOff();
    window->Render();
    images[effect ? 1 : 0] = vtkFXScenes::Capture(window);
    window->EraseOn();
    renderer->SetPass(nullptr);
  }
  const int exposures = vtkFXScenes::MaxDifference(images[0], images[1]);
  std::cout << "two exposures, the window's Erase off: largest difference with the HDR target "
            << exposures << "/255" << std::endl;
  FX_CHECK(exposures <= 1, "the HDR target changed the second exposure by " << exposures);
  return EXIT_SUCCESS;
}

// Props that are lit but whose primitives VTK leaves unlit (a PBR
// material, a line without normals) emit only their emissive colour,
// none here: beside the emitting sphere they add nothing to the emission
// channel (before, their whole colour went into it and glowed).
int CheckUnlitPrimitivesDoNotGlow(vtkRenderWindow* window)
{
  window->SetSize(400, 300);
  const double emission[3] = { 0.5, 0.4, 0.3 };
  double totals[2] = { 0.0, 0.0 };
  for (int withOthers = 0; withOthers < 2; ++withOthers)
  {
    vtkRenderer* renderer = MakeScene(window, emission);
    if (withOthers)
    {
      auto pbr = Sphere(0.6, 0.25, nullptr);
      pbr->GetProperty()->SetInterpolationToPBR();
      pbr->GetProperty()->SetColor(1.0, 1.0, 1.0);
      renderer->AddActor(pbr);
      vtkNew<vtkLineSource> line;
      line->SetPoint1(-0.8, -0.4, 0.0);
      line->SetPoint2(0.8, -0.4, 0.0);
      vtkNew<vtkPolyDataMapper> lineMapper;
      lineMapper->SetInputConnection(line->GetOutputPort());
      vtkNew<vtkActor> lineActor;
      lineActor->SetMapper(lineMapper);
      lineActor->GetProperty()->SetColor(1.0, 1.0, 1.0);
      lineActor->GetProperty()->SetLineWidth(5.0);
      renderer->AddActor(lineActor);
    }
    vtkNew<vtkFXPipelinePass> pipeline;
    vtkNew<vtkFXBloomPass> bloom;
    pipeline->AddEffect("bloom", bloom);
    renderer->SetPass(pipeline);
    window->Render();
    totals[withOthers] = Sum(
      vtkFXTest::Download(pipeline->GetGBufferPass()->GetChannelTexture(GB::Emission), 4), 4, 3);
    renderer->SetPass(nullptr);
  }
  std::cout << "emission with the emitter alone " << totals[0]
            << ", beside a PBR sphere and a line without normals " << totals[1] << std::endl;
  FX_CHECK(totals[0] > 1000.0 && std::fabs(totals[1] - totals[0]) <= 1e-3 * totals[0],
    "unlit primitives of lit props emitted");
  return EXIT_SUCCESS;
}

int CheckNothingToDo(vtkRenderWindow* window)
{
  window->SetSize(200, 150);
  vtkNew<vtkFXPipelinePass> pipeline;
  vtkNew<vtkFXBloomPass> bloom;
  std::vector<unsigned char> without, with;
  RenderWithoutAndWith(window, nullptr, pipeline, bloom, without, with);
  const std::string passes = vtkFXTest::Passes(pipeline);
  std::cout << "no emission: passes " << passes << std::endl;
  FX_CHECK(passes.find("bloom") == std::string::npos && passes.find("hdr-target") == std::string::npos,
    passes);
  FX_CHECK(!(pipeline->GetGBufferChannels() & GB::ChannelBit(GB::Emission)),
    "an emission channel nobody reads");
  FX_CHECK(with == without, "the image changed");
  return EXIT_SUCCESS;
}

// Over a transparent background (alpha bit planes, background alpha 0), the
// glow's coverage goes over the alpha as a translucent surface's would: a
// background pixel's alpha is then its largest colour component (the glow
// is all its light), the sphere stays opaque, and where no glow reaches the
// alpha stays 0. (Before, the halo kept alpha 0 and an RGBA screenshot
// composited over a page lost it.)
int CheckGlowAlpha()
{
  auto window = vtkFXTest::MakeWindow(200, 150);
  window->SetAlphaBitPlanes(1);
  const double emission[3] = { 3.0, 1.0, 0.25 };
  vtkRenderer* renderer = MakeScene(window, emission);
  renderer->SetBackgroundAlpha(0.0);
  vtkNew<vtkFXPipelinePass> pipeline;
  renderer->SetPass(pipeline);
  window->Render();
  const auto rgba = [&window]() {
    std::vector<unsigned char> pixels(static_cast<size_t>(200) * 150 * 4);
    unsigned char* data = window->GetRGBACharPixelData(0, 0, 199, 149, 0);
    std::copy(data, data + pixels.size(), pixels.begin());
    delete[] data;
    return pixels;
  };
  const auto without = rgba();
  vtkNew<vtkFXBloomPass> bloom;
  pipeline->AddEffect("bloom", bloom);
  window->Render();
  const auto with = rgba();
  int halo = 0, dark = 0, worst = 0, opaque = 0, lostOpacity = 0;
  for (size_t i = 0; i < with.size(); i += 4)
  {
    const int largest = std::max({ with[i], with[i + 1], with[i + 2] });
    if (without[i + 3] == 255)
    {
      ++opaque;
      lostOpacity += with[i + 3] != 255;
      continue;
    }
    FX_CHECK(without[i + 3] == 0, "the background's alpha without bloom");
    worst = std::max(worst, std::abs(with[i + 3] - largest));
    halo += largest >= 8;
    dark += largest == 0 && with[i + 3] == 0;
  }
  std::cout << "glow alpha: " << halo << " halo pixels, largest |alpha - max(rgb)| " << worst
            << ", " << dark << " background pixels dark with alpha 0, " << opaque
            << " sphere pixels (" << lostOpacity << " not opaque)" << std::endl;
  // (both from the same half float, each rounded to 8 bits once)
  FX_CHECK(worst <= 1, "a background pixel's alpha is not its glow's coverage");
  FX_CHECK(halo > 1000 && dark > 1000 && opaque > 1000, "the scene's halo, dark and sphere pixels");
  FX_CHECK(lostOpacity == 0, "the sphere's pixels lost opacity");
  return EXIT_SUCCESS;
}

// The scene of MakeScene without emission, its lit image painted by a
// probe with `paint` (see PaintProbe), then bloom with threshold 1.
void PaintThenBloom(vtkRenderWindow* window, const char* paint, vtkFXPipelinePass* pipeline,
  PaintProbe* probe, vtkFXBloomPass* bloom, int width = 400, int height = 300)
{
  window->SetSize(width, height);
  MakeScene(window, nullptr)->SetPass(pipeline);
  probe->Paint = paint;
  pipeline->AddEffect("paint", probe);
  bloom->SetThreshold(1.0);
  pipeline->AddEffect("bloom", bloom);
}

int CheckHotPixels(vtkRenderWindow* window)
{
  vtkNew<vtkFXPipelinePass> pipeline;
  vtkNew<PaintProbe> probe;
  vtkNew<vtkFXBloomPass> bloom;
  PaintThenBloom(window,
    "  if (p == ivec2(100, 150)) color = vec4(vec3(big), 1.0);\n"
    "  else if (p == ivec2(300, 150)) color = vec4(zero / zero);\n"
    "  else discard;",
    pipeline, probe, bloom);
  float largestOn = 0.0f;
  for (bool suppress : { true, false })
  {
    bloom->SetFireflySuppression(suppress);
    window->Render();
    const std::string passes = vtkFXTest::Passes(pipeline);
    FX_CHECK(passes.find("paint") < passes.find("bloom"), passes);
    const auto glow = vtkFXTest::Download(bloom->GetGlowTexture(), 4);
    FX_CHECK(!glow.empty(), "no glow texture");
    float largest = 0.0f;
    for (size_t i = 0; i < glow.size(); ++i)
    {
      FX_CHECK(std::isfinite(glow[i]), "a non-finite glow value");
      largest = i % 4 == 3 ? largest : std::max(largest, glow[i]); // RGB, not alpha
    }
    std::cout << "hot pixels, firefly suppression " << (suppress ? "on" : "off")
              << ": largest glow " << largest << std::endl;
    // On, the 1e30 pixel (clamped to 65504, minus the threshold) weighs
    // like one of value ~1 in the first taps: its glow stays below 0.2
    // (measured 0.099), but is there; off, it glows as the clamped value
    // it is, hundreds of times more (so the pixel did reach the bloom).
    if (suppress)
    {
      largestOn = largest;
      FX_CHECK(largest > 0.0f && largest < 0.2f, "a firefly grew a glow of " << largest);
    }
    else
    {
      FX_CHECK(largest > 100.0f * largestOn, "without suppression the firefly glows only " << largest);
    }
  }
  return EXIT_SUCCESS;
}

// The same through the emission channel: two specks of about one pixel
// beside a dark sphere, one emitting 1e30 (+inf in the half-float
// channel), one NaN. The glow stays finite everywhere; with firefly
// suppression the 1e30 speck adds about what a pixel of value 1 would
// (the glow's largest value below 0.2, the image at most 0.1 brighter
// anywhere), without it at least 100 times more.
int CheckHotEmission(vtkRenderWindow* window)
{
  window->SetSize(400, 300);
  vtkRenderer* renderer = MakeScene(window, nullptr);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double hot[2][3] = { { 1e30, 1e30, 1e30 }, { nan, nan, nan } };
  for (int k = 0; k < 2; ++k)
  {
    renderer->AddActor(Sphere(k ? 0.45 : -0.45, 0.002, hot[k]));
  }
  vtkNew<vtkFXPipelinePass> pipeline;
  renderer->SetPass(pipeline);
  window->Render();
  const auto without = vtkFXScenes::Capture(window);
  vtkNew<vtkFXBloomPass> bloom;
  pipeline->AddEffect("bloom", bloom);
  float largestOn = 0.0f;
  for (bool suppress : { true, false })
  {
    bloom->SetFireflySuppression(suppress);
    window->Render();
    const auto glow = vtkFXTest::Download(bloom->GetGlowTexture(), 4);
    FX_CHECK(!glow.empty(), "no glow texture");
    float largest = 0.0f;
    for (size_t i = 0; i < glow.size(); ++i)
    {
      FX_CHECK(std::isfinite(glow[i]), "a non-finite glow value from a hot emission");
      largest = i % 4 == 3 ? largest : std::max(largest, glow[i]);
    }
    const auto with = vtkFXScenes::Capture(window);
    int brighter = 0;
    for (size_t i = 0; i < with.size() && i < without.size(); ++i)
    {
      brighter = std::max(brighter, int(with[i]) - int(without[i]));
    }
    std::cout << "hot emission (1e30 and NaN specks), firefly suppression "
              << (suppress ? "on" : "off") << ": largest glow " << largest
              << ", image brighter by up to " << brighter << " levels" << std::endl;
    if (suppress)
    {
      largestOn = largest;
      FX_CHECK(largest > 0.0f && largest < 0.2f, "a 1e30 speck grew a glow of " << largest);
      FX_CHECK(brighter <= 26, "a 1e30 speck brightened the image by " << brighter << " levels");
    }
    else
    {
      FX_CHECK(largest > 100.0f * largestOn, "without suppression the speck glows only " << largest);
    }
  }
  return EXIT_SUCCESS;
}

// Light above a threshold glows, with the soft knee's weights: a square of
// value 2 over threshold 1 (knee 1/2) gives (2 - 1) per channel, one of
// 0.8 (inside the knee) 0.8 x (0.8 - 1 + 0.5)^2 / (4 x 0.5) / 0.8 = 0.045.
// The glow's total (firefly suppression off) is the squares' areas times
// those, within 2%; the HDR target is kept, as the threshold reads it.
int CheckThreshold(vtkRenderWindow* window)
{
  vtkNew<vtkFXPipelinePass> pipeline;
  vtkNew<PaintProbe> probe;
  vtkNew<vtkFXBloomPass> bloom;
  PaintThenBloom(window,
    "  if (all(greaterThanEqual(p, ivec2(100, 100))) && all(lessThan(p, ivec2(140, 140))))\n"
    "    color = vec4(2.0, 2.0, 2.0, 1.0);\n"
    "  else if (all(greaterThanEqual(p, ivec2(250, 100))) && all(lessThan(p, ivec2(290, 140))))\n"
    "    color = vec4(0.8, 0.8, 0.8, 1.0);\n"
    "  else discard;",
    pipeline, probe, bloom);
  bloom->SetKnee(0.5);
  bloom->FireflySuppressionOff();
  pipeline->AddEffect("bloom", bloom);
  window->Render();
  const std::string passes = vtkFXTest::Passes(pipeline);
  FX_CHECK(passes.find("hdr-target") != std::string::npos, passes);
  // Nothing emits: the threshold reads the lit image, and no emission
  // channel is allocated for it.
  FX_CHECK(!(pipeline->GetGBufferChannels() & GB::ChannelBit(GB::Emission)),
    "an emission channel for a threshold alone");
  const double glow = 4.0 * Sum(vtkFXTest::Download(bloom->GetGlowTexture(), 4), 4, 3);
  const double expected = 3.0 * 40.0 * 40.0 * (1.0 + 0.045);
  std::cout << "threshold: glow " << glow << ", expected " << expected << " (ratio "
            << glow / expected << ")" << std::endl;
  FX_CHECK(std::fabs(glow / expected - 1.0) < 0.02, "glow " << glow << " for " << expected);
  return EXIT_SUCCESS;
}

// At an odd size each half-resolution texel still takes exactly two
// columns, so a bright column glows the same wherever it is (the stretched
// mapping stepped 1 or 3 columns at places, and columns there counted up
// to a quarter more or less). One column above the threshold (1 over it per
// pixel and channel) at a few places: the glow's total is its own.
int CheckThresholdOddSize(vtkRenderWindow* window)
{
  for (int column : { 20, 199, 200, 201, 202, 203 })
  {
    vtkNew<vtkFXPipelinePass> pipeline;
    vtkNew<PaintProbe> probe;
    vtkNew<vtkFXBloomPass> bloom;
    const std::string paint = "  color = p.x == " + std::to_string(column) +
      " ? vec4(2.0, 2.0, 2.0, 1.0) : vec4(0.0, 0.0, 0.0, 1.0);";
    PaintThenBloom(window, paint.c_str(), pipeline, probe, bloom, 401, 301);
    bloom->SetKnee(0.0);
    bloom->FireflySuppressionOff();
    window->Render();
    const double glow = GlowTotal(bloom);
    const double expected = 3.0 * 301.0;
    std::cout << "threshold at 401x301, column " << column << " glows " << glow << " (ratio "
              << glow / expected << ")" << std::endl;
    FX_CHECK(std::fabs(glow / expected - 1.0) < 0.01, "column " << column << ": " << glow);
  }
  return EXIT_SUCCESS;
}

// Light at the image's edges, at sizes whose levels are odd (the last texel
// of a level then lies partly outside the image): a 2x2 block 1 above the
// threshold in each corner and at the middle of the top and right edges
// adds exactly its light to the HDR image (Intensity 1, knee 0, no firefly
// suppression): the sum of the target with the glow minus the painted
// image's is 4 x 3 within 4%. Measured: 0.2-0.3% low at the bottom-left
// corner, where every level's texels meet the image's edge; 1.2-1.4% high
// at a top or right edge, where an odd level's texels straddle it and the
// pyramid's sampling is no longer symmetric about the mirror; 2.8-3.0% at
// the top-right corner, both at once. Mirroring at the levels' texture
// edges, up to half a texel past the image, added 1.44 to 1.76 times the
// light at those edges and 2.2 to 3.5 times at that corner.
int CheckEdgeEnergy(vtkRenderWindow* window)
{
  for (const int size : { 301, 601 })
  {
    const std::string n = std::to_string(size);
    const std::string last = std::to_string(size - 2);
    const std::string middle = std::to_string(size / 2);
    for (const std::string& where : std::vector<std::string>{ "p.x >= " + last + " && p.y >= " + last,
           "p.x < 2 && p.y < 2", "p.x < 2 && p.y >= " + last, "p.x >= " + last + " && p.y < 2",
           "p.y >= " + last + " && p.x >= " + middle + " && p.x < " + middle + " + 2",
           "p.x >= " + last + " && p.y >= " + middle + " && p.y < " + middle + " + 2" })
    {
      vtkNew<vtkFXPipelinePass> pipeline;
      vtkNew<PaintProbe> probe;
      vtkNew<vtkFXBloomPass> bloom;
      const std::string paint = "  color = (" + where +
        ") ? vec4(2.0, 2.0, 2.0, 1.0) : vec4(0.0, 0.0, 0.0, 1.0);";
      PaintThenBloom(window, paint.c_str(), pipeline, probe, bloom, size, size);
      bloom->SetKnee(0.0);
      bloom->FireflySuppressionOff();
      bloom->SetIntensity(1.0);
      window->Render();
      const std::string passes = vtkFXTest::Passes(pipeline);
      FX_CHECK(passes.find("bloom") != std::string::npos, passes);
      // (the painted image alone sums to 2 x 4 x 3)
      const double added =
        Sum(vtkFXTest::Download(pipeline->GetHDRTargetPass()->GetColorTexture(), 4), 4, 3) - 24.0;
      std::cout << "edges at " << n << "x" << n << ", light where " << where << ": added "
                << added << " (ratio " << added / 12.0 << ", "
                << bloom->GetNumberOfLevels(size, size) << " levels)" << std::endl;
      FX_CHECK(std::fabs(added / 12.0 - 1.0) < 0.04, where << " at " << n << ": added " << added);
      window->GetRenderers()->GetFirstRenderer()->SetPass(nullptr);
    }
  }
  return EXIT_SUCCESS;
}

// An emissive prop under a threshold of 0 without knee: its lit colour is
// all emission, which glows from the channel; the threshold takes the
// reflected light only (none here), so the glow is the emission's alone,
// not twice it.
int CheckEmissionAndThreshold(vtkRenderWindow* window)
{
  window->SetSize(400, 300);
  const double emission[3] = { 0.5, 0.4, 0.3 };
  vtkNew<vtkFXPipelinePass> pipeline;
  vtkNew<vtkFXBloomPass> bloom;
  bloom->FireflySuppressionOff();
  std::vector<unsigned char> without, with;
  RenderWithoutAndWith(window, emission, pipeline, bloom, without, with);
  const double emissionOnly = GlowTotal(bloom);
  bloom->SetThreshold(0.0);
  bloom->SetKnee(0.0);
  window->Render();
  const std::string passes = vtkFXTest::Passes(pipeline);
  const double both = GlowTotal(bloom);
  std::cout << "emission " << emissionOnly << " glows, with a threshold of 0 as well " << both
            << " (" << passes << ")" << std::endl;
  FX_CHECK(passes.find("hdr-target") != std::string::npos, passes);
  FX_CHECK(emissionOnly > 1000.0, "no glow from the emission");
  FX_CHECK(std::fabs(both / emissionOnly - 1.0) < 0.02, "emission counted twice: " << both);
  return EXIT_SUCCESS;
}

// No opaque prop: a translucent sphere lit brighter than 1 glows under a
// threshold (the lit image is the HDR target's, whatever drew it).
int CheckThresholdWithoutOpaqueProps(vtkRenderWindow* window)
{
  window->SetSize(200, 150);
  vtkRenderer* renderer = MakeScene(window, nullptr);
  vtkActor* sphere = vtkActor::SafeDownCast(renderer->GetActors()->GetItemAsObject(0));
  sphere->GetProperty()->SetColor(1.0, 1.0, 1.0);
  sphere->GetProperty()->SetOpacity(0.5);
  vtkNew<vtkLight> light;
  light->SetLightTypeToHeadlight();
  light->SetIntensity(8.0);
  renderer->AddLight(light);
  vtkNew<vtkFXPipelinePass> pipeline;
  vtkNew<vtkFXBloomPass> bloom;
  bloom->SetThreshold(1.0);
  bloom->FireflySuppressionOff();
  pipeline->AddEffect("bloom", bloom);
  renderer->SetPass(pipeline);
  window->Render();
  const std::string passes = vtkFXTest::Passes(pipeline);
  const double glow = bloom->GetGlowTexture() ? GlowTotal(bloom) : 0.0;
  std::cout << "threshold with translucent props only: glow " << glow << " (" << passes << ")"
            << std::endl;
  FX_CHECK(passes.find("bloom") != std::string::npos && passes.find("gbuffer") == std::string::npos,
    passes);
  FX_CHECK(glow > 100.0, "no glow from the translucent sphere: " << glow);
  renderer->SetPass(nullptr);
  return EXIT_SUCCESS;
}

// A NaN knee is refused with an error (it would make the threshold's
// weights NaN); the knee set before stays.
// An emitter behind an opaque prop the G-buffer does not capture (a
// vtkImageActor slice, drawn forward): hidden, nothing may glow (the slice
// fills the view); half hidden (the slice covers x < 0), the glow is half
// the whole sphere's (0.45 to 0.55: its half-disc, less the pixels on the
// slice's edge).
vtkSmartPointer<vtkImageActor> Slice(double xMax)
{
  const unsigned char grey[3] = { 60, 60, 60 };
  return vtkFXTest::UniformSlice(-3.0, xMax, -3.0, 3.0, 0.5, grey);
}

int CheckHiddenEmitter(vtkRenderWindow* window)
{
  const double emission[3] = { 4.0, 3.0, 2.0 };
  {
    vtkNew<vtkFXPipelinePass> pipeline;
    vtkNew<vtkFXBloomPass> bloom;
    std::vector<unsigned char> without, with;
    RenderWithoutAndWith(window, emission, pipeline, bloom, without, with,
      [](vtkRenderer* renderer) { renderer->AddViewProp(Slice(3.0)); });
    const int difference = vtkFXScenes::MaxDifference(without, with);
    std::cout << "an emitter behind a forward-drawn slice: largest change by bloom " << difference
              << ", image sum " << ImageSum(without) << " -> " << ImageSum(with) << std::endl;
    FX_CHECK(difference == 0, "a hidden emitter glows: " << difference << " levels");
    FX_CHECK(pipeline->GetHDRTargetBytesPerPixel() > 0, "the mask ran without the HDR target");
  }
  // A 2D prop (drawn in the overlay, after the glow) hides nothing: no
  // HDR target for it.
  {
    vtkNew<vtkFXPipelinePass> pipeline;
    vtkNew<vtkFXBloomPass> bloom;
    std::vector<unsigned char> without, with;
    RenderWithoutAndWith(window, emission, pipeline, bloom, without, with, [](vtkRenderer* renderer) {
      vtkNew<vtkTextActor> label;
      label->SetInput("label");
      renderer->AddViewProp(label);
    });
    FX_CHECK(pipeline->GetHDRTargetBytesPerPixel() == 0 && vtkFXScenes::MaxDifference(without, with) > 0,
      "an emitter beside a 2D prop: HDR target " << pipeline->GetHDRTargetBytesPerPixel()
                                                 << " bytes per pixel");
  }
  double totals[2];
  for (int half = 0; half < 2; ++half)
  {
    vtkNew<vtkFXPipelinePass> pipeline;
    vtkNew<vtkFXBloomPass> bloom;
    bloom->FireflySuppressionOff();
    std::vector<unsigned char> without, with;
    RenderWithoutAndWith(window, emission, pipeline, bloom, without, with, [half](vtkRenderer* renderer) {
      renderer->AddViewProp(Slice(half ? 0.0 : -2.9)); // (a sliver at the border, else)
    });
    totals[half] = GlowTotal(bloom);
  }
  std::cout << "an emitter half behind a forward-drawn slice: glow " << totals[1] << " of "
            << totals[0] << " (" << totals[1] / totals[0] << ")" << std::endl;
  FX_CHECK(totals[0] > 0.0 && totals[1] / totals[0] > 0.45 && totals[1] / totals[0] < 0.55,
    "an emitter half hidden: glow " << totals[1] << " of " << totals[0]);
  return EXIT_SUCCESS;
}

// What is drawn over an emitter after the opaque layer dims its glow by its
// transmittance T, as it dims the emitter itself: a translucent plane of
// opacity 0.5 filling the view in front of the sphere (T = 0.5 exactly,
// under VTK's order-independent transparency and under depth peeling) and
// a slab of volume between them (opaque: T = 0; black, so it adds no
// light). The glow is measured against the sphere's glow with nothing in
// front; the plane's edges lie outside the view, so every emissive pixel
// sees T. A plane beside the sphere on screen dims nothing and costs
// nothing: no HDR target for it.
vtkSmartPointer<vtkActor> TranslucentPlane(double opacity, double xMin = -3.0)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(xMin, -3.0, 0.5);
  plane->SetPoint1(3.0, -3.0, 0.5);
  plane->SetPoint2(xMin, 3.0, 0.5);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(plane->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.2, 0.2, 0.2);
  actor->GetProperty()->SetOpacity(opacity);
  return actor;
}

vtkSmartPointer<vtkVolume> BlackSlab(double opacity, double unitDistance)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(5, 5, 3);
  image->SetSpacing(1.5, 1.5, 0.1);
  image->SetOrigin(-3.0, -3.0, 0.45);
  image->AllocateScalars(VTK_FLOAT, 1);
  auto* values = static_cast<float*>(image->GetScalarPointer());
  std::fill(values, values + 75, 1.0f);
  vtkNew<vtkGPUVolumeRayCastMapper> mapper;
  mapper->SetInputData(image);
  vtkNew<vtkPiecewiseFunction> opacities;
  opacities->AddPoint(0.0, opacity);
  opacities->AddPoint(2.0, opacity);
  vtkNew<vtkColorTransferFunction> colors;
  colors->AddRGBPoint(0.0, 0.0, 0.0, 0.0);
  colors->AddRGBPoint(2.0, 0.0, 0.0, 0.0);
  auto volume = vtkSmartPointer<vtkVolume>::New();
  volume->SetMapper(mapper);
  volume->GetProperty()->SetScalarOpacity(opacities);
  volume->GetProperty()->SetColor(colors);
  volume->GetProperty()->SetScalarOpacityUnitDistance(unitDistance);
  return volume;
}

int CheckEmitterBehindTranslucency(vtkRenderWindow* window)
{
  const double emission[3] = { 4.0, 3.0, 2.0 };
  struct Case
  {
    const char* Name;
    double Expected, Tolerance;
    bool Target; // whether the HDR target is expected
    std::function<void(vtkRenderer*)> Arrange;
  };
  const Case cases[] = {
    { "nothing in front", 1.0, 1e-9, false, [](vtkRenderer*) {} },
    { "a translucent plane beside it", 1.0, 1e-9, false,
      [](vtkRenderer* renderer) { renderer->AddActor(TranslucentPlane(0.5, 0.45)); } },
    { "a translucent plane (opacity 0.5)", 0.5, 0.02, true,
      [](vtkRenderer* renderer) { renderer->AddActor(TranslucentPlane(0.5)); } },
    { "the same plane, depth peeling", 0.5, 0.02, true,
      [](vtkRenderer* renderer) {
        renderer->AddActor(TranslucentPlane(0.5));
        renderer->UseDepthPeelingOn();
      } },
    { "an opaque volume", 0.0, 0.01, true,
      [](vtkRenderer* renderer) { renderer->AddVolume(BlackSlab(1.0, 0.01)); } },
    { "a volume of optical depth ln 2", 0.5, 0.03, true,
      [](vtkRenderer* renderer) { renderer->AddVolume(BlackSlab(0.5, 0.2)); } },
  };
  double whole = 0.0;
  for (const Case& c : cases)
  {
    vtkNew<vtkFXPipelinePass> pipeline;
    vtkNew<vtkFXBloomPass> bloom;
    bloom->FireflySuppressionOff();
    std::vector<unsigned char> without, with;
    RenderWithoutAndWith(window, emission, pipeline, bloom, without, with, [&c](vtkRenderer* renderer) {
      c.Arrange(renderer);
      renderer->ResetCameraClippingRange();
    });
    const std::string passes = vtkFXTest::Passes(pipeline);
    const double glow = GlowTotal(bloom);
    whole = whole > 0.0 ? whole : glow;
    std::cout << "an emitter behind " << c.Name << ": glow " << glow << " of " << whole << " ("
              << glow / whole << ", expected " << c.Expected << ") (" << passes << ")" << std::endl;
    FX_CHECK(whole > 1000.0, "no glow");
    FX_CHECK(std::fabs(glow / whole - c.Expected) <= c.Tolerance,
      c.Name << ": glow " << glow / whole << " of the whole, expected " << c.Expected);
    FX_CHECK((pipeline->GetHDRTargetBytesPerPixel() > 0) == c.Target, c.Name << ": " << passes);
    FX_CHECK(std::string(c.Name).find("plane") == std::string::npos ||
        passes.find("translucent") != std::string::npos,
      c.Name << ": the plane was not drawn: " << passes);
    window->GetRenderers()->GetFirstRenderer()->SetPass(nullptr);
  }
  // The mark leaves colours alone: a dim emitter on a grey background
  // behind a plane of opacity 0 (under order-independent transparency and
  // under depth peeling) or a volume of opacity 0 gives the image it gives
  // with nothing in front (which brings the HDR target and the mark; a
  // mark that scaled colours, 1024 x the emitter's less 1023 x the
  // background, would show as 0).
  const double dim[3] = { 0.2, 0.1, 0.05 };
  std::vector<unsigned char> alone;
  for (int what = 0; what < 4; ++what)
  {
    vtkNew<vtkFXPipelinePass> pipeline;
    vtkNew<vtkFXBloomPass> bloom;
    std::vector<unsigned char> without, with;
    RenderWithoutAndWith(window, dim, pipeline, bloom, without, with, [what](vtkRenderer* renderer) {
      renderer->SetBackground(0.5, 0.5, 0.5);
      if (what == 1 || what == 2)
      {
        renderer->AddActor(TranslucentPlane(0.0));
        renderer->SetUseDepthPeeling(what == 2);
      }
      else if (what == 3)
      {
        renderer->AddVolume(BlackSlab(0.0, 0.2));
      }
      renderer->ResetCameraClippingRange();
    });
    const std::string passes = vtkFXTest::Passes(pipeline);
    window->GetRenderers()->GetFirstRenderer()->SetPass(nullptr);
    if (what == 0)
    {
      alone = with;
      continue;
    }
    const int difference = vtkFXScenes::MaxDifference(alone, with);
    std::cout << "a dim emitter behind a plane or volume of opacity 0 (" << what
              << "): largest difference " << difference << " from nothing in front (" << passes
              << ")" << std::endl;
    FX_CHECK(passes.find("hdr-target") != std::string::npos, passes);
    FX_CHECK(difference <= 1, "case " << what << ": opacity 0 changed the image by " << difference);
  }
  return EXIT_SUCCESS;
}

// Keys set on an assembly, as the README says to set them (VTK hands them
// to its parts as it renders them, and already when asked whether it has
// opaque or translucent geometry, which the scene analysis asks first):
// its part glows from the first frame, as much as in the second.
int CheckAssemblyKeysFirstFrame(vtkRenderWindow* window)
{
  window->SetSize(400, 300);
  window->GetRenderers()->RemoveAllItems();
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  renderer->SetBackground(0.0, 0.0, 0.0);
  vtkNew<vtkAssembly> assembly;
  assembly->AddPart(Sphere(0.0, 0.3, nullptr));
  vtkNew<vtkInformation> keys;
  const double emission[3] = { 2.0, 1.0, 0.5 };
  keys->Set(GB::EMISSIVE_COLOR(), emission, 3);
  assembly->SetPropertyKeys(keys);
  renderer->AddViewProp(assembly);
  renderer->ResetCamera();
  vtkNew<vtkFXPipelinePass> pipeline;
  vtkNew<vtkFXBloomPass> bloom;
  bloom->FireflySuppressionOff();
  pipeline->AddEffect("bloom", bloom);
  renderer->SetPass(pipeline);
  double glow[2];
  std::string passes[2];
  for (int frame = 0; frame < 2; ++frame)
  {
    window->Render();
    passes[frame] = vtkFXTest::Passes(pipeline);
    glow[frame] = passes[frame].find("bloom") != std::string::npos && bloom->GetGlowTexture()
      ? GlowTotal(bloom)
      : 0.0;
  }
  std::cout << "emission keys on an assembly: glow " << glow[0] << " in the first frame, "
            << glow[1] << " in the second (" << passes[0] << ")" << std::endl;
  FX_CHECK(glow[1] > 1000.0 && std::fabs(glow[0] / glow[1] - 1.0) < 1e-6,
    "the first frame's glow " << glow[0] << " against " << glow[1]);
  renderer->SetPass(nullptr);
  return EXIT_SUCCESS;
}

int CheckBadParameters()
{
  vtkNew<vtkFXBloomPass> bloom;
  vtkFXTest::ErrorCounter errors(bloom);
  bloom->SetKnee(0.25);
  bloom->SetKnee(std::numeric_limits<double>::quiet_NaN());
  std::cout << "NaN knee: " << errors.Count << " error(s), knee " << bloom->GetKnee() << std::endl;
  FX_CHECK(errors.Count == 1 && bloom->GetKnee() == 0.25, "NaN knee");
  bloom->SetKnee(7.0);
  FX_CHECK(bloom->GetKnee() == 1.0, "knee clamped to 1");
  return EXIT_SUCCESS;
}
}

int TestBloom(int, char*[])
{
  // One window for every part: a window per part can exhaust a virtual X
  // server's connections.
  auto window = vtkFXTest::MakeWindow(400, 300);
  FX_CHECK(CheckEnergy(window) == EXIT_SUCCESS, "energy");
  FX_CHECK(CheckNothingToDo(window) == EXIT_SUCCESS, "no emission");
  FX_CHECK(CheckUnlitPrimitivesDoNotGlow(window) == EXIT_SUCCESS, "unlit primitives");
  FX_CHECK(CheckHotPixels(window) == EXIT_SUCCESS, "hot pixels");
  FX_CHECK(CheckHotEmission(window) == EXIT_SUCCESS, "hot emission");
  FX_CHECK(CheckThreshold(window) == EXIT_SUCCESS, "threshold");
  FX_CHECK(CheckThresholdOddSize(window) == EXIT_SUCCESS, "threshold, odd size");
  FX_CHECK(CheckEdgeEnergy(window) == EXIT_SUCCESS, "light at the image's edges");
  FX_CHECK(CheckSplatGlow(window) == EXIT_SUCCESS, "splats and wide points glow whole");
  FX_CHECK(CheckTargetKeepsFrame(window) == EXIT_SUCCESS, "the HDR target keeps the frame's values");
  FX_CHECK(CheckEmissionAndThreshold(window) == EXIT_SUCCESS, "emission and threshold");
  FX_CHECK(CheckThresholdWithoutOpaqueProps(window) == EXIT_SUCCESS, "threshold, no opaque prop");
  FX_CHECK(CheckHiddenEmitter(window) == EXIT_SUCCESS, "hidden emitter");
  FX_CHECK(CheckEmitterBehindTranslucency(window) == EXIT_SUCCESS, "emitter behind translucency");
  FX_CHECK(CheckAssemblyKeysFirstFrame(window) == EXIT_SUCCESS, "keys on an assembly");
  FX_CHECK(CheckBadParameters() == EXIT_SUCCESS, "bad parameters");
  FX_CHECK(CheckGlowAlpha() == EXIT_SUCCESS, "the glow's alpha over a transparent background");
  // A screenshot at scale 2 of a 200x150 viewport is 300 rows high: the
  // glow reaches as far in it as in a 400x300 viewport.
  {
    vtkNew<vtkFXBloomPass> bloom;
    FX_CHECK(bloom->GetNumberOfLevels(200, 150, 300) == bloom->GetNumberOfLevels(400, 300) &&
        bloom->GetNumberOfLevels(200, 150) < bloom->GetNumberOfLevels(400, 300),
      "levels for a scaled screenshot");
  }
  return EXIT_SUCCESS;
}
