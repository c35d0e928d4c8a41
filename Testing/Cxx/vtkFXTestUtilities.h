// Helpers shared by the vtkFX C++ tests (header only).
#ifndef vtkFXTestUtilities_h
#define vtkFXTestUtilities_h

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkCallbackCommand.h"
#include "vtkCameraPass.h"
#include "vtkFXAVSMPass.h"
#include "vtkFXBloomPass.h"
#include "vtkFXGBufferPass.h"
#include "vtkFXPipelinePass.h"
#include "vtkFXToonPass.h"
#include "vtkFXScenes.h"
#include "vtkImageActor.h"
#include "vtkImageData.h"
#include "vtkImageMapper3D.h"
#include "vtkLightsPass.h"
#include "vtkNew.h"
#include "vtkOpaquePass.h"
#include "vtkPNGWriter.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderer.h"
#include "vtkSequencePass.h"
#include "vtkPixelBufferObject.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"
#include "vtkTesting.h"
#include "vtkTextureObject.h"
#include "vtkTransform.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

// Prints the failed condition with its location and makes the test fail.
#define FX_CHECK(cond, message)                                                                    \
  do                                                                                               \
  {                                                                                                \
    if (!(cond))                                                                                   \
    {                                                                                              \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #cond << ": " << message      \
                << std::endl;                                                                      \
      return EXIT_FAILURE;                                                                         \
    }                                                                                              \
  } while (false)

namespace vtkFXTest
{
// An actor drawing `source`'s polygonal output (the mapper stays connected:
// a test may change the source).
inline vtkSmartPointer<vtkActor> SurfaceActor(vtkAlgorithm* source)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

// Counts the events of one kind an object reports (errors by default, kept
// off the console).
struct EventCounter
{
  int Count = 0;
  std::string Last;
  vtkNew<vtkCallbackCommand> Command;
  explicit EventCounter(vtkObject* object, unsigned long event = vtkCommand::ErrorEvent)
  {
    this->Command->SetClientData(this);
    this->Command->SetCallback([](vtkObject*, unsigned long, void* client, void* data) {
      auto* self = static_cast<EventCounter*>(client);
      ++self->Count;
      self->Last = data ? static_cast<const char*>(data) : "";
    });
    object->AddObserver(event, this->Command);
  }
};
using ErrorCounter = EventCounter;

// An offscreen window with one sample per pixel (the G-buffer has one).
// Adds to `pipeline` the effect `name` names, with its defaults: "ao"
// (ambient occlusion and its blur), "do" (directional occlusion), "toon"
// (bands and lines), "lines" (lines alone), "avsm" or "bloom". False for
// any other name.
inline bool AddEffect(vtkFXPipelinePass* pipeline, const std::string& name)
{
  if (name == "ao" || name == "do")
  {
    pipeline->SetAmbientOcclusion(name == "ao");
    pipeline->SetDirectionalOcclusion(name == "do");
    return true;
  }
  vtkSmartPointer<vtkFXEffectPass> effect;
  if (name == "toon" || name == "lines")
  {
    auto toon = vtkSmartPointer<vtkFXToonPass>::New();
    toon->SetBands(name == "toon");
    effect = toon;
  }
  else if (name == "avsm")
  {
    effect = vtkSmartPointer<vtkFXAVSMPass>::New();
  }
  else if (name == "bloom")
  {
    effect = vtkSmartPointer<vtkFXBloomPass>::New();
  }
  if (effect)
  {
    pipeline->AddEffect(name == "lines" ? "toon" : name.c_str(), effect);
  }
  return effect != nullptr;
}

inline vtkSmartPointer<vtkRenderWindow> MakeWindow(int width, int height)
{
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(width, height);
  return window;
}

// Installs a G-buffer used alone, as in a hand-built VTK pass chain:
// camera -> sequence(lights, G-buffer(opaque)). The renderer keeps it alive.
inline vtkFXGBufferPass* InstallGBufferAlone(vtkRenderer* renderer)
{
  vtkNew<vtkFXGBufferPass> gbuffer;
  vtkNew<vtkOpaquePass> opaque;
  gbuffer->SetDelegatePass(opaque);
  vtkNew<vtkLightsPass> lights;
  vtkNew<vtkRenderPassCollection> passes;
  passes->AddItem(lights);
  passes->AddItem(gbuffer);
  vtkNew<vtkSequencePass> sequence;
  sequence->SetPasses(passes);
  vtkNew<vtkCameraPass> cameraPass;
  cameraPass->SetDelegatePass(sequence);
  renderer->SetPass(cameraPass);
  return gbuffer;
}

// The passes that ran in the pipeline's last frame, comma-separated.
inline std::string Passes(vtkFXPipelinePass* pipeline)
{
  std::string list;
  for (int i = 0; i < pipeline->GetNumberOfPassesThatRan(); ++i)
  {
    list += (i ? "," : "") + std::string(pipeline->GetPassThatRan(i));
  }
  return list;
}

// Angle in radians between two unit vectors.
inline double Angle(const double a[3], const double b[3])
{
  const double cosine = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  return std::acos(std::min(1.0, std::max(-1.0, cosine)));
}

// Ambient occlusion of a point on a floor at distance h from an infinite
// perpendicular wall: a cosine-distributed ray w hits the wall at
// t = h / w.x (w.x > 0), and
//   A(h) = 1 - (1/pi) Int_{w.x > 0, t < R} f(t) cos(theta) dw.
// Binary falloff (f = 1): the cosine-weighted directions project uniformly
// onto the unit disk (Malley), so A is one minus the disk's segment beyond
// x = a = h/R over pi: A(h) = 1 - (acos a - a sqrt(1 - a^2)) / pi.
// Cube-root falloff f(t) = 1 - (t/R)^(1/3): midpoint rule on (theta, phi).
// Both give A(0) = 1/2: the wall takes half of the cosine-weighted
// hemisphere.
inline double CreaseOcclusionBinary(double h, double R)
{
  const double a = std::min(1.0, std::max(0.0, h / R));
  return 1.0 - (std::acos(a) - a * std::sqrt(1.0 - a * a)) / 3.14159265358979323846;
}

inline double CreaseOcclusion(double h, double R)
{
  const int n = 600;
  const double pi = 3.14159265358979323846;
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
  {
    const double theta = (i + 0.5) / n * pi / 2;
    for (int j = 0; j < n; ++j)
    {
      const double wx = std::sin(theta) * std::cos((j + 0.5) / n * 2 * pi);
      if (wx > 0.0 && h / wx < R)
      {
        sum += (1.0 - std::cbrt(h / wx / R)) * std::cos(theta) * std::sin(theta);
      }
    }
  }
  return 1.0 - sum * (pi / 2 / n) * (2 * pi / n) / pi;
}

// The crease occlusion of a falloff (0 Binary, 1 CubeRoot: the values of
// vtkFXSSAOPass::Falloff and vtkFXReferenceAO::Falloff).
inline double CreaseOcclusion(double h, double R, int falloff)
{
  return falloff == 0 ? CreaseOcclusionBinary(h, R) : CreaseOcclusion(h, R);
}

// Name of a falloff in test output.
inline const char* FalloffName(int falloff)
{
  return falloff == 0 ? "binary" : "cube-root";
}

// The value of "-X value" in argv, or "" when absent.
inline std::string Argument(int argc, char* argv[], const char* flag)
{
  for (int i = 0; i + 1 < argc; ++i)
  {
    if (std::strcmp(argv[i], flag) == 0)
    {
      return argv[i + 1];
    }
  }
  return std::string();
}

// An opaque image slice of one colour `rgb` over x0..x1, y0..y1 at height
// z (pixels 0.1 apart): a vtkImageActor, which the G-buffer does not
// capture and the pipeline draws forward.
inline vtkSmartPointer<vtkImageActor> UniformSlice(
  double x0, double x1, double y0, double y1, double z, const unsigned char rgb[3])
{
  const int columns = static_cast<int>(std::lround((x1 - x0) / 0.1)) + 1;
  const int rows = static_cast<int>(std::lround((y1 - y0) / 0.1)) + 1;
  vtkNew<vtkImageData> slice;
  slice->SetDimensions(columns, rows, 1);
  slice->SetSpacing(0.1, 0.1, 1.0);
  slice->SetOrigin(x0, y0, z);
  slice->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* pixels = static_cast<unsigned char*>(slice->GetScalarPointer());
  for (int i = 0; i < columns * rows; ++i)
  {
    std::copy(rgb, rgb + 3, pixels + 3 * i);
  }
  auto actor = vtkSmartPointer<vtkImageActor>::New();
  actor->GetMapper()->SetInputData(slice);
  return actor;
}

// Scales the renderer's actors by `scale` and moves them by `offset` along
// each axis (through their user matrices), with the camera and its clipping
// range following, so the image should not change; `parallel` switches the
// projection; nearRatio > 0 sets a near/far ratio instead of the scaled
// automatic range.
inline void MoveScene(vtkRenderer* renderer, double scale, double offset, bool parallel,
  double nearRatio)
{
  vtkNew<vtkTransform> transform;
  transform->Translate(offset, offset, offset);
  transform->Scale(scale, scale, scale);
  vtkActorCollection* actors = renderer->GetActors();
  vtkCollectionSimpleIterator it;
  actors->InitTraversal(it);
  while (vtkActor* actor = actors->GetNextActor(it))
  {
    actor->SetUserMatrix(transform->GetMatrix());
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  // The clipping range scales with the scene (VTK's automatic range is not
  // exactly proportional: it would clip the far ground differently).
  double range[2];
  camera->GetClippingRange(range);
  double position[3], focal[3];
  camera->GetPosition(position);
  camera->GetFocalPoint(focal);
  transform->TransformPoint(position, position);
  transform->TransformPoint(focal, focal);
  camera->SetPosition(position);
  camera->SetFocalPoint(focal);
  camera->SetParallelProjection(parallel);
  camera->SetParallelScale(camera->GetParallelScale() * scale);
  if (nearRatio > 0.0)
  {
    const double d = camera->GetDistance();
    camera->SetClippingRange(1e-4 * d, 1e-4 * d / nearRatio);
  }
  else
  {
    camera->SetClippingRange(range[0] * scale, range[1] * scale);
  }
}

// Compares the window with the baseline given by -V, twice:
// - VTK's image difference, threshold as in vtkRegressionTestImageThreshold.
//   VTK 9.1's forgives per-pixel differences below its own threshold (105
//   summed over RGB), so it cannot see a change of a few tens of levels
//   over whole regions (toon bands against smooth light both pass);
// - PSNR against the baseline, at least minimumPSNR dB: the images
//   reproduce on this Mesa at 51 dB or more (most exactly), while shadows
//   appearing on a translucent prop measured 39-42 dB and toon bands 23 dB.
// Unlike VTK's macro, a missing -V is a failure: an image test that
// compares nothing must not pass. On failure VTK writes the test image and
// the difference into -T (the test image also when only PSNR fails).
inline bool MatchesBaseline(vtkRenderWindow* window, int argc, char* argv[], double threshold,
  double minimumPSNR = 45.0)
{
  const std::string baseline = Argument(argc, argv, "-V");
  if (baseline.empty())
  {
    std::cerr << "image test run without a baseline (-V): nothing compared" << std::endl;
    return false;
  }
  vtkNew<vtkTesting> testing;
  for (int i = 0; i < argc; ++i)
  {
    testing->AddArgument(argv[i]);
  }
  testing->SetRenderWindow(window);
  if (testing->RegressionTestAndCaptureOutput(threshold, std::cout) != vtkTesting::PASSED)
  {
    return false;
  }
  std::vector<unsigned char> expected;
  int size[2] = { 0, 0 };
  const auto image = vtkFXScenes::Capture(window);
  const double psnr = vtkFXScenes::LoadRGB(baseline, expected, size)
    ? vtkFXScenes::PSNR(expected, image)
    : -1.0;
  std::cout << "PSNR against " << baseline << ": " << psnr << " dB (at least " << minimumPSNR
            << ")" << std::endl;
  if (psnr >= minimumPSNR)
  {
    return true;
  }
  const std::string name = baseline.substr(baseline.find_last_of("/\\") + 1);
  vtkNew<vtkWindowToImageFilter> capture;
  capture->SetInput(window);
  capture->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(capture->GetOutputPort());
  writer->SetFileName((Argument(argc, argv, "-T") + "/" + name).c_str());
  writer->Write();
  std::cerr << "PSNR " << psnr << " dB against the baseline; image written to "
            << writer->GetFileName() << std::endl;
  return false;
}

// Reads a texture back as floats, `components` per texel, rows bottom-up.
inline std::vector<float> Download(vtkTextureObject* texture, int components)
{
  std::vector<float> values;
  if (!texture)
  {
    return values;
  }
  vtkPixelBufferObject* pbo = texture->Download();
  if (!pbo)
  {
    return values;
  }
  const size_t n = static_cast<size_t>(texture->GetWidth()) * texture->GetHeight() * components;
  const int type = pbo->GetType();
  void* data = pbo->MapPackedBuffer();
  values.resize(n);
  if (type == VTK_FLOAT)
  {
    std::memcpy(values.data(), data, n * sizeof(float));
  }
  else if (type == VTK_UNSIGNED_CHAR)
  {
    const unsigned char* bytes = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < n; ++i)
    {
      values[i] = bytes[i] / 255.0f;
    }
  }
  else if (type == VTK_UNSIGNED_INT)
  {
    // (a 32-bit fixed-point depth texture, as the G-buffer keeps when the
    // window does)
    const unsigned int* words = static_cast<const unsigned int*>(data);
    for (size_t i = 0; i < n; ++i)
    {
      values[i] = static_cast<float>(words[i] / 4294967295.0);
    }
  }
  pbo->UnmapPackedBuffer();
  pbo->Delete();
  return values;
}

// Octahedral decoding, the CPU twin of fxDecodeNormal in vtkFXNormalCoding.glsl
// (a pre-lit fragment's code has x moved up by 3).
inline void DecodeNormal(float ex, float ey, double n[3])
{
  n[0] = ex > 1.5f ? ex - 3.0 : ex;
  n[1] = ey;
  n[2] = 1.0 - std::fabs(n[0]) - std::fabs(ey);
  if (n[2] < 0.0)
  {
    const double x = n[0], y = n[1];
    n[0] = (1.0 - std::fabs(y)) * (x >= 0.0 ? 1.0 : -1.0);
    n[1] = (1.0 - std::fabs(x)) * (y >= 0.0 ? 1.0 : -1.0);
  }
  const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (int i = 0; i < 3; ++i)
  {
    n[i] /= l;
  }
}
}

#endif
