// vtkfx-bench: error against run time, in one process, for vtkFX's passes
// next to VTK's own rendering.
//
//   vtkfx-bench pipeline|ao|do|avsm|bloom|lights [INPUT ...] [--size WxH] [--frames N] --out DIR
//
// "ao" and "do" (directional occlusion): see vtkFXBenchAO.cxx; "avsm": vtkFXBenchAVSM.cxx; "bloom":
// vtkFXBenchBloom.cxx; "lights": vtkFXBenchLights.cxx.
// "pipeline": the vtkFX pipeline with no effect (which must reproduce VTK's
// forward render of the same scene), with its default ambient occlusion and
// with toon shading (bands and feature lines, vtkFXToonPass's defaults),
// against that forward render. Four windows hold identical copies of the
// scene, one per renderer, and frames are interleaved so that all see the
// same machine load. Writes
// DIR/pipeline.csv (scene, method, setting, ms, rmse, psnr) with the median
// frame time over N frames (PSNR over the pixels that show data), and
// prints the time ratios (to VTK, and to vtkFX without effects) and the
// pipeline's per-pass GPU times per scene.
#include "vtkFXArguments.h"
#include "vtkFXBench.h"
#include "vtkFXHeap.h"
#include "vtkFXPipelinePass.h"
#include "vtkFXScenes.h"
#include "vtkFXToonPass.h"

#include "vtkNew.h"
#include "vtkRenderWindow.h"
#include "vtkRendererCollection.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtksys/SystemTools.hxx"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using namespace vtkFXBench;

int BenchPipeline(const Options& o)
{
  std::ofstream csv;
  std::string csvPath;
  if (!OpenReport(o, "pipeline", csv, csvPath, "paired_ratio_vtk,paired_ratio_none"))
  {
    return 1;
  }
  vtkNew<vtkTimerLog> timer;
  // VTK's forward render, then vtkFX with no effect, with its default
  // ambient occlusion and with toon shading, each in its own window, frames
  // interleaved so that all see the same machine load.
  struct Variant
  {
    std::string Setting;
    std::function<void(vtkFXPipelinePass*)> Configure;
    vtkSmartPointer<vtkRenderWindow> Window;
    vtkSmartPointer<vtkFXPipelinePass> Pipeline;
    std::vector<double> Ms;
    std::map<std::string, std::vector<double>> PassMs;
  };
  auto forward = MakeWindow(o);
  const auto toon = [](vtkFXPipelinePass* p) {
    vtkNew<vtkFXToonPass> effect;
    p->AddEffect("toon", effect);
  };
  std::vector<Variant> variants = { { "effects=none", [](vtkFXPipelinePass*) {}, MakeWindow(o) },
    { "effects=ao", [](vtkFXPipelinePass* p) { p->AmbientOcclusionOn(); }, MakeWindow(o) },
    { "effects=toon", toon, MakeWindow(o) } };
  for (size_t s = 0; s < o.Inputs.size(); ++s)
  {
    const std::string& input = o.Inputs[s];
    std::string error;
    auto forwardRenderer = Stage(forward, input, error);
    if (!forwardRenderer)
    {
      std::cerr << "vtkfx-bench: " << error << "\n";
      return 1;
    }
    for (auto& v : variants)
    {
      auto renderer = Stage(v.Window, input, error);
      if (!renderer)
      {
        std::cerr << "vtkfx-bench: " << error << "\n";
        return 1;
      }
      v.Pipeline = vtkSmartPointer<vtkFXPipelinePass>::New();
      v.Configure(v.Pipeline);
      renderer->SetPass(v.Pipeline);
      v.Ms.clear();
      v.PassMs.clear();
      v.Window->Render(); // warm up: shader compilation and allocation are not part of a frame
    }
    forward->Render();
    std::vector<double> vtkMs;
    for (int f = 0; f < o.Frames; ++f)
    {
      std::cerr << "\r[" << s + 1 << "/" << o.Inputs.size() << "] " << input << ": frame "
                << f + 1 << "/" << o.Frames << std::flush;
      vtkMs.push_back(TimedRender(forward, timer));
      for (auto& v : variants)
      {
        v.Ms.push_back(TimedRender(v.Window, timer));
        for (int i = 0; i < v.Pipeline->GetNumberOfPassesThatRan(); ++i)
        {
          const std::string pass = v.Pipeline->GetPassThatRan(i);
          const double ms = v.Pipeline->GetPassMilliseconds(pass.c_str());
          if (ms >= 0.0)
          {
            v.PassMs[pass].push_back(ms);
          }
        }
      }
    }
    std::cerr << "\n";
    const auto reference = vtkFXScenes::Capture(forward);
    unsigned char background[3];
    vtkFXScenes::BackgroundBytes(forwardRenderer, background);
    const double vtk = Median(vtkMs);
    const double none = Median(variants.front().Ms);
    csv << input << ",vtk-forward,default," << vtk << ",0,inf,1,"
        << PairedRatio(vtkMs, variants.front().Ms) << "\n";
    for (auto& v : variants)
    {
      const auto image = vtkFXScenes::Capture(v.Window);
      const double psnr = vtkFXScenes::PSNR(reference, image, background);
      const double fx = Median(v.Ms);
      const double pairedVTK = PairedRatio(v.Ms, vtkMs);
      const double pairedNone = PairedRatio(v.Ms, variants.front().Ms);
      csv << input << ",vtkfx-pipeline," << v.Setting << "," << fx << ","
          << RMSE(reference, image) << "," << psnr << "," << pairedVTK << "," << pairedNone
          << "\n";
      std::ostringstream line;
      line << std::fixed << std::setprecision(2) << input << ": VTK " << vtk << " ms, vtkFX "
           << v.Setting << " " << fx << " ms, ratio " << fx / vtk << " (" << fx / none
           << " x effects=none; frame by frame " << pairedVTK << " and " << pairedNone
           << "), PSNR " << psnr
           << " dB, G-buffer " << v.Pipeline->GetGBufferBytesPerPixel() << " B/px; GPU ms:";
      for (const auto& pass : v.PassMs)
      {
        line << " " << pass.first << " " << Median(pass.second);
      }
      std::cout << line.str() << std::endl;
    }
  }
  std::cout << "wrote " << csvPath << " (" << o.Width << "x" << o.Height << ", median of "
            << o.Frames << " interleaved frames)\n";
  return 0;
}

void Usage(std::ostream& os)
{
  os << "usage: vtkfx-bench pipeline|ao|do|avsm|bloom|lights [INPUT ...] [--size WxH] [--frames N]\n"
        "                   [--falloff binary|cuberoot] [--max-vtk-lights N] --out DIR\n"
        "pipeline: vtkFX without effects, with its default ambient occlusion and with\n"
        "          toon shading against\n"
        "          VTK's forward render (default: every built-in scene, the bunny and\n"
        "          the fandisk, 1280x720)\n"
        "ao:       ambient occlusion against a ray-traced reference, vtkFX's and VTK's\n"
        "          (default: scene:corner, bunny, fandisk, 1crn.pdb, 640x480), with\n"
        "          visibility within R (--falloff binary, the default) or the\n"
        "          near-weighted 1 - (t/R)^(1/3) (--falloff cuberoot)\n"
        "do:       directional occlusion against a reference traced with the shading\n"
        "          normals, beside vtkFX's plain AO and VTK's (default: scene:bumps,\n"
        "          scene:terrain, scene:normalmap, bunny, scene:corner, 640x480)\n"
        "bloom:    vtkFX's glow and the seed's direct 21x21 Gaussian against the exact\n"
        "          glow computed on the CPU (default: scene:glow, 1280x720)\n"
        "avsm:     shadows of translucent props, AVSM-4/8/16 against the exact deep shadow\n"
        "          map (default: scene:particles, scene:cloud and scene:isoshadow, 1280x720)\n"
        "lights:   frame time with 1 to 1024 point lights, vtkFX against VTK's forward\n"
        "          render (VTK up to --max-vtk-lights, default 256; default INPUT\n"
        "          scene:spheres, 1280x720)\n"
     << vtkFXHeap::UsageNote;
}
}

int main(int argc, char* argv[])
{
  const bool keptHeap = vtkFXHeap::KeepFreedMemory();
  Options o;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--falloff")
    {
      const std::string f = i + 1 < argc ? argv[++i] : "";
      if (f != "binary" && f != "cuberoot")
      {
        std::cerr << "vtkfx-bench: bad --falloff '" << f << "' (binary or cuberoot)\n";
        return 2;
      }
      o.Falloff = f == "binary" ? 0 : 1;
    }
    else if (a == "--max-vtk-lights" || a == "--frames" || a == "--size" || a == "--out")
    {
      std::string v;
      if (!vtkFXArguments::TakeValue(argc, argv, i, v))
      {
        std::cerr << "vtkfx-bench: " << a << " needs a value\n";
        return 2;
      }
      const bool ok = a == "--out" ||
        (a == "--max-vtk-lights" ? vtkFXArguments::ParseInt(v, 0, 1024, o.MaxVTKLights)
        : a == "--frames"         ? vtkFXArguments::ParseInt(v, 1, 100000, o.Frames)
                                  : vtkFXArguments::ParseSize(v, o.Width, o.Height));
      if (!ok)
      {
        std::cerr << "vtkfx-bench: bad " << a << " '" << v << "' ("
                  << (a == "--out"          ? "a directory"
                       : a == "--size"       ? "WxH, 1 to 16384 pixels a side"
                       : a == "--frames"     ? "a whole number, 1 to 100000"
                                             : "a whole number, 0 to 1024")
                  << ")\n";
        return 2;
      }
      o.Out = a == "--out" ? v : o.Out;
      o.SizeGiven = o.SizeGiven || a == "--size";
    }
    else if (a == "--help" || a == "-h")
    {
      Usage(std::cout);
      return 0;
    }
    else if (!a.empty() && a[0] == '-')
    {
      std::cerr << "vtkfx-bench: unknown option '" << a << "'\n";
      Usage(std::cerr);
      return 2;
    }
    else if (o.Effect.empty())
      o.Effect = a;
    else
      o.Inputs.push_back(a);
  }
  const bool known = o.Effect == "pipeline" || o.Effect == "ao" || o.Effect == "do" || o.Effect == "bloom" ||
    o.Effect == "lights" || o.Effect == "avsm";
  if (!known || o.Out.empty())
  {
    std::cerr << "vtkfx-bench: " << (o.Out.empty() ? "--out DIR is required" : "unknown benchmark '" + o.Effect + "'") << "\n";
    Usage(std::cerr);
    return 2;
  }
  // Every input checked before any work: a typo in the last one must not
  // cost the first one's run.
  for (const std::string& input : o.Inputs)
  {
    std::string error;
    if (!vtkFXScenes::CheckInput(input, error))
    {
      std::cerr << "vtkfx-bench: " << error << "\n";
      return 1;
    }
  }
  vtksys::SystemTools::MakeDirectory(o.Out);
  std::cout << vtkFXHeap::Describe(keptHeap) << "\n";
  const std::string data = vtkFXScenes::DataDirectory();
  if (o.Effect == "ao" || o.Effect == "do")
  {
    if (o.Inputs.empty() && o.Effect == "ao")
    {
      o.Inputs = { "scene:corner", data + "/stanford-bunny.obj", data + "/fandisk.obj",
        data + "/1crn.pdb" };
    }
    if (o.Inputs.empty())
    {
      // Bumped (rivets and ridges; a terrain's fine elevation) and
      // normal-mapped scenes, a mesh with neither, and coloured props by
      // white walls (the bleeding).
      o.Inputs = { "scene:bumps", "scene:terrain", "scene:normalmap",
        data + "/stanford-bunny.obj", "scene:corner" };
    }
    if (!o.SizeGiven)
    {
      o.Width = 640;
      o.Height = 480;
    }
    return BenchAO(o);
  }
  if (o.Effect == "bloom")
  {
    if (o.Inputs.empty())
    {
      o.Inputs = { "scene:glow" };
    }
    return BenchBloom(o);
  }
  if (o.Effect == "lights")
  {
    return BenchLights(o);
  }
  if (o.Effect == "avsm")
  {
    if (o.Inputs.empty())
    {
      o.Inputs = { "scene:particles", "scene:cloud", "scene:isoshadow" };
    }
    return BenchAVSM(o);
  }
  if (o.Inputs.empty())
  {
    o.Inputs = vtkFXScenes::BuiltInSceneNames();
    o.Inputs.push_back(data + "/stanford-bunny.obj");
    o.Inputs.push_back(data + "/fandisk.obj");
  }
  return BenchPipeline(o);
}
