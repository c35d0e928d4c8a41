// vtkfx-render: render a dataset or a built-in scene through vtkFX (or plain
// VTK) offscreen, write a PNG and optional per-pass statistics.
//
//   vtkfx-render INPUT [--size WxH] [--effects none|LIST] [--plain-vtk]
//                [--frames N] [--out FILE.png] [--stats FILE.json]
//                [--debug-channel NAME] [--no-ground]
//                [--ao-radius R | --ao-radius-fraction F]
//                [--ao-quality low|medium|high] [--ao-falloff binary|cuberoot]
//                [--ao-thickness F] [--do-method hemisphere|horizon]
#include "vtkFXArguments.h"
#include "vtkFXHeap.h"
#include "vtkFXScenes.h"

#include "vtkFXAVSMPass.h"
#include "vtkFXBilateralBlurPass.h"
#include "vtkFXBloomPass.h"
#include "vtkFXDirectionalOcclusionPass.h"
#include "vtkFXSSAOPass.h"
#include "vtkFXToonPass.h"
#include "vtkFXCompositePass.h"
#include "vtkFXGBufferPass.h"
#include "vtkFXPipelinePass.h"
#include "vtkFXRenderUtilities.h"

#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTimerLog.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace
{
struct Arguments
{
  std::string Input;
  int Width = 1280;
  int Height = 720;
  std::vector<std::string> Effects;
  bool PlainVTK = false;
  int Frames = 1;
  std::string Out = "vtkfx.png";
  std::string Stats;
  std::string DebugChannel;
  bool Ground = true;
  double AORadius = 0.0;         // world units; 0: from the fraction
  double AORadiusFraction = 0.0; // of the visible bounds' diagonal; 0: the default
  int AOQuality = vtkFXPipelinePass::Medium;
  int AOFalloff = vtkFXSSAOPass::Binary;
  double AOThickness = 0.0; // fractions of the radius; 0: the pass's default
  bool AOOptions = false; // any --ao-* option given
  bool AOQualityGiven = false;
  int DOMethod = -1; // --do-method; -1: the pass's default
};

// Effects the pipeline knows: "ssao" (screen-space ambient occlusion),
// "blur" (its depth/normal-aware blur and upsampling), "do" (directional
// occlusion resolved with bumped normals, blur included), "toon" (banded
// diffuse light and feature lines), "lines" (the feature lines alone) and
// "bloom" (glow of emissive props) and "avsm" (shadows of translucent props).
const std::vector<std::string> KnownEffects = { "ssao", "blur", "do", "bleed", "toon", "lines",
  "bloom", "avsm" };

void Usage(std::ostream& os)
{
  os << "usage: vtkfx-render INPUT [--size WxH] [--effects none|LIST] [--plain-vtk]\n"
        "                    [--frames N] [--out FILE.png] [--stats FILE.json]\n"
        "                    [--debug-channel normal|depth|albedo|specular|ambient|emission|\n"
        "                                     geometric-normal|occlusion]\n"
        "                    [--no-ground] [--ao-radius R | --ao-radius-fraction F]\n"
        "                    [--ao-quality low|medium|high] [--ao-falloff binary|cuberoot]\n"
        "                    [--ao-thickness F] [--do-method hemisphere|horizon]\n"
        "LIST: comma-separated effects: ssao, blur (ssao,blur: ambient occlusion),\n"
        "      do (directional occlusion: shows bumps in the ambient term; not with ssao),\n"
        "      bleed (with do: colour bounced off nearby occluders),\n"
        "      toon (banded light and feature lines) or lines (feature lines alone),\n"
        "      bloom (glow of emissive props), avsm (shadows cast by translucent props)\n"
        "INPUT: a .obj, .ply, .stl, .vtp, .vtk or .pdb file, or one of:";
  for (const auto& name : vtkFXScenes::BuiltInSceneNames())
  {
    os << " " << name;
  }
  os << "\n" << vtkFXHeap::UsageNote;
}

// The index of `text` among `names`, or -1.
int IndexOf(const std::string& text, const std::vector<std::string>& names)
{
  const auto it = std::find(names.begin(), names.end(), text);
  return it == names.end() ? -1 : static_cast<int>(it - names.begin());
}

bool Parse(int argc, char* argv[], Arguments& args, std::string& error)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&](std::string& out) {
      if (!vtkFXArguments::TakeValue(argc, argv, i, out))
      {
        error = a + " needs a value";
        return false;
      }
      return true;
    };
    std::string v;
    if (a == "--help" || a == "-h")
    {
      Usage(std::cout);
      std::exit(0);
    }
    else if (a == "--size")
    {
      if (!value(v) || !vtkFXArguments::ParseSize(v, args.Width, args.Height))
      {
        error = "bad --size '" + v + "' (expected WxH, each 1..16384)";
        return false;
      }
    }
    else if (a == "--effects")
    {
      if (!value(v))
        return false;
      args.Effects.clear();
      std::istringstream list(v);
      std::string name;
      while (std::getline(list, name, ','))
      {
        if (name.empty() || name == "none")
          continue;
        if (std::find(KnownEffects.begin(), KnownEffects.end(), name) == KnownEffects.end())
        {
          error = "unknown effect '" + name + "' (known: none";
          for (const auto& e : KnownEffects)
            error += ", " + e;
          error += ")";
          return false;
        }
        args.Effects.push_back(name);
      }
    }
    else if (a == "--ao-radius" || a == "--ao-radius-fraction")
    {
      const bool fraction = a == "--ao-radius-fraction";
      if (!value(v) ||
        !(fraction ? vtkFXArguments::ParseInRange(v, 1e-6, 10.0, args.AORadiusFraction)
                   : vtkFXArguments::ParseInRange(v, 1e-30, 1e30, args.AORadius)))
      {
        error = "bad " + a + " '" + v + "' (expected a decimal number " +
          (fraction ? std::string("from 1e-6 to 10: a fraction of the data's diagonal)")
                    : std::string("from 1e-30 to 1e30, in world units)"));
        return false;
      }
      args.AOOptions = true;
    }
    else if (a == "--ao-quality")
    {
      if (!value(v) || (args.AOQuality = IndexOf(v, { "low", "medium", "high" })) < 0)
      {
        error = "bad --ao-quality '" + v + "' (low, medium or high)";
        return false;
      }
      args.AOOptions = true;
      args.AOQualityGiven = true;
    }
    else if (a == "--ao-falloff")
    {
      if (!value(v) || (args.AOFalloff = IndexOf(v, { "binary", "cuberoot" })) < 0)
      {
        error = "bad --ao-falloff '" + v + "' (binary: visibility within the radius, or cuberoot)";
        return false;
      }
      args.AOOptions = true;
    }
    else if (a == "--ao-thickness")
    {
      if (!value(v) || !vtkFXArguments::ParseInRange(v, 1e-3, 1e3, args.AOThickness))
      {
        error = "bad --ao-thickness '" + v + "' (expected a decimal number from 0.001 to 1000: "
                "how far behind a surface it is solid, in fractions of the radius)";
        return false;
      }
      args.AOOptions = true;
    }
    else if (a == "--do-method")
    {
      if (!value(v) || (args.DOMethod = IndexOf(v, { "hemisphere", "horizon" })) < 0)
      {
        error = "bad --do-method '" + v + "' (hemisphere: the seed's samples, or horizon)";
        return false;
      }
    }
    else if (a == "--plain-vtk")
      args.PlainVTK = true;
    else if (a == "--no-ground")
      args.Ground = false;
    else if (a == "--frames")
    {
      if (!value(v) || !vtkFXArguments::ParseInt(v, 1, 100000, args.Frames))
      {
        error = "bad --frames '" + v + "' (expected 1..100000)";
        return false;
      }
    }
    else if (a == "--out")
    {
      if (!value(args.Out))
        return false;
    }
    else if (a == "--stats")
    {
      if (!value(args.Stats))
        return false;
    }
    else if (a == "--debug-channel")
    {
      if (!value(args.DebugChannel))
        return false;
      if (args.DebugChannel != "occlusion" &&
        vtkFXGBufferPass::GetChannelFromName(args.DebugChannel.c_str()) < 0)
      {
        error = "unknown G-buffer channel '" + args.DebugChannel + "'";
        return false;
      }
    }
    else if (!a.empty() && a[0] == '-')
    {
      error = "unknown option '" + a + "'";
      return false;
    }
    else if (args.Input.empty())
      args.Input = a;
    else
    {
      error = "more than one INPUT given ('" + args.Input + "', '" + a + "')";
      return false;
    }
  }
  if (args.Input.empty())
  {
    error = "no INPUT given";
    return false;
  }
  const auto has = [&args](const char* e) {
    return std::find(args.Effects.begin(), args.Effects.end(), e) != args.Effects.end();
  };
  if (has("do") && has("ssao"))
  {
    error = "'do' (directional occlusion) replaces 'ssao': give one of them";
    return false;
  }
  if (has("bleed") && !has("do"))
  {
    error = "'bleed' is directional occlusion's diffuse bleeding: use --effects do,bleed";
    return false;
  }
  if (args.DOMethod >= 0 && !has("do"))
  {
    error = "--do-method is directional occlusion's: add --effects do";
    return false;
  }
  if (args.DOMethod == 1 && has("bleed"))
  {
    // (vtkFXDirectionalOcclusionPass would quietly take the hemisphere)
    error = "'bleed' reads each hemisphere sample's occluder: --do-method horizon cannot bleed";
    return false;
  }
  if (has("do") && args.AOQualityGiven)
  {
    error = "--ao-quality picks an ambient-occlusion preset; 'do' has none (--ao-radius and "
            "--ao-falloff apply to it)";
    return false;
  }
  if (args.AOThickness > 0.0 && (has("do") || args.AOFalloff != vtkFXSSAOPass::Binary ||
                                   args.AOQuality == vtkFXPipelinePass::Low))
  {
    error = "--ao-thickness is the horizon estimator's, with the binary falloff: not with 'do', "
            "--ao-falloff cuberoot or --ao-quality low (hemisphere samples)";
    return false;
  }
  if (has("blur") && !has("ssao"))
  {
    error = has("do") ? "'do' blurs its own channels: give --effects do (not do,blur)"
                      : "effect 'blur' blurs an occlusion effect: use --effects ssao,blur";
    return false;
  }
  if (has("toon") && has("lines"))
  {
    error = "'toon' already draws feature lines: give --effects toon, or lines without bands";
    return false;
  }
  if (args.AORadius > 0.0 && args.AORadiusFraction > 0.0)
  {
    error = "give --ao-radius (world units) or --ao-radius-fraction, not both";
    return false;
  }
  if (args.AOOptions && !has("ssao") && !has("do"))
  {
    error = "--ao-* options set the ambient occlusion: add --effects ssao,blur (or do)";
    return false;
  }
  if (args.DebugChannel == "occlusion" && !has("ssao") && !has("do"))
  {
    error = "--debug-channel occlusion shows an occlusion effect: add --effects ssao or do";
    return false;
  }
  if (args.PlainVTK && !args.Effects.empty())
  {
    error = "--plain-vtk renders VTK's own image: it takes no --effects";
    return false;
  }
  if (args.PlainVTK && !args.DebugChannel.empty())
  {
    error = "--plain-vtk renders VTK's own image: it has no --debug-channel (a G-buffer's)";
    return false;
  }
  return true;
}

double Median(std::vector<double> v)
{
  if (v.empty())
    return -1.0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string JsonString(const std::string& s)
{
  std::string out = "\"";
  for (char c : s)
  {
    if (c == '"' || c == '\\')
      out += '\\';
    out += c;
  }
  return out + "\"";
}
}

int main(int argc, char* argv[])
{
  const bool keptHeap = vtkFXHeap::KeepFreedMemory();
  Arguments args;
  std::string error;
  if (!Parse(argc, argv, args, error))
  {
    std::cerr << "vtkfx-render: " << error << "\n";
    Usage(std::cerr);
    return 2;
  }

  vtkNew<vtkRenderer> renderer;
  vtkFXScenes::Options options;
  options.Ground = args.Ground;
  if (!vtkFXScenes::Populate(renderer, args.Input, options, error))
  {
    std::cerr << "vtkfx-render: " << error << "\n";
    return 1;
  }

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  // The G-buffer has one sample per pixel: compare like with like.
  window->SetMultiSamples(0);
  window->SetSize(args.Width, args.Height);
  window->AddRenderer(renderer);

  vtkNew<vtkFXPipelinePass> pipeline;
  if (!args.PlainVTK)
  {
    renderer->SetPass(pipeline);
    const auto has = [&args](const char* e) {
      return std::find(args.Effects.begin(), args.Effects.end(), e) != args.Effects.end();
    };
    pipeline->SetAmbientOcclusion(has("ssao"));
    pipeline->SetAmbientOcclusionQuality(args.AOQuality);
    pipeline->SetAmbientOcclusionFalloff(args.AOFalloff); // applies the preset
    if (args.AORadius > 0.0)
    {
      pipeline->GetSSAOPass()->SetRadius(args.AORadius);
    }
    if (args.AORadiusFraction > 0.0)
    {
      pipeline->GetSSAOPass()->SetRadiusFraction(args.AORadiusFraction);
    }
    if (args.AOThickness > 0.0)
    {
      pipeline->GetSSAOPass()->SetOccluderThickness(args.AOThickness);
    }
    pipeline->GetOcclusionBlurPass()->SetEnabled(has("blur"));
    if (has("do"))
    {
      pipeline->SetDirectionalOcclusion(true);
      pipeline->GetDirectionalOcclusionPass()->SetBleeding(has("bleed") ? 1.0 : 0.0);
      if (args.DOMethod >= 0)
      {
        pipeline->GetDirectionalOcclusionPass()->SetMethod(
          args.DOMethod == 1 ? vtkFXSSAOPass::Horizon : vtkFXSSAOPass::Hemisphere);
      }
      if (args.AORadius > 0.0)
      {
        pipeline->GetDirectionalOcclusionPass()->SetRadius(args.AORadius);
      }
      if (args.AORadiusFraction > 0.0)
      {
        pipeline->GetDirectionalOcclusionPass()->SetRadiusFraction(args.AORadiusFraction);
      }
    }
    if (has("toon") || has("lines"))
    {
      vtkNew<vtkFXToonPass> toon;
      toon->SetBands(has("toon"));
      pipeline->AddEffect("toon", toon);
    }
    if (has("avsm"))
    {
      vtkNew<vtkFXAVSMPass> avsm;
      pipeline->AddEffect("avsm", avsm);
    }
    if (has("bloom"))
    {
      vtkNew<vtkFXBloomPass> bloom;
      pipeline->AddEffect("bloom", bloom);
    }
    if (args.DebugChannel == "occlusion")
    {
      pipeline->GetCompositePass()->DebugOcclusionOn();
    }
    else if (!args.DebugChannel.empty())
    {
      pipeline->SetDebugChannel(vtkFXGBufferPass::GetChannelFromName(args.DebugChannel.c_str()));
    }
  }

  // Frame times: wall clock with a finish per frame; pass times: GPU timers,
  // whose results arrive a frame or more late (harvested each frame).
  std::vector<double> frameMs;
  std::map<std::string, std::vector<double>> passMs;
  std::vector<std::string> passesThatRan;
  vtkNew<vtkTimerLog> timer;
  const int warmup = args.Frames > 1 ? 1 : 0;
  for (int f = 0; f < args.Frames + warmup; ++f)
  {
    timer->StartTimer();
    window->Render();
    window->WaitForCompletion();
    timer->StopTimer();
    if (f >= warmup)
    {
      frameMs.push_back(1000.0 * timer->GetElapsedTime());
    }
    if (!args.PlainVTK)
    {
      passesThatRan.clear();
      for (int i = 0; i < pipeline->GetNumberOfPassesThatRan(); ++i)
      {
        const std::string name = pipeline->GetPassThatRan(i);
        passesThatRan.push_back(name);
        const double ms = pipeline->GetPassMilliseconds(name.c_str());
        if (ms >= 0.0 && f >= warmup)
        {
          passMs[name].push_back(ms);
        }
      }
    }
  }

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(args.Out.c_str());
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    std::cerr << "vtkfx-render: could not write '" << args.Out << "'\n";
    return 1;
  }

  const double frameMedian = Median(frameMs);
  std::cout << "vtkfx-render: " << args.Input << " -> " << args.Out << " (" << args.Width << "x"
            << args.Height << ", " << (args.PlainVTK ? "plain VTK" : "vtkFX")
            << "), median frame " << frameMedian << " ms over " << frameMs.size() << " frames";
  if (!args.PlainVTK)
  {
    std::cout << ", G-buffer " << pipeline->GetGBufferBytesPerPixel() << " bytes/pixel";
  }
  std::cout << "\n" << vtkFXHeap::Describe(keptHeap) << "\n";
  if (!args.PlainVTK)
  {
    std::cout << "passes:";
    for (size_t i = 0; i < passesThatRan.size(); ++i)
    {
      std::cout << (i ? "," : " ") << passesThatRan[i];
    }
    std::cout << "\n";
  }
  if (!args.PlainVTK && pipeline->GetAmbientOcclusion())
  {
    vtkFXSSAOPass* ssao = pipeline->GetSSAOPass();
    vtkFXBilateralBlurPass* blur = pipeline->GetOcclusionBlurPass();
    static const char* const qualities[] = { "low", "medium", "high" };
    std::cout << "ambient occlusion: " << qualities[pipeline->GetAmbientOcclusionQuality()]
              << ", " << (ssao->GetFalloff() == vtkFXSSAOPass::Binary ? "binary" : "cuberoot")
              << " falloff, radius " << ssao->GetEffectiveRadius() << ", "
              << (ssao->GetMethod() == vtkFXSSAOPass::Horizon ? "horizon" : "hemisphere") << " "
              << ssao->GetEffectiveNumberOfSamples() << " samples, "
              << (ssao->UsesThinOccluders()
                     ? "occluders " + vtkFXRenderUtilities::GLSLFloat(ssao->GetOccluderThickness()) +
                       " R thick, "
                     : std::string())
              << (ssao->GetHalfResolution() ? "half" : "full") << " resolution, "
              << (blur->GetEnabled()
                       ? std::string(blur->GetKernel() == vtkFXBilateralBlurPass::Box ? "box " : "") +
                         "blur radius " + std::to_string(blur->GetRadius())
                       : std::string("no blur"))
              << "\n";
  }
  if (!args.PlainVTK && pipeline->GetDirectionalOcclusion())
  {
    vtkFXDirectionalOcclusionPass* directional = pipeline->GetDirectionalOcclusionPass();
    vtkFXBilateralBlurPass* blur = pipeline->GetDirectionalOcclusionBlurPass();
    std::cout << "directional occlusion: "
              << (directional->GetMethod() == vtkFXSSAOPass::Horizon && directional->GetBleeding() <= 0.0
                     ? "horizon, "
                     : "hemisphere, ")
              << (directional->GetFalloff() == vtkFXSSAOPass::Binary ? "binary" : "cuberoot")
              << " falloff, radius " << directional->GetEffectiveRadius() << ", "
              << directional->GetEffectiveNumberOfSamples() << " samples, "
              << (directional->GetHalfResolution() ? "half" : "full") << " resolution, "
              << (blur && blur->GetEnabled() ? "blur radius " + std::to_string(blur->GetRadius())
                                             : std::string("no blur"))
              << ", bleeding " << directional->GetBleeding() << "\n";
  }
  auto* toon = args.PlainVTK ? nullptr : vtkFXToonPass::SafeDownCast(pipeline->GetEffect("toon"));
  if (toon)
  {
    std::cout << "toon: ";
    if (toon->GetBands())
    {
      std::cout << "bands at";
      for (int i = 0; i < toon->GetNumberOfBandThresholds(); ++i)
      {
        std::cout << " " << toon->GetBandThreshold(i);
      }
      std::cout << ", ";
    }
    std::cout << "lines " << toon->GetLineWidth() << " px at " << toon->GetLineReferenceHeight()
              << " rows (" << toon->GetEffectiveLineWidth(args.Height) << " px here), crease angle "
              << toon->GetCreaseAngle() << " degrees\n";
  }

  if (!args.Stats.empty())
  {
    std::ofstream json(args.Stats.c_str());
    if (!json)
    {
      std::cerr << "vtkfx-render: could not write '" << args.Stats << "'\n";
      return 1;
    }
    json << "{\n  \"input\": " << JsonString(args.Input) << ",\n  \"width\": " << args.Width
         << ",\n  \"height\": " << args.Height << ",\n  \"mode\": "
         << (args.PlainVTK ? "\"plain-vtk\"" : "\"vtkfx\"") << ",\n  \"frames\": " << frameMs.size()
         << ",\n  \"frame_ms_median\": " << frameMedian
         << ",\n  \"heap_kept\": " << (keptHeap ? "true" : "false") << ",\n  \"passes_ran\": [";
    for (size_t i = 0; i < passesThatRan.size(); ++i)
    {
      json << (i ? ", " : "") << JsonString(passesThatRan[i]);
    }
    json << "],\n  \"pass_ms_median\": {";
    bool first = true;
    for (const auto& name : passesThatRan)
    {
      json << (first ? "" : ",") << "\n    " << JsonString(name) << ": " << Median(passMs[name]);
      first = false;
    }
    json << (first ? "" : "\n  ") << "},\n  \"gbuffer_bytes_per_pixel\": "
         << (args.PlainVTK ? 0 : pipeline->GetGBufferBytesPerPixel()) << ",\n  \"gbuffer_channels\": [";
    first = true;
    for (int c = 0; !args.PlainVTK && c < vtkFXGBufferPass::NumberOfChannels; ++c)
    {
      if (pipeline->GetGBufferChannels() & vtkFXGBufferPass::ChannelBit(c))
      {
        json << (first ? "" : ", ") << JsonString(vtkFXGBufferPass::GetChannelName(c));
        first = false;
      }
    }
    json << "]\n}\n";
  }
  return 0;
}
