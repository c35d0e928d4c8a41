// Bad input never crashes the G-buffer and never puts NaN in it: a mesh
// with NaN points, NaN, infinite and zero normals, and degenerate (zero-area)
// triangles, next to a prop of opacity exactly 0. Reads every channel back
// (the G-buffer alone, all channels requested): all texels are finite and
// every normal is either a valid octahedral code (|x| + |y| <= 1) or the
// unlit sentinel. Then, through the pipeline, the invisible prop stays
// invisible and a scene with no light at all matches VTK's forward render.
#include "vtkFXAVSMPass.h"
#include "vtkFXBilateralBlurPass.h"
#include "vtkFXBloomPass.h"
#include "vtkFXCompositePass.h"
#include "vtkFXDirectionalOcclusionPass.h"
#include "vtkFXGBufferPass.h"
#include "vtkFXSSAOPass.h"
#include "vtkFXPipelinePass.h"
#include "vtkFXToonPass.h"
#include "vtkFXScenes.h"
#include "vtkFXTestUtilities.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCallbackCommand.h"
#include "vtkObjectFactory.h"
#include "vtkVersion.h"
#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkSphereSource.h"

#include <limits>

namespace
{
// A fan of triangles, some degenerate, with a few NaN / infinite normals.
vtkSmartPointer<vtkPolyData> BadMesh()
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkFloatArray> normals;
  normals->SetNumberOfComponents(3);
  normals->SetName("Normals");
  vtkNew<vtkCellArray> polys;
  const int n = 24;
  points->InsertNextPoint(0, 0, 0);
  normals->InsertNextTuple3(0, 0, 1);
  for (int i = 0; i < n; ++i)
  {
    const double a = 2.0 * 3.14159265358979 * i / n;
    points->InsertNextPoint(std::cos(a), std::sin(a), 0.2 * std::sin(3 * a));
    if (i % 5 == 0)
      normals->InsertNextTuple3(nan, 0, 1);
    else if (i % 7 == 0)
      normals->InsertNextTuple3(inf, -inf, 0);
    else if (i % 11 == 0)
      normals->InsertNextTuple3(0, 0, 0);
    else
      normals->InsertNextTuple3(0, 0, 1);
  }
  for (int i = 0; i < n; ++i)
  {
    const vtkIdType tri[3] = { 0, 1 + i, 1 + (i + 1) % n };
    polys->InsertNextCell(3, tri);
    const vtkIdType degenerate[3] = { 1 + i, 1 + i, 1 + (i + 1) % n };
    polys->InsertNextCell(3, degenerate);
  }
  // A triangle through a NaN point.
  const vtkIdType bad = points->InsertNextPoint(nan, 0.5, 0.0);
  normals->InsertNextTuple3(0, 0, 1);
  const vtkIdType withNaN[3] = { 0, 1, bad };
  polys->InsertNextCell(3, withNaN);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(polys);
  poly->GetPointData()->SetNormals(normals);
  return poly;
}
}

// A floating-point parameter set to NaN: refused with one error, the
// value kept (VTK's clamping macro would store NaN, which the shaders then
// read).
template <typename T>
bool RefusesNaN(const char* name, void (T::*set)(double), double (T::*get)())
{
  vtkNew<T> object;
  vtkFXTest::ErrorCounter errors(object);
  const double before = (object->*get)();
  (object.GetPointer()->*set)(std::numeric_limits<double>::quiet_NaN());
  const double after = (object.GetPointer()->*get)();
  std::cout << object->GetClassName() << "::Set" << name << "(NaN): " << errors.Count
            << " error(s), " << before << " -> " << after << std::endl;
  return errors.Count == 1 && after == before;
}

int CheckParametersRefuseNaN()
{
  using A = vtkFXAVSMPass;
  using B = vtkFXBilateralBlurPass;
  using G = vtkFXBloomPass;
  using C = vtkFXCompositePass;
  using D = vtkFXDirectionalOcclusionPass;
  using S = vtkFXSSAOPass;
  using T = vtkFXToonPass;
  const bool all[] = {
    RefusesNaN<A>("Bias", &A::SetBias, &A::GetBias),
    RefusesNaN<A>("SplatRadius", &A::SetSplatRadius, &A::GetSplatRadius),
    RefusesNaN<B>("DepthSigma", &B::SetDepthSigma, &B::GetDepthSigma),
    RefusesNaN<G>("Intensity", &G::SetIntensity, &G::GetIntensity),
    RefusesNaN<G>("Radius", &G::SetRadius, &G::GetRadius),
    RefusesNaN<G>("Threshold", &G::SetThreshold, &G::GetThreshold),
    RefusesNaN<G>("Knee", &G::SetKnee, &G::GetKnee),
    RefusesNaN<C>("LightCutoff", &C::SetLightCutoff, &C::GetLightCutoff),
    RefusesNaN<C>("MaterialColorScale", &C::SetMaterialColorScale, &C::GetMaterialColorScale),
    RefusesNaN<C>(
      "OcclusionDiffuseStrength", &C::SetOcclusionDiffuseStrength, &C::GetOcclusionDiffuseStrength),
    RefusesNaN<D>("Bleeding", &D::SetBleeding, &D::GetBleeding),
    RefusesNaN<S>("Radius", &S::SetRadius, &S::GetRadius),
    RefusesNaN<S>("RadiusFraction", &S::SetRadiusFraction, &S::GetRadiusFraction),
    RefusesNaN<S>("Bias", &S::SetBias, &S::GetBias),
    RefusesNaN<T>("SilhouetteThreshold", &T::SetSilhouetteThreshold, &T::GetSilhouetteThreshold),
    RefusesNaN<T>("CreaseAngle", &T::SetCreaseAngle, &T::GetCreaseAngle),
    RefusesNaN<T>("LineWidth", &T::SetLineWidth, &T::GetLineWidth),
  };
  for (bool refused : all)
  {
    FX_CHECK(refused, "a parameter took NaN");
  }
  // A colour: NaN refused, the others clamped to 0..65504.
  vtkNew<T> toon;
  vtkFXTest::ErrorCounter errors(toon);
  toon->SetLineColor(0.2, 0.3, 0.4);
  toon->SetLineColor(0.5, std::numeric_limits<double>::quiet_NaN(), 0.5);
  double color[3];
  toon->GetLineColor(color);
  std::cout << "vtkFXToonPass::SetLineColor(0.5, NaN, 0.5): " << errors.Count << " error(s), "
            << color[0] << " " << color[1] << " " << color[2] << " kept" << std::endl;
  FX_CHECK(errors.Count == 1 && color[0] == 0.2 && color[1] == 0.3 && color[2] == 0.4,
    "the line colour took NaN");
  const double out[3] = { -1.0, 2.0, 1e9 };
  toon->SetLineColor(out);
  toon->GetLineColor(color);
  FX_CHECK(color[0] == 0.0 && color[1] == 2.0 && color[2] == 65504.0,
    "the line colour was not clamped: " << color[0] << " " << color[1] << " " << color[2]);
  return EXIT_SUCCESS;
}

// A driver that cannot make the G-buffer (no memory for its channels at a
// huge size, say): simulated by a factory override of vtkFXGBufferPass
// whose framebuffer never completes.
class FailingGBuffer : public vtkFXGBufferPass
{
public:
  static FailingGBuffer* New();
  vtkTypeMacro(FailingGBuffer, vtkFXGBufferPass);

protected:
  bool FrameBufferComplete() override { return false; }
};
vtkStandardNewMacro(FailingGBuffer);

class FailingGBufferFactory : public vtkObjectFactory
{
public:
  static FailingGBufferFactory* New()
  {
    auto* f = new FailingGBufferFactory;
    f->InitializeObjectBase();
    return f;
  }
  const char* GetVTKSourceVersion() override { return VTK_SOURCE_VERSION; }
  const char* GetDescription() override { return "a G-buffer that cannot be made"; }

protected:
  FailingGBufferFactory()
  {
    this->RegisterOverride("vtkFXGBufferPass", "FailingGBuffer", "test", 1,
      []() -> vtkObject* { return FailingGBuffer::New(); });
  }
};

// Without its G-buffer the pipeline still shows the scene: the opaque props
// drawn forward (as VTK draws them: the image within 50 dB of VTK's own),
// one error said, and the composite and the effects that read the G-buffer
// (ambient occlusion, lines) left out.
int CheckGBufferFailure(vtkRenderWindow* window)
{
  window->GetRenderers()->RemoveAllItems();
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  std::string error;
  vtkFXScenes::Populate(renderer, "scene:corner", vtkFXScenes::Options(), error);
  // The largest prop translucent: the others hide parts of it only where
  // the frame keeps their depth (the HDR target, which the bloom
  // schedules, starts from the framebuffer's depth then).
  vtkActor* largest = nullptr;
  vtkCollectionSimpleIterator it;
  renderer->GetActors()->InitTraversal(it);
  while (vtkActor* actor = renderer->GetActors()->GetNextActor(it))
  {
    largest = (!largest || actor->GetLength() > largest->GetLength()) ? actor : largest;
  }
  FX_CHECK(largest, "scene:corner has props");
  largest->GetProperty()->SetOpacity(0.5);
  renderer->SetPass(nullptr);
  window->Render();
  const auto forward = vtkFXScenes::Capture(window);

  vtkNew<FailingGBufferFactory> factory;
  vtkObjectFactory::RegisterFactory(factory);
  vtkNew<vtkFXPipelinePass> pipeline;
  vtkObjectFactory::UnRegisterFactory(factory);
  FX_CHECK(pipeline->GetGBufferPass()->IsA("FailingGBuffer"), "the override is in place");
  int errors = 0;
  vtkNew<vtkCallbackCommand> countErrors;
  countErrors->SetClientData(&errors);
  countErrors->SetCallback(
    [](vtkObject*, unsigned long, void* count, void*) { ++*static_cast<int*>(count); });
  pipeline->GetGBufferPass()->AddObserver(vtkCommand::ErrorEvent, countErrors);
  pipeline->AmbientOcclusionOn();
  vtkNew<vtkFXToonPass> toon;
  pipeline->AddEffect("toon", toon);
  // (a glow of nothing: light above 100 only; it brings the HDR target)
  vtkNew<vtkFXBloomPass> bloom;
  bloom->SetThreshold(100.0);
  pipeline->AddEffect("bloom", bloom);
  renderer->SetPass(pipeline);
  window->Render();
  window->Render();
  const auto image = vtkFXScenes::Capture(window);
  const std::string passes = vtkFXTest::Passes(pipeline);
  const double psnr = vtkFXScenes::PSNR(forward, image);
  std::cout << "G-buffer that cannot be made: passes " << passes << ", " << errors
            << " error(s), PSNR " << psnr << " dB against VTK's forward render" << std::endl;
  FX_CHECK(!pipeline->GetGBufferPass()->GetFrameComplete(), "the failure is reported");
  FX_CHECK(errors == 1, errors << " errors for two frames");
  FX_CHECK(passes.find("composite") == std::string::npos &&
      passes.find("ssao") == std::string::npos && passes.find("toon") == std::string::npos &&
      passes.find("gbuffer") != std::string::npos,
    passes);
  FX_CHECK(psnr >= 45.0, "the opaque props drawn forward: " << psnr << " dB");
  renderer->SetPass(nullptr);
  return EXIT_SUCCESS;
}

int TestRobustness(int, char*[])
{
  FX_CHECK(CheckParametersRefuseNaN() == EXIT_SUCCESS, "parameters and NaN");
  auto window = vtkFXTest::MakeWindow(200, 160);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(BadMesh());
  vtkNew<vtkActor> bad;
  bad->SetMapper(mapper);
  bad->GetProperty()->SetSpecular(1.0);
  bad->GetProperty()->SetSpecularPower(128.0);
  bad->GetProperty()->SetAmbient(1.0);
  renderer->AddActor(bad);

  // Opacity exactly 0, forced opaque: invisible, in front of the mesh's
  // centre. VTK blends it in its opaque step, so the G-buffer leaves it to
  // be drawn forward (vtkFXGBufferPass::CanCapture; an unforced one is
  // translucent), and the mesh's channels behind it stay finite.
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0, 0, 0.5);
  sphere->SetRadius(0.3);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> invisible;
  invisible->SetMapper(sphereMapper);
  invisible->GetProperty()->SetOpacity(0.0);
  invisible->ForceOpaqueOn();
  invisible->GetProperty()->SetColor(1, 0, 0);
  renderer->AddActor(invisible);
  renderer->ResetCamera();

  // The G-buffer alone, every channel requested (its default).
  vtkFXGBufferPass* gbuffer = vtkFXTest::InstallGBufferAlone(renderer);
  window->Render();
  FX_CHECK(gbuffer->GetAllocatedChannels() == (1u << vtkFXGBufferPass::NumberOfChannels) - 1,
    "all channels allocated");
  int covered = 0;
  for (int c = 0; c < vtkFXGBufferPass::NumberOfChannels; ++c)
  {
    const int components =
      (c == vtkFXGBufferPass::Normal || c == vtkFXGBufferPass::GeometricNormal) ? 2
      : c == vtkFXGBufferPass::LinearDepth                                    ? 1
                                                                              : 4;
    const auto values = vtkFXTest::Download(gbuffer->GetChannelTexture(c), components);
    FX_CHECK(!values.empty(), "channel " << vtkFXGBufferPass::GetChannelName(c) << " read back");
    for (size_t i = 0; i < values.size(); ++i)
    {
      FX_CHECK(std::isfinite(values[i]),
        vtkFXGBufferPass::GetChannelName(c) << " texel " << i / components << " is " << values[i]);
    }
    if (c == vtkFXGBufferPass::Normal)
    {
      for (size_t i = 0; i < values.size(); i += 2)
      {
        const bool sentinel = values[i] == 4.0f && values[i + 1] == 4.0f;
        const bool valid = std::fabs(values[i]) + std::fabs(values[i + 1]) <= 1.0f + 1e-3f;
        FX_CHECK(sentinel || valid, "normal code (" << values[i] << ", " << values[i + 1] << ")");
        covered += valid ? 1 : 0;
      }
    }
  }
  std::cout << covered << " lit texels, every channel finite" << std::endl;
  FX_CHECK(covered > 1000, "the mesh is visible");

  // Through the pipeline: the opacity-0 sphere shows nothing.
  vtkNew<vtkFXPipelinePass> pipeline;
  renderer->SetPass(nullptr);
  window->Render();
  const auto forward = vtkFXScenes::Capture(window);
  renderer->SetPass(pipeline);
  window->Render();
  const auto deferred = vtkFXScenes::Capture(window);
  FX_CHECK(pipeline->GetLastSceneInfo().OpaqueProps.size() == 1 &&
      pipeline->GetLastSceneInfo().ForwardOpaqueProps.size() == 1,
    "the opacity-0 sphere is drawn forward");
  const size_t centre = 3 * (80 * 200 + 100);
  std::cout << "centre pixel: VTK " << int(forward[centre]) << "," << int(forward[centre + 1]) << ","
            << int(forward[centre + 2]) << " vtkFX " << int(deferred[centre]) << ","
            << int(deferred[centre + 1]) << "," << int(deferred[centre + 2]) << std::endl;
  FX_CHECK(std::abs(forward[centre] - deferred[centre]) <= 2 &&
      std::abs(forward[centre + 1] - deferred[centre + 1]) <= 2,
    "the opacity-0 sphere is as invisible as in VTK");

  // No light at all (and no automatic light): VTK shows ambient + diffuse.
  renderer->RemoveAllLights();
  renderer->AutomaticLightCreationOff();
  renderer->SetPass(nullptr);
  window->Render();
  const auto unlitForward = vtkFXScenes::Capture(window);
  renderer->SetPass(pipeline);
  window->Render();
  const double psnr = vtkFXScenes::PSNR(unlitForward, vtkFXScenes::Capture(window));
  std::cout << "no lights: PSNR " << psnr << " dB against VTK" << std::endl;
  FX_CHECK(pipeline->GetLastSceneInfo().LightingComplexity == 0, "no lighting");
  FX_CHECK(psnr >= 40.0, "unlit rendering matches VTK");
  // Occlusion darkens light and toon bands quantise it: with none on, both
  // are left out with the channels they would read (lines alone would stay).
  for (bool directional : { false, true })
  {
    vtkNew<vtkFXPipelinePass> withEffects;
    if (directional)
    {
      withEffects->DirectionalOcclusionOn();
    }
    else
    {
      withEffects->AmbientOcclusionOn();
    }
    vtkNew<vtkFXToonPass> bands;
    bands->FeatureLinesOff();
    withEffects->AddEffect("toon", bands);
    renderer->SetPass(withEffects);
    window->Render();
    const std::string passes = vtkFXTest::Passes(withEffects);
    std::cout << "no lights, " << (directional ? "directional occlusion" : "ambient occlusion")
              << " and toon bands: passes " << passes << std::endl;
    FX_CHECK(passes.find("ssao") == std::string::npos && passes.find("do") == std::string::npos &&
        passes.find("toon") == std::string::npos &&
        !(withEffects->GetGBufferChannels() & vtkFXGBufferPass::ChannelBit(vtkFXGBufferPass::LinearDepth)),
      "effects without light to act on ran: " << passes);
  }

  // A specular power below 8-bit resolution of power / 128 (0.2; vtkProperty
  // allows 0..128): it came back 0 and pow(0, 0) blackened the pixels
  // whose reflection points away from the viewer (39 dB against VTK, whole
  // pixels black). As VTK within 50 dB and 8 levels.
  {
    window->GetRenderers()->RemoveAllItems();
    vtkNew<vtkRenderer> shiny;
    window->AddRenderer(shiny);
    vtkNew<vtkActor> ball;
    ball->SetMapper(sphereMapper);
    ball->GetProperty()->SetSpecular(0.3);
    ball->GetProperty()->SetSpecularPower(0.2);
    shiny->AddActor(ball);
    shiny->ResetCamera();
    // VTK's forward render, then a new pipeline's: PSNR, largest difference
    // and the pipeline's G-buffer bytes per pixel.
    const auto againstVTK = [&](const char* what, int& bytes) {
      shiny->SetPass(nullptr);
      window->Render();
      const auto forward = vtkFXScenes::Capture(window);
      vtkNew<vtkFXPipelinePass> fx;
      shiny->SetPass(fx);
      window->Render();
      const auto deferred = vtkFXScenes::Capture(window);
      const double psnr = vtkFXScenes::PSNR(forward, deferred);
      const int largest = vtkFXScenes::MaxDifference(forward, deferred);
      bytes = fx->GetGBufferBytesPerPixel();
      std::cout << what << ": PSNR " << psnr << " dB against VTK, largest difference " << largest
                << " levels, G-buffer " << bytes << " bytes per pixel" << std::endl;
      return psnr >= 50.0 && largest <= 8;
    };
    int plainBytes = 0, brightBytes = 0;
    FX_CHECK(againstVTK("specular power 0.2", plainBytes), "a small specular power renders as in VTK");

    // Colours above 1 (vtkProperty does not clamp them; VTK's shaders use
    // them as given): the material channels go to 16-bit floats, only then.
    ball->GetProperty()->SetDiffuseColor(1.8, 1.2, 0.4);
    ball->GetProperty()->SetAmbient(0.1);
    ball->GetProperty()->SetAmbientColor(2.0, 2.0, 2.0);
    ball->GetProperty()->SetSpecularPower(20.0);
    FX_CHECK(againstVTK("diffuse colour (1.8, 1.2, 0.4), ambient colour 2", brightBytes),
      "colours above 1 render as in VTK");
    FX_CHECK(brightBytes > plainBytes, "no wider material channels");
  }
  FX_CHECK(CheckGBufferFailure(window) == EXIT_SUCCESS, "G-buffer failure");
  return EXIT_SUCCESS;
}
