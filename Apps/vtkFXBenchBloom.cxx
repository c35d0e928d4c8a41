// vtkfx-bench bloom: vtkFXBloomPass against the glow it approximates,
// computed exactly on the CPU, and against the seed's direct Gaussian
// (seed 004: one full-resolution pass of 21 x 21 taps, spaced to reach the
// radius), as RMSE against time.
//
// The glow vtkFXBloomPass aims at is the emission convolved with the mean
// of the Gaussians of its levels (vtkFXBloomPass::GetLevelSigma), times
// its intensity, added to the image. The reference image is the frame
// without bloom plus that glow, computed in double precision from the
// emission channel the pipeline rendered (separable Gaussians, 4 sigma
// wide). The direct methods weigh their taps by the same kernel (taps
// normalised, so they keep the energy too). Frames are interleaved
// between one window per method. Writes DIR/bloom.csv (scene, method,
// setting, ms, rmse, psnr; ms is the bloom's share of the frame, the frame
// minus the frame without bloom), DIR/bloom-SCENE.png (RMSE against time)
// and DIR/bloom-strip-SCENE.png (reference | vtkFX | direct 21x21 | none).
#include "vtkFXBench.h"
#include "vtkFXBloomPass.h"
#include "vtkFXGBufferPass.h"
#include "vtkFXPipelinePass.h"
#include "vtkFXRenderUtilities.h"
#include "vtkFXScenes.h"

#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPlotPoints.h"
#include "vtkRenderState.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTimerLog.h"
#include "vtkFXOpenGL.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace
{
using GB = vtkFXGBufferPass;
using namespace vtkFXBench;

// The glow kernel of vtkFXBloomPass at `levels` levels, at offset (x, y)
// pixels: the mean of its levels' Gaussians.
double Kernel(int levels, double x, double y)
{
  double k = 0.0;
  for (int level = 1; level <= levels; ++level)
  {
    const double s = vtkFXBloomPass::GetLevelSigma(level);
    k += std::exp(-(x * x + y * y) / (2.0 * s * s)) / (2.0 * 3.14159265358979 * s * s);
  }
  return k / levels;
}

// The seed's glow: one full-resolution pass of Taps x Taps texel fetches of
// the emission, Step pixels apart, weighted by the kernel, added onto the
// image.
class DirectGlow : public vtkFXEffectPass
{
public:
  static DirectGlow* New();
  vtkTypeMacro(DirectGlow, vtkFXEffectPass);
  DirectGlow() { this->Stage = PostProcess; }
  unsigned int GetRequiredChannels() override { return GB::ChannelBit(GB::Emission); }
  // Like vtkFXBloomPass without a threshold: emission only, no HDR target.
  bool GetNeedsHDRTarget() override { return false; }
  void Configure(int taps, int step, int levels, double intensity)
  {
    this->Taps = taps;
    this->Step = step;
    this->Weights.clear();
    const int r = taps / 2;
    double sum = 0.0;
    for (int y = -r; y <= r; ++y)
    {
      for (int x = -r; x <= r; ++x)
      {
        this->Weights.push_back(static_cast<float>(Kernel(levels, x * step, y * step)));
        sum += this->Weights.back();
      }
    }
    for (float& w : this->Weights)
    {
      w = static_cast<float>(intensity * w / sum);
    }
  }
  void Render(const vtkRenderState* s) override
  {
    auto* window = vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow());
    vtkTextureObject* emission = this->GBuffer ? this->GBuffer->GetChannelTexture(GB::Emission) : nullptr;
    if (!emission)
    {
      return;
    }
    std::ostringstream fs;
    fs << "//VTK::System::Dec\nin vec2 texCoord;\nuniform sampler2D fxEmission;\n"
          "uniform float fxWeights["
       << this->Weights.size()
       << "];\nuniform int fxStep;\n//VTK::Output::Dec\n"
          "void main() {\n"
          "  ivec2 size = textureSize(fxEmission, 0);\n"
          "  ivec2 p = ivec2(texCoord * vec2(size));\n"
          "  vec3 sum = vec3(0.0);\n"
          "  int r = "
       << this->Taps / 2
       << ";\n"
          "  for (int y = -r; y <= r; ++y)\n"
          "    for (int x = -r; x <= r; ++x)\n"
          "      sum += fxWeights[(y + r) * (2 * r + 1) + x + r] *\n"
          "        texelFetch(fxEmission, clamp(p + fxStep * ivec2(x, y), ivec2(0), size - 1), 0).rgb;\n"
          "  gl_FragData[0] = vec4(sum, 0.0);\n"
          "}\n";
    vtkShaderProgram* program = vtkFXRenderUtilities::ReadyQuad(this->Quad, window, fs.str());
    if (!program)
    {
      return;
    }
    vtkFXRenderUtilities::BlendOntoScope blend(window, GL_ONE, GL_ONE, GL_ZERO, GL_ONE);
    emission->Activate();
    program->SetUniformi("fxEmission", emission->GetTextureUnit());
    program->SetUniform1fv("fxWeights", static_cast<int>(this->Weights.size()), this->Weights.data());
    program->SetUniformi("fxStep", this->Step);
    this->Quad.Helper->Render();
    emission->Deactivate();
  }
  void ReleaseGraphicsResources(vtkWindow* w) override
  {
    vtkFXRenderUtilities::ReleaseQuad(this->Quad, w);
  }

private:
  int Taps = 21;
  int Step = 1;
  std::vector<float> Weights;
  vtkFXRenderUtilities::FullScreenQuad Quad;
};
vtkStandardNewMacro(DirectGlow);

// One channel of a w x h image convolved with a Gaussian of deviation s
// along x then y (4 s wide, edges clamped, as the GPU's samplers clamp).
std::vector<double> Gaussian(const std::vector<double>& in, int w, int h, double s)
{
  const int r = static_cast<int>(std::ceil(4.0 * s));
  std::vector<double> weights(2 * r + 1);
  double sum = 0.0;
  for (int i = -r; i <= r; ++i)
  {
    sum += weights[i + r] = std::exp(-i * i / (2.0 * s * s));
  }
  for (double& v : weights)
  {
    v /= sum;
  }
  std::vector<double> tmp(in.size(), 0.0), out(in.size(), 0.0);
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      double v = 0.0;
      for (int i = -r; i <= r; ++i)
      {
        v += weights[i + r] * in[static_cast<size_t>(y) * w + std::min(w - 1, std::max(0, x + i))];
      }
      tmp[static_cast<size_t>(y) * w + x] = v;
    }
  }
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      double v = 0.0;
      for (int i = -r; i <= r; ++i)
      {
        v += weights[i + r] * tmp[static_cast<size_t>(std::min(h - 1, std::max(0, y + i))) * w + x];
      }
      out[static_cast<size_t>(y) * w + x] = v;
    }
  }
  return out;
}

// The image without bloom plus intensity x (kernel * emission), rounded to
// bytes as the window would.
std::vector<unsigned char> ReferenceImage(const std::vector<unsigned char>& base,
  const std::vector<float>& emission, int w, int h, int levels, double intensity)
{
  std::vector<unsigned char> image(base.size());
  for (int c = 0; c < 3; ++c)
  {
    std::vector<double> channel(static_cast<size_t>(w) * h);
    for (size_t i = 0; i < channel.size(); ++i)
    {
      channel[i] = emission[4 * i + c];
    }
    std::vector<double> glow(channel.size(), 0.0);
    for (int level = 1; level <= levels; ++level)
    {
      const auto blurred = Gaussian(channel, w, h, vtkFXBloomPass::GetLevelSigma(level));
      for (size_t i = 0; i < glow.size(); ++i)
      {
        glow[i] += blurred[i] / levels;
      }
    }
    for (size_t i = 0; i < glow.size(); ++i)
    {
      const double v = base[3 * i + c] / 255.0 + intensity * glow[i];
      image[3 * i + c] = static_cast<unsigned char>(std::lround(255.0 * std::min(1.0, std::max(0.0, v))));
    }
  }
  return image;
}

struct Method
{
  std::string Name;
  std::string Setting;
  int Family; // 0 vtkFX, 1 direct; -1 the frame without bloom
  std::function<void(vtkFXPipelinePass*, int levels)> Configure;
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkFXPipelinePass> Pipeline;
  std::vector<double> FrameMs;
  std::vector<unsigned char> Image;
  double Ms = 0.0, RMSE = 0.0, PSNR = 0.0;
};

std::vector<Method> MakeMethods(double intensity)
{
  const auto bloom = [intensity](bool suppress) {
    return [intensity, suppress](vtkFXPipelinePass* p, int) {
      vtkNew<vtkFXBloomPass> b;
      b->SetIntensity(intensity);
      b->SetFireflySuppression(suppress);
      p->AddEffect("bloom", b);
    };
  };
  const auto direct = [intensity](int taps) {
    return [intensity, taps](vtkFXPipelinePass* p, int levels) {
      // Taps spaced to reach 3 deviations of the widest level.
      const double reach = 3.0 * vtkFXBloomPass::GetLevelSigma(levels);
      const int step = std::max(1, static_cast<int>(std::lround(reach / (taps / 2))));
      vtkNew<DirectGlow> d;
      d->Configure(taps, step, levels, intensity);
      p->AddEffect("direct", d);
    };
  };
  return { { "vtkfx-none", "no bloom", -1, [](vtkFXPipelinePass*, int) {} },
    { "vtkfx-bloom", "default", 0, bloom(true) },
    { "vtkfx-bloom", "no firefly suppression", 0, bloom(false) },
    { "direct", "21x21 taps", 1, direct(21) }, { "direct", "11x11 taps", 1, direct(11) } };
}
}

namespace vtkFXBench
{
int BenchBloom(const Options& o)
{
  std::ofstream csv;
  std::string csvPath;
  if (!OpenReport(o, "bloom", csv, csvPath))
  {
    return 1;
  }
  const double intensity = 0.5; // vtkFXBloomPass's default
  int skipped = 0;                // inputs without emission
  std::vector<Method> methods = MakeMethods(intensity);
  for (auto& m : methods)
  {
    m.Window = MakeWindow(o);
  }
  vtkNew<vtkTimerLog> timer;
  vtkNew<vtkFXBloomPass> probe; // for the number of levels
  const int levels = probe->GetNumberOfLevels(o.Width, o.Height);
  for (const std::string& input : o.Inputs)
  {
    for (auto& m : methods)
    {
      std::string error;
      auto renderer = Stage(m.Window, input, error);
      if (!renderer)
      {
        std::cerr << "vtkfx-bench: " << error << "\n";
        return 1;
      }
      m.Pipeline = vtkSmartPointer<vtkFXPipelinePass>::New();
      m.Configure(m.Pipeline, levels);
      renderer->SetPass(m.Pipeline);
      m.FrameMs.clear();
      m.Window->Render(); // warm up
    }
    TimeFramesInTurn(methods, o.Frames, input, timer);
    for (auto& m : methods)
    {
      m.Image = vtkFXScenes::Capture(m.Window);
    }
    Method& none = methods[0];
    Method& ours = methods[1];
    const auto emission = Download(
      ours.Window, ours.Pipeline->GetGBufferPass()->GetChannelTexture(GB::Emission), 4);
    if (emission.empty())
    {
      std::cerr << "vtkfx-bench: " << input << " has nothing emissive: no glow to measure\n";
      ++skipped;
      continue;
    }
    timer->StartTimer();
    const auto reference =
      ReferenceImage(none.Image, emission, o.Width, o.Height, levels, intensity);
    timer->StopTimer();
    const double cpuMs = 1000.0 * timer->GetElapsedTime();
    const double noneMs = Median(none.FrameMs);
    const std::string tag = FileTag(input);
    csv << input << ",exact-cpu,mean of " << levels << " Gaussians," << cpuMs << ",0,inf\n";
    std::vector<PlotPoint> points;
    for (auto& m : methods)
    {
      const double frame = Median(m.FrameMs);
      m.Ms = frame - noneMs;
      m.RMSE = RMSE(m.Image, reference);
      m.PSNR = vtkFXScenes::PSNR(m.Image, reference);
      csv << input << "," << m.Name << "," << m.Setting << "," << m.Ms << "," << m.RMSE << ","
          << m.PSNR << "\n";
      std::cout << std::fixed << std::setprecision(2) << input << ": " << m.Name << " ("
                << m.Setting << ") frame " << frame << " ms, " << frame / noneMs
                << "x the frame without bloom, RMSE " << std::setprecision(5) << m.RMSE
                << ", PSNR " << std::setprecision(2) << m.PSNR << " dB" << std::endl;
      if (m.Family >= 0)
      {
        points.push_back({ m.Family, m.Setting, m.Ms, m.RMSE });
      }
    }
    std::cout << input << ": exact glow on the CPU (" << levels << " Gaussians, sigma up to "
              << vtkFXBloomPass::GetLevelSigma(levels) << " px) " << cpuMs << " ms" << std::endl;
    WritePointsPlot({ { "vtkFX bloom", 200, 60, 30, vtkPlotPoints::CIRCLE },
                      { "direct Gaussian (seed 004)", 30, 80, 200, vtkPlotPoints::SQUARE } },
      points, tag + ": glow error against time (" + std::to_string(o.Width) + "x" +
        std::to_string(o.Height) + ")",
      "bloom time (ms per frame, frame minus frame without bloom)", "RMSE against the exact glow",
      o.Out + "/bloom-" + tag + ".png");
    WriteRGBStrip({ &reference, &ours.Image, &methods[3].Image, &none.Image }, o.Width, o.Height,
      o.Out + "/bloom-strip-" + tag + ".png");
  }
  if (skipped == static_cast<int>(o.Inputs.size()))
  {
    std::cerr << "vtkfx-bench: no input has anything emissive; " << csvPath
              << " holds no measurement\n";
    return 1;
  }
  std::cout << "wrote " << csvPath << " (" << o.Width << "x" << o.Height << ", median of "
            << o.Frames << " interleaved frames)\n";
  return 0;
}
}
