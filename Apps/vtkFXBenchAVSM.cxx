// vtkfx-bench avsm: shadows of translucent props, vtkFXAVSMPass with 4, 8
// and 16 nodes and an opacity shadow map of the same memory as 4 and 8
// nodes (8 and 16 regular slices), against its exact mode (the
// uncompressed deep shadow map, every fragment of every texel), as
// transmittance RMSE against time.
//
// Every method makes its shadow maps every frame (ReuseShadowMaps off, as
// when the data or the lights change); a last block orbits the camera under
// the lights fixed where they are, with the maps kept (no shadows, AVSM-8,
// exact: rows "..., camera orbiting, maps kept").
// One window per method, frames interleaved: no shadows, AVSM-4, -8, -16,
// the two opacity shadow maps and exact, each with a 1024 x 1024 map (the AVSM issue's setting). The
// error is the RMSE of the light's transmittance at the opaque receivers
// (the pass's "visibility" output) against the exact mode's; the PSNR is
// the image's against the exact mode's image. The shadow part's time is the
// frame minus the frame without shadows; a last profiled frame per method
// splits it into capture, resolve and look-up (with a glFinish between
// them). Writes DIR/avsm.csv (scene, method, setting, ms, rmse, psnr,
// capture_ms, resolve_ms, lookup_ms, curve_bytes_per_texel,
// list_bytes_per_texel), DIR/avsm-SCENE.png (RMSE against time) and
// DIR/avsm-strip-SCENE.png (exact | AVSM-8 | VTK's vtkShadowMapPass, where
// translucent props cast nothing | no shadows) and DIR/avsm-ray-SCENE.png
// (the transmittance along the light ray through the texel with the most
// fragments, exact against every curve, as the AVSM demo's debug view).
#include "vtkFXAVSMPass.h"
#include "vtkFXBench.h"
#include "vtkFXGBufferPass.h"
#include "vtkFXPipelinePass.h"
#include "vtkFXScenes.h"

#include "vtkCameraPass.h"
#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLightsPass.h"
#include "vtkNew.h"
#include "vtkOpaquePass.h"
#include "vtkPlotPoints.h"
#include "vtkRenderWindow.h"
#include "vtkRenderPass.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkSequencePass.h"
#include "vtkShadowMapBakerPass.h"
#include "vtkShadowMapPass.h"
#include "vtkTextureObject.h"
#include "vtkTimerLog.h"
#include "vtkTranslucentPass.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>

namespace
{
using namespace vtkFXBench;

struct Method
{
  std::string Name;
  std::string Setting;
  int Nodes; // 0: no shadows
  bool Exact;
  int Representation; // vtkFXAVSMPass::Representation
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkFXAVSMPass> AVSM;
  vtkSmartPointer<vtkFXPipelinePass> Pipeline;
  std::vector<double> FrameMs;
  std::vector<float> Visibility;
  std::vector<float> LinearDepth; // the G-buffer's: 0 where no receiver is
  std::vector<unsigned char> Image;
};

// Optical depth along a light ray at light depth z, from a curve as
// vtkFXAVSMPass::GetTexelCurve gives it (nodes, or slices over `range`),
// evaluated as the look-up shader does.
double CurveAt(const std::vector<double>& depths, const std::vector<double>& tau,
  const double range[2], double z)
{
  if (depths.empty()) // slices
  {
    const double k = static_cast<double>(tau.size());
    const double x = (z - range[0]) / std::max(range[1] - range[0], 1e-30) * k;
    if (!(x > 0.0))
    {
      return 0.0;
    }
    if (x >= k)
    {
      return tau.back();
    }
    const size_t i = static_cast<size_t>(x);
    return (i == 0 ? 0.0 : tau[i - 1]) * (1.0 - (x - i)) + tau[i] * (x - i);
  }
  double result = 0.0;
  for (size_t j = 0; j < depths.size(); ++j)
  {
    if (depths[j] <= z)
    {
      const bool last = j + 1 == depths.size() || depths[j + 1] > 1e37;
      const double span = last ? 0.0 : depths[j + 1] - depths[j];
      const double f = span > 0.0 ? std::min(1.0, (z - depths[j]) / span) : 1.0;
      result = last ? tau[j] : tau[j] + f * (tau[j + 1] - tau[j]);
    }
  }
  return result;
}

// The transmittance along the light ray through the texel with the most
// fragments: exact (every fragment) against each curve.
void WriteRayPlot(std::vector<Method>& methods, const std::string& title, const std::string& path)
{
  Method& exact = methods[methods.size() - 2];
  exact.Window->MakeCurrent();
  int x = 0, y = 0;
  std::vector<double> depths, tau, exits;
  if (!exact.AVSM->GetLongestListTexel(x, y) ||
    !exact.AVSM->GetTexelFragments(x, y, depths, tau, &exits) || depths.empty())
  {
    return;
  }
  const double lo = *std::min_element(depths.begin(), depths.end());
  const double hi = *std::max_element(exits.begin(), exits.end());
  const double margin = 0.1 * std::max(hi - lo, 1e-6);
  std::vector<PlotLine> lines;
  const unsigned char palette[][3] = { { 30, 30, 30 }, { 200, 60, 30 }, { 230, 150, 20 },
    { 120, 40, 160 }, { 40, 150, 60 }, { 30, 80, 200 } };
  size_t colour = 0;
  const auto addLine = [&](const std::string& name, const std::function<double(double)>& opticalDepth) {
    PlotLine line{ name, palette[colour][0], palette[colour][1], palette[colour][2], {}, {} };
    colour = (colour + 1) % 6;
    for (int i = 0; i <= 400; ++i)
    {
      const double z = lo - margin + (hi - lo + 2.0 * margin) * i / 400.0;
      line.X.push_back(z);
      line.Y.push_back(std::exp(-opticalDepth(z)));
    }
    lines.push_back(line);
  };
  addLine("exact (" + std::to_string(depths.size()) + " fragments)", [&](double z) {
    // Each segment's share in front of z (vtkFXAVSMLists.glsl's
    // fxSegmentShare): linear inside it, a step for a surface.
    double sum = 0.0;
    for (size_t i = 0; i < depths.size(); ++i)
    {
      sum += exits[i] > depths[i]
        ? tau[i] * std::min(1.0, std::max(0.0, (z - depths[i]) / (exits[i] - depths[i])))
        : (depths[i] < z ? tau[i] : 0.0);
    }
    return sum;
  });
  for (Method& m : methods)
  {
    std::vector<double> nodeDepths, nodeTau;
    if (!m.AVSM || m.Exact)
    {
      continue;
    }
    m.Window->MakeCurrent();
    // The slices span the casters' depth range of the view that holds the
    // texel (a point light's cube has six, each its own range).
    int view = 0;
    for (int v = 0; v < m.AVSM->GetNumberOfViews(); ++v)
    {
      int origin[2];
      const int size = m.AVSM->GetShadowMapSize();
      if (m.AVSM->GetViewOrigin(v, origin) && x >= origin[0] && x < origin[0] + size &&
        y >= origin[1] && y < origin[1] + size)
      {
        view = v;
      }
    }
    double range[2];
    m.AVSM->GetCasterDepthRange(range, view);
    if (m.AVSM->GetTexelCurve(x, y, nodeDepths, nodeTau))
    {
      addLine(m.Name + " " + m.Setting,
        [=](double z) { return CurveAt(nodeDepths, nodeTau, range, z); });
    }
  }
  WriteLinePlot(lines, title + " (texel " + std::to_string(x) + ", " + std::to_string(y) + ")",
    "light depth (0..1, linear along the light)", "transmittance", path);
}

// The last frame's transmittance at the receivers and the G-buffer's
// linear depth (0 where no receiver is), read back.
void ReadVisibility(Method& m)
{
  m.Visibility = Download(m.Window, m.AVSM->GetOutputTexture("visibility"), 1);
  m.LinearDepth = Download(
    m.Window, m.Pipeline->GetGBufferPass()->GetChannelTexture(vtkFXGBufferPass::LinearDepth), 1);
}

// Transmittance error at the receivers (1 everywhere without shadows): the
// pixels where the exact mode's G-buffer has a surface, not the background.
double TransmittanceRMSE(const Method& m, const Method& exact)
{
  double sum = 0.0;
  size_t count = 0;
  for (size_t i = 0; i < exact.Visibility.size(); ++i)
  {
    if (i >= exact.LinearDepth.size() || !(exact.LinearDepth[i] > 0.0f))
    {
      continue;
    }
    const double mine = m.Visibility.empty() ? 1.0 : m.Visibility[i];
    sum += (mine - exact.Visibility[i]) * (mine - exact.Visibility[i]);
    ++count;
  }
  return count ? std::sqrt(sum / count) : 0.0;
}

// VTK's own shadows on the renderer: the shadow-map baker and pass of
// VTK's examples over lights and opaque props, then the translucent props.
// A caster with opacity below 1 casts nothing there.
// The renderer's camera lights (the light kit's) as scene lights where the
// camera puts them now: lights that stay when the camera moves.
void FixCameraLights(vtkRenderer* renderer)
{
  renderer->GetActiveCamera(); // the camera lights follow this one
  vtkLightCollection* lightList = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  lightList->InitTraversal(it);
  while (vtkLight* light = lightList->GetNextLight(it))
  {
    if (light->LightTypeIsCameraLight())
    {
      light->SetTransformMatrix(renderer->GetActiveCamera()->GetCameraLightTransformMatrix());
      double position[3], focal[3];
      light->GetTransformedPosition(position);
      light->GetTransformedFocalPoint(focal);
      light->SetTransformMatrix(nullptr);
      light->SetLightTypeToSceneLight();
      light->SetPosition(position);
      light->SetFocalPoint(focal);
    }
  }
}

void UseVTKShadowMaps(vtkRenderer* renderer)
{
  // VTK's shadow maps misplace camera lights (the light kit's).
  FixCameraLights(renderer);
  vtkNew<vtkLightsPass> lights;
  vtkNew<vtkOpaquePass> opaque;
  vtkNew<vtkRenderPassCollection> opaquePasses;
  opaquePasses->AddItem(lights);
  opaquePasses->AddItem(opaque);
  vtkNew<vtkSequencePass> opaqueSequence;
  opaqueSequence->SetPasses(opaquePasses);
  // The baker renders the opaque props from each light: through a camera
  // pass of its own (VTK's TestShadowMapPass).
  vtkNew<vtkCameraPass> opaqueCamera;
  opaqueCamera->SetDelegatePass(opaqueSequence);
  vtkNew<vtkShadowMapBakerPass> baker;
  baker->SetOpaqueSequence(opaqueCamera);
  baker->SetResolution(1024);
  vtkNew<vtkShadowMapPass> shadows;
  shadows->SetShadowMapBakerPass(baker);
  shadows->SetOpaqueSequence(opaqueSequence);
  vtkNew<vtkTranslucentPass> translucent;
  vtkNew<vtkRenderPassCollection> passes;
  passes->AddItem(baker);
  passes->AddItem(shadows);
  passes->AddItem(translucent);
  vtkNew<vtkSequencePass> sequence;
  sequence->SetPasses(passes);
  vtkNew<vtkCameraPass> camera;
  camera->SetDelegatePass(sequence);
  renderer->SetPass(camera);
}

// The camera orbiting a scene whose lights stay (the light kit's camera
// lights fixed where they are), with the shadow maps kept between frames
// (vtkFXAVSMPass::ReuseShadowMaps): no shadows, AVSM-8 and exact, in the
// windows the main measurement used, 2 degrees a frame. Each frame then
// costs the look-up only; the output says how many frames reused the maps.
void BenchOrbit(const Options& o, const std::string& input, std::vector<Method> orbit,
  std::ofstream& csv, vtkTimerLog* timer)
{
  for (Method& m : orbit)
  {
    vtkRenderer* renderer = m.Window->GetRenderers()->GetFirstRenderer();
    FixCameraLights(renderer);
    if (m.AVSM)
    {
      m.AVSM->ReuseShadowMapsOn();
    }
    m.FrameMs.clear();
    m.Window->Render(); // makes the maps the orbit keeps
  }
  // Frames that reused the maps, per method: each frame's flag, read
  // before the next frame and after the last.
  std::vector<int> reused(orbit.size(), 0);
  const auto countReused = [&orbit, &reused](const Method& m) {
    if (m.AVSM && !m.FrameMs.empty() && m.AVSM->GetReusedShadowMaps())
    {
      ++reused[&m - orbit.data()]; // (m is one of orbit's)
    }
  };
  TimeFramesInTurn(orbit, o.Frames, input + " orbiting", timer, [&](Method& m) {
    countReused(m);
    vtkRenderer* renderer = m.Window->GetRenderers()->GetFirstRenderer();
    renderer->GetActiveCamera()->Azimuth(2.0);
    renderer->ResetCameraClippingRange();
  });
  for (size_t i = 0; i < orbit.size(); ++i)
  {
    Method& m = orbit[i];
    countReused(m);
    m.Image = vtkFXScenes::Capture(m.Window);
    if (m.AVSM)
    {
      ReadVisibility(m);
      // Profile's switch remakes the maps; the frame after it reuses them.
      m.AVSM->ProfileOn();
      m.Window->Render();
      m.Window->Render();
      m.AVSM->ProfileOff();
    }
  }
  const Method& exact = orbit.back();
  const double none = Median(orbit.front().FrameMs);
  for (size_t i = 1; i < orbit.size(); ++i)
  {
    const Method& m = orbit[i];
    const double rmse = TransmittanceRMSE(m, exact);
    const double psnr = vtkFXScenes::PSNR(m.Image, exact.Image);
    const double frame = Median(m.FrameMs);
    const double lookup = m.AVSM->GetPhaseMilliseconds(2);
    const std::string setting = m.Setting + ", camera orbiting, maps kept";
    csv << input << "," << m.Name << "," << setting << "," << frame - none << "," << rmse << ","
        << psnr << "," << m.AVSM->GetPhaseMilliseconds(0) << ","
        << m.AVSM->GetPhaseMilliseconds(1) << "," << lookup << ","
        << m.AVSM->GetCurveBytesPerTexel() << "," << m.AVSM->GetListBytesPerTexel() << "\n";
    std::cout << std::fixed << std::setprecision(2) << input << ": " << m.Name << " (" << setting
              << ") frame " << frame << " ms, " << frame / none
              << "x the orbiting frame without shadows (frame by frame "
              << PairedRatio(m.FrameMs, orbit.front().FrameMs) << "x); " << reused[i] << " of "
              << m.FrameMs.size() << " frames reused the maps; look-up " << lookup
              << " ms; transmittance RMSE against exact " << std::setprecision(4) << rmse
              << std::endl;
  }
}

}

namespace vtkFXBench
{
int BenchAVSM(const Options& o)
{
  std::ofstream csv;
  std::string csvPath;
  // The shared columns, then the time split and the memory.
  if (!OpenReport(o, "avsm", csv, csvPath,
        "capture_ms,resolve_ms,lookup_ms,curve_bytes_per_texel,list_bytes_per_texel"))
  {
    return 1;
  }
  const int nodes = vtkFXAVSMPass::AdaptiveNodes;
  const int slices = vtkFXAVSMPass::RegularSlices;
  std::vector<Method> methods = { { "vtkfx-none", "no shadows", 0, false, nodes },
    { "vtkfx-avsm", "4 nodes", 4, false, nodes }, { "vtkfx-avsm", "8 nodes", 8, false, nodes },
    { "vtkfx-avsm", "16 nodes", 16, false, nodes },
    { "opacity-shadow-map", "8 slices (memory of 4 nodes)", 4, false, slices },
    { "opacity-shadow-map", "16 slices (memory of 8 nodes)", 8, false, slices },
    { "opacity-shadow-map", "32 slices (memory of 16 nodes)", 16, false, slices },
    { "vtkfx-exact", "all fragments", 8, true, nodes },
    { "vtk-shadow-map", "vtkShadowMapPass 1024", -1, false, nodes } };
  for (auto& m : methods)
  {
    m.Window = MakeWindow(o);
  }
  vtkNew<vtkTimerLog> timer;
  for (const std::string& input : o.Inputs)
  {
    for (auto& m : methods)
    {
      // The last scene's passes free their GL resources before they go
      // (VTK's shadow-map baker insists).
      vtkRenderer* previous = m.Window->GetRenderers()->GetFirstRenderer();
      if (previous && previous->GetPass())
      {
        // (in the window's own context: GL deletes names in the current one)
        m.Window->MakeCurrent();
        previous->GetPass()->ReleaseGraphicsResources(m.Window);
      }
      std::string error;
      auto renderer = Stage(m.Window, input, error);
      if (!renderer)
      {
        std::cerr << "vtkfx-bench: " << error << "\n";
        return 1;
      }
      vtkNew<vtkFXPipelinePass> pipeline;
      m.Pipeline = pipeline;
      m.AVSM = nullptr;
      if (m.Nodes < 0)
      {
        UseVTKShadowMaps(renderer);
      }
      else if (m.Nodes > 0)
      {
        m.AVSM = vtkSmartPointer<vtkFXAVSMPass>::New();
        m.AVSM->SetShadowMapSize(1024);
        m.AVSM->SetNumberOfNodes(m.Nodes);
        m.AVSM->SetExact(m.Exact);
        m.AVSM->SetRepresentation(m.Representation);
        // Every frame makes its shadow maps, as when the data or the
        // lights change (the orbit below keeps them).
        m.AVSM->ReuseShadowMapsOff();
        pipeline->AddEffect("avsm", m.AVSM);
      }
      if (m.Nodes >= 0)
      {
        renderer->SetPass(pipeline);
      }
      m.FrameMs.clear();
      m.Window->Render(); // warm up; the list buffer grows to the scene here
      m.Window->Render();
    }
    TimeFramesInTurn(methods, o.Frames, input, timer);
    for (auto& m : methods)
    {
      m.Image = vtkFXScenes::Capture(m.Window);
      if (m.AVSM)
      {
        ReadVisibility(m);
        m.AVSM->ProfileOn(); // one more frame, finished phase by phase
        m.Window->Render();
        m.AVSM->ProfileOff();
      }
    }
    const Method& exact = methods[methods.size() - 2];
    const double none = Median(methods.front().FrameMs);
    std::vector<PlotPoint> points;
    for (auto& m : methods)
    {
      // VTK's shadow maps give no transmittance to compare: its row has
      // none (-1), and its image differs from vtkFX's by its opaque shadows.
      const double rmse = m.Nodes < 0 ? -1.0 : TransmittanceRMSE(m, exact);
      const double psnr = vtkFXScenes::PSNR(m.Image, exact.Image);
      const double frame = Median(m.FrameMs);
      const double ms = frame - none;
      const double capture = m.AVSM ? m.AVSM->GetPhaseMilliseconds(0) : 0.0;
      const double resolve = m.AVSM ? m.AVSM->GetPhaseMilliseconds(1) : 0.0;
      const double lookup = m.AVSM ? m.AVSM->GetPhaseMilliseconds(2) : 0.0;
      const int curveBytes = m.AVSM ? m.AVSM->GetCurveBytesPerTexel() : 0;
      const double listBytes = m.AVSM ? m.AVSM->GetListBytesPerTexel() : 0.0;
      csv << input << "," << m.Name << "," << m.Setting << "," << ms << "," << rmse << "," << psnr
          << "," << capture << "," << resolve << "," << lookup << "," << curveBytes << ","
          << listBytes << "\n";
      std::cout << std::fixed << std::setprecision(2) << input << ": " << m.Name << " ("
                << m.Setting << ") frame " << frame << " ms, " << frame / none
                << "x the frame without shadows (frame by frame "
                << PairedRatio(m.FrameMs, methods.front().FrameMs) << "x); ";
      if (m.Nodes < 0)
      {
        std::cout << "no transmittance (opaque shadows), image PSNR " << psnr << " dB"
                  << std::endl;
      }
      else
      {
        std::cout << "transmittance RMSE " << std::setprecision(4) << rmse << ", PSNR "
                  << std::setprecision(2) << psnr << " dB; capture " << capture << ", resolve "
                  << resolve << ", look-up " << lookup << " ms; " << curveBytes
                  << " B/texel kept, " << listBytes << " B/texel of lists" << std::endl;
      }
      if (m.AVSM)
      {
        const int family = m.Exact ? 2 : m.Representation == slices ? 1 : 0;
        points.push_back({ family, m.Setting, ms, rmse });
      }
    }
    const std::string tag = FileTag(input);
    WritePointsPlot({ { "vtkFX AVSM", 200, 60, 30, vtkPlotPoints::CIRCLE },
                      { "opacity shadow map (equal memory)", 40, 150, 60, vtkPlotPoints::DIAMOND },
                      { "exact deep shadow map", 30, 80, 200, vtkPlotPoints::SQUARE } },
      points, tag + ": translucent shadows, error against time",
      "shadow time (ms per frame, frame minus frame without shadows)",
      "transmittance RMSE against the exact mode", o.Out + "/avsm-" + tag + ".png");
    WriteRayPlot(methods, tag + ": transmittance along the light ray with the most fragments",
      o.Out + "/avsm-ray-" + tag + ".png");
    WriteRGBStrip({ &exact.Image, &methods[2].Image, &methods.back().Image, &methods[0].Image },
      o.Width, o.Height, o.Out + "/avsm-strip-" + tag + ".png");
    BenchOrbit(o, input, { methods.front(), methods[2], methods[methods.size() - 2] }, csv, timer);
  }
  std::cout << "wrote " << csvPath << " (" << o.Width << "x" << o.Height << ", median of "
            << o.Frames << " interleaved frames, 1024 x 1024 shadow maps)\n";
  return 0;
}
}
