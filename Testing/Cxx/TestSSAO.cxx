// vtkFXSSAOPass against analytic cases, read back from its textures, for
// both definitions (Falloff Binary and CubeRoot):
// - a flat plane seen from 70 to 4 degrees is unoccluded: the raw
//   hemisphere occlusion is >= 0.98 at every pixel more than one radius
//   from the plane's border;
// - near the inner crease of two perpendicular planes, the blurred
//   estimate follows the closed form A(h) of its falloff at distance h from
//   the wall (vtkFXTest::CreaseOcclusionBinary, exact; CreaseOcclusion,
//   quadrature; A(0) = 0.5, half the cosine-weighted hemisphere inside the
//   wall), over the floor pixels 0.03 R to R from the wall (closer pixels,
//   within 1.5 pixels of the crease, cannot resolve the wall): hemisphere
//   within 0.03 on average, 0.03 in every band of (h/R)^(1/3) from 0.4 and
//   0.1 at every pixel; horizon within 0.04, 0.055 and 0.08 (Binary, 16
//   fetches) and 0.02, 0.085 and 0.11 (CubeRoot, 8 fetches);
//   every estimate darkens toward the crease band after band (bands of 20
//   pixels or more);
// - the horizon-based estimator reads a flat plane as open (0.99 or more)
//   before any blur, with no pattern of the noise tile left;
// - every value of every float read-back texture is finite and in [0, 1],
//   at full and half resolution, blurred or not;
// - the blur with Separable off is the full 2D joint-bilateral filter (the
//   CPU's, within 1e-5), and the separable blur equals it where depth is
//   constant, approximates it at depth edges (section 6).
#include "vtkFXDirectionalOcclusionPass.h"
#include "vtkFXBilateralBlurPass.h"
#include "vtkFXCompositePass.h"
#include "vtkFXGBufferPass.h"
#include "vtkFXPipelinePass.h"
#include "vtkFXRenderUtilities.h"
#include "vtkFXSSAOPass.h"
#include "vtkFXScenes.h"
#include "vtkFXOcclusionTestUtilities.h"
#include "vtkFXTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkRendererCollection.h"

#include <algorithm>
#include <functional>
#include <memory>

namespace
{
using GB = vtkFXGBufferPass;
using namespace vtkFXOcclusionTest;

// The crease's closed form of a falloff: exact for Binary; for CubeRoot,
// vtkFXTest::CreaseOcclusion tabulated in (h/R)^(1/3), where it is smooth,
// and interpolated (the quadrature costs too much per call).
double CreaseOcclusionAt(double h, double R, int falloff)
{
  if (falloff == vtkFXSSAOPass::Binary)
  {
    return vtkFXTest::CreaseOcclusion(h, R, falloff);
  }
  static std::vector<double> table;
  const int n = 256;
  if (table.empty())
  {
    for (int i = 0; i <= n; ++i)
    {
      const double x = double(i) / n;
      table.push_back(vtkFXTest::CreaseOcclusion(x * x * x * R, R));
    }
  }
  const double x = std::min(1.0, std::cbrt(std::max(0.0, h / R))) * n;
  const int i = std::min(n - 1, static_cast<int>(x));
  return table[i] + (x - i) * (table[i + 1] - table[i]);
}

// Mean |v(x) - (v(x - 2) + v(x + 2)) / 2| along rows and columns, over the
// texels that show a surface with both of those neighbours, in a (value,
// depth) image of w x h: what a pattern of period 4 leaves (its two halves
// differ) and a smooth image does not.
double TileResidual(const std::vector<float>& values, int w, int h)
{
  // (against the mean of the texels 2 away on either side, not the texel 2
  // away alone: a smooth gradient of the occlusion, as at a crease, then
  // drops out, and the half-period difference of the tile stays)
  double sum = 0.0;
  int count = 0;
  auto at = [&](int x, int y) { return 2 * (static_cast<size_t>(y) * w + x); };
  for (int y = 2; y + 2 < h; ++y)
  {
    for (int x = 2; x + 2 < w; ++x)
    {
      const size_t i = at(x, y);
      const size_t pairs[2][2] = { { at(x - 2, y), at(x + 2, y) }, { at(x, y - 2), at(x, y + 2) } };
      for (const auto& pair : pairs)
      {
        if (values[i + 1] > 0.0f && values[pair[0] + 1] > 0.0f && values[pair[1] + 1] > 0.0f)
        {
          sum += std::fabs(values[i] - 0.5 * (values[pair[0]] + values[pair[1]]));
          ++count;
        }
      }
    }
  }
  return count ? sum / count : 0.0;
}

// Where the camera's frustum puts the pixels, and the G-buffer normals the
// blur judges a half-resolution texel's tangent plane by.
struct TangentPlanes
{
  double Origin[3][3], Direction[3][3]; // vtkFXRenderUtilities::ComputeFrustumRay
  std::vector<float> Normals;           // encoded, 2 per G-buffer texel
  int Size[2] = { 0, 0 };               // G-buffer texels
  int Step = 1;                         // G-buffer texels per blurred texel

  TangentPlanes(vtkRenderer* renderer, vtkFXGBufferPass* gbuffer, int step)
    : Step(step)
  {
    vtkFXRenderUtilities::ComputeFrustumRay(renderer, this->Origin, this->Direction);
    vtkTextureObject* normals = gbuffer->GetGeometricNormalTexture();
    this->Normals = vtkFXTest::Download(normals, 2);
    this->Size[0] = static_cast<int>(normals->GetWidth());
    this->Size[1] = static_cast<int>(normals->GetHeight());
  }

  // The ray through the G-buffer texel blurred texel (x, y) holds.
  void Ray(int x, int y, double origin[3], double direction[3]) const
  {
    const double ndc[2] = { (std::min(x * this->Step, this->Size[0] - 1) + 0.5) / this->Size[0] * 2 - 1,
      (std::min(y * this->Step, this->Size[1] - 1) + 0.5) / this->Size[1] * 2 - 1 };
    for (int i = 0; i < 3; ++i)
    {
      origin[i] = this->Origin[0][i] + ndc[0] * this->Origin[1][i] + ndc[1] * this->Origin[2][i];
      direction[i] =
        this->Direction[0][i] + ndc[0] * this->Direction[1][i] + ndc[1] * this->Direction[2][i];
    }
  }

  // fxPlaneDepthAt: the depth at blurred texel (qx, qy) of the tangent plane
  // of texel (x, y) at depth d0, or d0 where the plane misses.
  double ExpectedDepth(int x, int y, double d0, int qx, int qy) const
  {
    const size_t t = 2 * (static_cast<size_t>(std::min(y * this->Step, this->Size[1] - 1)) *
        this->Size[0] + std::min(x * this->Step, this->Size[0] - 1));
    double n[3], o0[3], d[3], o[3];
    vtkFXTest::DecodeNormal(this->Normals[t], this->Normals[t + 1], n);
    this->Ray(x, y, o0, d);
    double p0[3] = { o0[0] + d0 * d[0], o0[1] + d0 * d[1], o0[2] + d0 * d[2] };
    this->Ray(qx, qy, o, d);
    const double facing = vtkMath::Dot(n, d);
    const double e = (vtkMath::Dot(n, p0) - vtkMath::Dot(n, o)) / facing;
    return std::fabs(facing) > 1e-8 && e > 0.0 ? e : d0;
  }
};

// The full 2D joint-bilateral filter, on the CPU in double precision, as
// vtkFXBilateralBlurFS defines it, over a (value, depth) image of w x h:
// a Gaussian of sigma radius / 2 per axis and the Cauchy weight of the
// tap's depth difference from the pixel's tangent plane or its own depth,
// the nearer (fxPlaneGap), relative to
// depthSigma x the pixel's depth; background (depth not above 0) passes
// through and never contributes.
std::vector<float> JointBilateral2D(const std::vector<float>& in, int w, int h, int radius,
  double depthSigma, const TangentPlanes& planes)
{
  std::vector<float> out(in);
  const double sigma = std::max(0.5 * radius, 0.5);
  auto gauss = [sigma](int i) { return std::exp(-0.5 * i * i / (sigma * sigma)); };
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const size_t p = 2 * (static_cast<size_t>(y) * w + x);
      const double d0 = in[p + 1];
      if (!(d0 > 0.0))
      {
        continue;
      }
      double sum = in[p], total = 1.0;
      for (int j = -radius; j <= radius; ++j)
      {
        for (int i = -radius; i <= radius; ++i)
        {
          const int qx = x + i, qy = y + j;
          if ((i == 0 && j == 0) || qx < 0 || qy < 0 || qx >= w || qy >= h)
          {
            continue;
          }
          const size_t q = 2 * (static_cast<size_t>(qy) * w + qx);
          if (!(in[q + 1] > 0.0f))
          {
            continue;
          }
          const double expected = planes.ExpectedDepth(x, y, d0, qx, qy);
          const double gap =
            std::min(std::fabs(in[q + 1] - expected), std::fabs(in[q + 1] - d0));
          const double r = gap / std::max(depthSigma * d0, 1e-37);
          const double weight = gauss(i) * gauss(j) / (1.0 + r * r);
          sum += weight * in[q];
          total += weight;
        }
      }
      out[p] = static_cast<float>(sum / total);
    }
  }
  return out;
}

// `values` (value, depth) with the depth set to 0 (left out of
// ValueDifference) at the texels whose window of `radius` texels in `guide`
// holds a depth other than `depth` (relative 1e-4) or lies partly outside.
std::vector<float> OnDepthOnly(std::vector<float> values, const std::vector<float>& guide,
  int w, int h, int radius, double depth)
{
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      bool flat = x >= radius && y >= radius && x + radius < w && y + radius < h;
      for (int j = -radius; flat && j <= radius; ++j)
      {
        for (int i = -radius; flat && i <= radius; ++i)
        {
          const float d = guide[2 * (static_cast<size_t>(y + j) * w + x + i) + 1];
          flat = std::fabs(d - depth) <= 1e-4 * depth;
        }
      }
      if (!flat)
      {
        values[2 * (static_cast<size_t>(y) * w + x) + 1] = 0.0f;
      }
    }
  }
  return values;
}

// Largest and root-mean-square difference of the values (not the depths)
// of two (value, depth) images over the texels with a surface.
std::array<double, 2> ValueDifference(const std::vector<float>& a, const std::vector<float>& b)
{
  double largest = 0.0, squares = 0.0;
  size_t count = 0;
  for (size_t i = 0; i + 1 < a.size() && i + 1 < b.size(); i += 2)
  {
    if (a[i + 1] > 0.0f)
    {
      const double d = std::fabs(double(a[i]) - double(b[i]));
      largest = std::max(largest, std::isfinite(d) ? d : 1e30);
      squares += d * d;
      ++count;
    }
  }
  return { largest, count ? std::sqrt(squares / count) : 1e30 };
}

// The crease of AddCrease with a plane floating above its floor: depth
// edges for the blur and the upsample to keep apart.
void AddCreaseAndFloatingPlane(Setup& s)
{
  AddCrease(s);
  const double o[3] = { -0.6, 0.25, 0.6 }, p1[3] = { 0.6, 0.25, 0.6 }, p2[3] = { -0.6, 0.25, 1.6 };
  s.Renderer->AddActor(Plane(o, p1, p2));
  s.Renderer->ResetCameraClippingRange();
}

}

namespace
{
// The crease of AddCrease in `s`, its occlusion pass set to `method`,
// `falloff` and `radius`.
vtkFXSSAOPass* CreaseOcclusion(Setup& s, int method, int falloff, double radius)
{
  AddCrease(s);
  vtkFXSSAOPass* ssao = s.Pipeline->GetSSAOPass();
  ssao->SetMethod(method);
  ssao->SetFalloff(falloff);
  ssao->SetRadius(radius);
  return ssao;
}

}

int TestSSAO(int, char*[])
{
  auto window = vtkFXTest::MakeWindow(Width, Height);
  const double radius = 0.5;

  // 0. The fetches each method takes: the hemisphere's samples as asked;
  // the horizon's 2 slices x 2 sides x NumberOfSamples / 4 steps, one
  // step at the least.
  {
    vtkNew<vtkFXSSAOPass> ssao;
    const int asked[] = { 1, 3, 6, 16, 63, 64 };
    const int horizon[] = { 4, 4, 4, 16, 60, 64 };
    for (size_t i = 0; i < sizeof(asked) / sizeof(asked[0]); ++i)
    {
      ssao->SetNumberOfSamples(asked[i]);
      ssao->SetMethod(vtkFXSSAOPass::Horizon);
      const int h = ssao->GetEffectiveNumberOfSamples();
      ssao->SetMethod(vtkFXSSAOPass::Hemisphere);
      const int s = ssao->GetEffectiveNumberOfSamples();
      FX_CHECK(h == horizon[i] && s == asked[i],
        asked[i] << " samples asked: horizon " << h << " (expected " << horizon[i]
                 << "), hemisphere " << s);
    }
  }

  const int falloffs[2] = { vtkFXSSAOPass::Binary, vtkFXSSAOPass::CubeRoot };
  const auto falloffName = vtkFXTest::FalloffName;

  // 1. A flat plane, 40 x 40 units, seen from 70 to 4 degrees above it:
  // hemisphere samples, raw.
  for (int falloff : falloffs)
  for (double elevation : { 70.0, 30.0, 10.0, 4.0 })
  {
    for (bool half : { false, true })
    {
      Setup s = MakeSetup(window);
      ViewPlane(s, elevation);
      vtkFXSSAOPass* ssao = s.Pipeline->GetSSAOPass();
      ssao->SetMethod(vtkFXSSAOPass::Hemisphere);
      ssao->SetFalloff(falloff);
      ssao->SetRadius(radius);
      ssao->SetNumberOfSamples(16);
      ssao->SetHalfResolution(half);
      s.Pipeline->GetOcclusionBlurPass()->EnabledOff();
      window->Render();
      vtkTextureObject* raw = ssao->GetOutputTexture();
      FX_CHECK(raw, "SSAO wrote its texture");
      if (CheckRange(raw, "plane") != EXIT_SUCCESS)
      {
        return EXIT_FAILURE;
      }
      const auto ao = OcclusionAtPixels(raw);
      const auto world = WorldPositions(s.Renderer, s.Pipeline->GetGBufferPass());
      int inside = 0;
      const float lowest = LowestOnPlane(ao, world, radius, inside);
      std::cout << falloffName(falloff) << " plane at " << elevation << " degrees (" << (half ? "half" : "full")
                << " resolution): lowest occlusion " << lowest << " over " << inside << " pixels"
                << std::endl;
      FX_CHECK(inside > 1000 && lowest >= 0.98f, "a flat plane is unoccluded");
    }
  }

  // 2. The inner crease of a floor (y = 0) and a wall (z = 0), both
  // estimators (horizon with its presets' fetches: 16 Binary, 8 CubeRoot),
  // against the closed form of each falloff.
  for (int method : { vtkFXSSAOPass::Hemisphere, vtkFXSSAOPass::Horizon })
  for (int falloff : falloffs)
  for (bool half : { false, true })
  {
    const bool horizon = method == vtkFXSSAOPass::Horizon;
    Setup s = MakeSetup(window);
    vtkFXSSAOPass* ssao = CreaseOcclusion(s, method, falloff, radius);
    ssao->SetNumberOfSamples(horizon ? (falloff == vtkFXSSAOPass::Binary ? 16 : 8) : 64);
    ssao->SetHalfResolution(half);
    // The pipeline's own configuration first: the blur leaves the result at
    // the SSAO's resolution, with its depth, for the composite.
    s.Pipeline->GetOcclusionBlurPass()->UpsampleOff();
    window->Render();
    {
      vtkTextureObject* shipped = s.Pipeline->GetOcclusionBlurPass()->GetOutputTexture();
      const auto values = vtkFXTest::Download(shipped, 2);
      FX_CHECK(!values.empty(), "blurred occlusion read back");
      for (size_t i = 0; i < values.size(); i += 2)
      {
        FX_CHECK(std::isfinite(values[i]) && values[i] >= 0.0f &&
            values[i] <= 1.0f && std::isfinite(values[i + 1]) &&
            values[i + 1] >= 0.0f,
          "blurred occlusion and depth at texel " << i / 2);
      }
    }
    s.Pipeline->GetOcclusionBlurPass()->UpsampleOn();
    window->Render();
    vtkTextureObject* blurred = s.Pipeline->GetOcclusionBlurPass()->GetOutputTexture();
    FX_CHECK(blurred && static_cast<int>(blurred->GetWidth()) == Width,
      "the blur upsampled to full resolution");
    // (The upsampled output is R8, in range by construction; the blurred
    // float result was checked above.)
    if (CheckRange(ssao->GetOutputTexture(), "crease, raw") != EXIT_SUCCESS)
    {
      return EXIT_FAILURE;
    }
    const auto ao = OcclusionAtPixels(blurred);
    const auto world = WorldPositions(s.Renderer, s.Pipeline->GetGBufferPass());
    // A sample near the crease projects a texel or two from it; pixels
    // closer than that (h < 0.03 R here, 1.5 pixels) cannot resolve the wall
    // and read about 0.75: compare from there on, bin by bin in
    // (h/R)^(1/3), the variable in which A(h) starts linearly from 0.5.
    double sumError = 0.0, worstError = 0.0, open = 1.0, worstH = 0.0, worstX = 0.0;
    int openPixels = 0; // floor pixels far from the crease
    double binSSAO[10] = {}, binA[10] = {};
    int binCount[10] = {};
    int n = 0;
    for (size_t i = 0; i < ao.size(); ++i)
    {
      const auto& p = world[i];
      // (away from the image border: samples that leave the screen count as
      // open, and samples at distance R, Binary, leave it first)
      const bool onFloor = p[3] > 0.0 && std::fabs(p[1]) < 1e-4 && std::fabs(p[0]) < 1.2;
      if (onFloor && p[2] < radius)
      {
        const double expected = CreaseOcclusionAt(p[2], radius, falloff);
        const int bin = std::min(9, static_cast<int>(std::cbrt(p[2] / radius) * 10));
        binSSAO[bin] += ao[i];
        binA[bin] += expected;
        ++binCount[bin];
        // (twice that at half resolution, whose texels are twice as large)
        if (p[2] >= (half ? 0.06 : 0.03) * radius)
        {
          const double error = std::fabs(ao[i] - expected);
          sumError += error;
          if (error > worstError) { worstH = p[2] / radius; worstX = p[0]; }
          worstError = std::max(worstError, error);
          ++n;
        }
      }
      if (onFloor && p[2] > 2.5 * radius)
      {
        open = std::min(open, static_cast<double>(ao[i]));
        ++openPixels;
      }
    }
    double worstBin = 0.0;
    for (int k = 0; k < 10; ++k)
    {
      if (binCount[k])
      {
        std::cout << "  (h/R)^(1/3) in [" << k / 10.0 << ", " << (k + 1) / 10.0 << "): SSAO "
                  << binSSAO[k] / binCount[k] << ", closed form " << binA[k] / binCount[k]
                  << " (" << binCount[k] << " pixels)" << std::endl;
        if (k >= 4) // h >= 0.064 R: every pixel of the bin resolves the wall
        {
          worstBin = std::max(worstBin, std::fabs(binSSAO[k] - binA[k]) / binCount[k]);
        }
      }
    }
    const double meanError = n ? sumError / n : 1.0;
    std::cout << falloffName(falloff) << (horizon ? " horizon" : " hemisphere") << " crease (" << (half ? "half" : "full") << " resolution): " << n
              << " floor pixels from 1.5 texels to R from the wall, mean |SSAO - A(h)| " << meanError
              << ", worst pixel " << worstError << " (h = " << worstH << " R, x = " << worstX << "), worst bin " << worstBin
              << "; lowest far from it " << open << std::endl;
    FX_CHECK(n >= 100, "pixels near the crease");
    if (!horizon)
    {
      FX_CHECK(meanError <= 0.03 && worstError <= 0.1 && worstBin <= 0.03,
        "the estimate follows the closed form");
    }
    else if (falloff == vtkFXSSAOPass::Binary)
    {
      // Horizons integrate visibility within R exactly for a height field,
      // up to 4 steps per side (16 fetches, at jittered distances) finding
      // the wall's top: measured 0.035 / 0.032 mean (full / half
      // resolution), 0.061 / 0.064 worst pixel, 0.048 worst bin (a bias
      // toward open: the steps sample the wall below its top).
      FX_CHECK(meanError <= 0.04 && worstError <= 0.08 && worstBin <= 0.055,
        "the horizon estimate follows the closed form");
    }
    else
    {
      // CubeRoot: XeGTAO's fade approximates that falloff; with 8 fetches
      // (2 steps per side) measured 0.013 / 0.012 mean (full / half
      // resolution), 0.089 / 0.063 worst pixel, 0.072 / 0.051 worst bin.
      FX_CHECK(meanError <= 0.02 && worstError <= 0.11 && worstBin <= 0.085,
        "the horizon estimate stays near the closed form");
    }
    // Nearer than 1.5 texels the estimate cannot resolve the wall (see
    // above), but it must still darken toward the crease, bin after bin,
    // and the nearest bin must be clearly occluded (A is 0.55 there; the
    // estimate reads 0.73 at full and 0.81 at half resolution).
    // (Bands of fewer than 20 pixels, nearest the crease, are too noisy to
    // order.)
    const int enough = 20;
    int nearest = -1;
    for (int k = 0; k < 10; ++k)
    {
      if (binCount[k] < enough)
      {
        continue;
      }
      if (nearest >= 0)
      {
        FX_CHECK(binSSAO[nearest] / binCount[nearest] <= binSSAO[k] / binCount[k] + 0.005,
          "occlusion darkens toward the crease (bin " << k << ")");
      }
      nearest = k;
      if (k == 0 || binCount[k - 1] < enough)
      {
        FX_CHECK(binSSAO[k] / binCount[k] <= 0.85, "the pixels nearest the crease are occluded");
      }
    }
    FX_CHECK(nearest >= 0, "bands near the crease");
    FX_CHECK(openPixels > 1000 && open >= 0.97,
      "far from the crease nothing occludes (" << openPixels << " pixels, lowest " << open << ")");
  }
  // 2b. Radii a float cannot hold (1e-35 rounds to 0, 1e35 squared to
  // inf): the pass keeps the radius within 1e-30..1e30, and every raw
  // value stays finite and in range, for both estimators and falloffs.
  for (int method : { vtkFXSSAOPass::Hemisphere, vtkFXSSAOPass::Horizon })
  for (int falloff : falloffs)
  for (double extreme : { 1e-35, 1e35 })
  {
    Setup s = MakeSetup(window);
    vtkFXSSAOPass* ssao = CreaseOcclusion(s, method, falloff, extreme);
    window->Render();
    const bool horizon = method == vtkFXSSAOPass::Horizon;
    std::cout << (horizon ? "horizon" : "hemisphere") << ", " << falloffName(falloff)
              << ", radius " << extreme << ": effective " << ssao->GetEffectiveRadius() << std::endl;
    FX_CHECK(ssao->GetEffectiveRadius() >= 1e-30 && ssao->GetEffectiveRadius() <= 1e30,
      "radius " << ssao->GetEffectiveRadius() << " used");
    FX_CHECK(CheckRange(ssao->GetOutputTexture(), "extreme radius, raw") ==
        EXIT_SUCCESS, "");
  }

  // 2d. Pixels that are not square (an off-axis screen, or an explicit
  // projection whose aspect is not the viewport's), here each twice as wide
  // as high: the horizon's steps still reach R in world units along both
  // image axes, and the crease (its distance from the wall runs up the
  // image) follows its closed form as in 2 (the preset's 16 fetches at
  // half resolution, blurred).
  {
    Setup s = MakeSetup(window);
    CreaseOcclusion(s, vtkFXSSAOPass::Horizon, vtkFXSSAOPass::Binary, radius);
    vtkCamera* camera = s.Renderer->GetActiveCamera();
    vtkNew<vtkMatrix4x4> wide;
    wide->DeepCopy(
      camera->GetProjectionTransformMatrix(s.Renderer->GetTiledAspectRatio(), -1, 1));
    for (int j = 0; j < 4; ++j)
    {
      wide->SetElement(0, j, 0.5 * wide->GetElement(0, j));
    }
    camera->SetExplicitProjectionTransformMatrix(wide);
    camera->UseExplicitProjectionTransformMatrixOn();
    window->Render();
    const auto ao = OcclusionAtPixels(s.Pipeline->GetOcclusionBlurPass()->GetOutputTexture());
    const auto world = WorldPositions(s.Renderer, s.Pipeline->GetGBufferPass());
    double sumError = 0.0;
    int n = 0;
    for (size_t i = 0; i < ao.size() && i < world.size(); ++i)
    {
      const auto& p = world[i];
      if (p[3] > 0.0 && std::fabs(p[1]) < 1e-4 && std::fabs(p[0]) < 1.2 &&
        p[2] >= 0.06 * radius && p[2] < radius)
      {
        sumError += std::fabs(ao[i] - CreaseOcclusionAt(p[2], radius, vtkFXSSAOPass::Binary));
        ++n;
      }
    }
    const double meanError = n ? sumError / n : 1.0;
    std::cout << "binary horizon crease, pixels twice as wide as high: " << n
              << " floor pixels, mean |SSAO - A(h)| " << meanError << std::endl;
    FX_CHECK(n >= 100 && meanError <= 0.04, "non-square pixels: the crease off its closed form");
  }

  // 2c. An occlusion pass that wrote nothing this frame (moved to the
  // Composite stage, where it does not run): the composite reads no
  // occlusion, not whatever texture unit 0 holds: the image is the one
  // without occlusion.
  {
    Setup s = MakeSetup(window);
    AddCrease(s);
    s.Pipeline->AmbientOcclusionOff();
    window->Render();
    const auto without = vtkFXScenes::Capture(window);
    s.Pipeline->AmbientOcclusionOn();
    s.Pipeline->GetSSAOPass()->SetStage(vtkFXEffectPass::Composite);
    window->Render();
    const int largest = vtkFXScenes::MaxDifference(without, vtkFXScenes::Capture(window));
    std::cout << "occlusion pass that did not run: image off the one without occlusion by "
              << largest << " levels" << std::endl;
    FX_CHECK(largest <= 1, "an occlusion texture nobody wrote was read");
  }

  // 3. The horizon-based estimator (GTAO, the default), for each falloff,
  // at full and half resolution: a flat plane seen from 70 to 4 degrees is
  // unoccluded in the raw estimate, as in the hemisphere's (each slice's
  // visible arcs over its open ones, both measured alike: 1 where nothing
  // occludes; lowest pixel measured 0.99999 or more, 0.998 at 10 degrees
  // at full resolution), without the noise tile's pattern that
  // dividing by the number of slices left (0.77 to 1.2 between directions
  // on a tilted plane, still 0.93 after the blur).
  for (int falloff : falloffs)
  for (bool half : { false, true })
  for (double elevation : { 70.0, 50.0, 30.0, 20.0, 10.0, 4.0 })
  {
    Setup s = MakeSetup(window);
    ViewPlane(s, elevation);
    vtkFXSSAOPass* ssao = s.Pipeline->GetSSAOPass();
    ssao->SetMethod(vtkFXSSAOPass::Horizon);
    ssao->SetFalloff(falloff);
    ssao->SetRadius(radius);
    ssao->SetHalfResolution(half);
    window->Render();
    vtkTextureObject* raw = ssao->GetOutputTexture();
    const auto ao = OcclusionAtPixels(raw);
    const auto world = WorldPositions(s.Renderer, s.Pipeline->GetGBufferPass());
    for (float v : ao)
    {
      FX_CHECK(std::isfinite(v) && v >= 0.0f && v <= 1.0f, "finite horizon visibility in [0, 1]");
    }
    int inside = 0;
    const float lowest = LowestOnPlane(ao, world, radius, inside);
    const double pattern = TileResidual(vtkFXTest::Download(raw, 2),
      static_cast<int>(raw->GetWidth()), static_cast<int>(raw->GetHeight()));
    std::cout << falloffName(falloff) << " horizon, plane at " << elevation << " degrees ("
              << (half ? "half" : "full") << " resolution): lowest raw " << lowest << " over " << inside
              << " pixels; tile pattern (mean |v(x) - (v(x - 2) + v(x + 2)) / 2|) " << pattern << std::endl;
    FX_CHECK(inside > 1000 && lowest >= 0.99f, "a flat plane is unoccluded (horizon-based)");
    FX_CHECK(pattern < 1e-4, "no noise-tile pattern on an open plane (horizon-based)");
  }

  // 3b. The same plane under a radius far beyond the scene (1e20 against a
  // plane a few units wide: a user's setting, or a default radius from the
  // bounds of one huge prop): the steps stop at the image's diagonal, and
  // their offsets, in units of R, were below 1e-15, where a square's floor
  // of 1e-30 bent every elevation towards the view: a tilted open plane
  // read as occluded.
  for (double elevation : { 30.0, 10.0 })
  {
    Setup s = MakeSetup(window);
    ViewPlane(s, elevation);
    vtkFXSSAOPass* ssao = s.Pipeline->GetSSAOPass();
    ssao->SetMethod(vtkFXSSAOPass::Horizon);
    ssao->SetFalloff(vtkFXSSAOPass::Binary);
    ssao->SetRadius(1e20);
    ssao->SetHalfResolution(false);
    window->Render();
    const auto ao = OcclusionAtPixels(ssao->GetOutputTexture());
    const auto world = WorldPositions(s.Renderer, s.Pipeline->GetGBufferPass());
    int inside = 0;
    const float lowest = LowestOnPlane(ao, world, radius, inside);
    std::cout << "horizon, plane at " << elevation << " degrees, radius 1e20: lowest raw " << lowest
              << " over " << inside << " pixels" << std::endl;
    FX_CHECK(inside > 1000 && lowest >= 0.99f, "a flat plane is unoccluded under a huge radius");
  }

  // 4. Where occluders leave the tile's pattern in the raw estimate (the
  // crease's floor and wall), the box kernel of radius 2, which holds each
  // tile entry once up to the depth weights, leaves less of it than the
  // Gaussian of the same radius (measured 0.56 of it, in the difference
  // from the closed form; the depth weights are in both figures).
  {
    double tileResidual[2] = { 0.0, 0.0 };
    for (int kernel : { vtkFXBilateralBlurPass::Gaussian, vtkFXBilateralBlurPass::Box })
    {
      Setup s = MakeSetup(window);
      CreaseOcclusion(s, vtkFXSSAOPass::Horizon, vtkFXSSAOPass::Binary, radius);
      s.Pipeline->GetOcclusionBlurPass()->SetKernel(kernel);
      s.Pipeline->GetOcclusionBlurPass()->SetRadius(2);
      s.Pipeline->GetOcclusionBlurPass()->UpsampleOff();
      window->Render();
      vtkTextureObject* half = s.Pipeline->GetOcclusionBlurPass()->GetOutputTexture();
      const int w = static_cast<int>(half->GetWidth());
      const int h = static_cast<int>(half->GetHeight());
      // Less the closed form at each texel's point (its G-buffer pixel's),
      // so that the crease's own curvature drops out; texels off the
      // floor and the wall are left out.
      auto values = vtkFXTest::Download(half, 2);
      const auto world = WorldPositions(s.Renderer, s.Pipeline->GetGBufferPass());
      for (int y = 0; y < h; ++y)
      {
        for (int x = 0; x < w; ++x)
        {
          const size_t i = 2 * (static_cast<size_t>(y) * w + x);
          const auto& p = world[static_cast<size_t>(std::min(2 * y, Height - 1)) * Width +
            std::min(2 * x, Width - 1)];
          const bool onFloor = std::fabs(p[1]) < 1e-4, onWall = std::fabs(p[2]) < 1e-4;
          if (p[3] > 0.0 && (onFloor || onWall))
          {
            values[i] -= static_cast<float>(
              CreaseOcclusionAt(onFloor ? p[2] : p[1], radius, vtkFXSSAOPass::Binary));
          }
          else
          {
            values[i + 1] = 0.0f;
          }
        }
      }
      tileResidual[kernel] = TileResidual(values, w, h);
    }
    std::cout << "crease: noise tile left by a blur of radius 2 (mean |r(x) - (r(x - 2) + "
                 "r(x + 2)) / 2| of r, the blurred estimate less the closed form): Gaussian "
              << tileResidual[0] << ", box " << tileResidual[1] << std::endl;
    FX_CHECK(tileResidual[1] < 0.7 * tileResidual[0], "the box kernel cancels the noise tile");
  }

  // 5. The pass skips the pixels without a surface (SkipBackground: by the
  // G-buffer's depth at full resolution, by a mask of its own at half): the
  // raw occlusion is bit for bit the same as with every pixel shaded, for
  // both estimators, one channel and three (directional occlusion), over a
  // plane that leaves background in view; also in a window of odd size,
  // whose half-resolution texels of the last row and column stand for a
  // clamped G-buffer pixel.
  auto oddWindow = vtkFXTest::MakeWindow(Width + 1, Height + 1);
  for (vtkRenderWindow* target : { window.GetPointer(), oddWindow.GetPointer() })
  for (bool half : { false, true })
  for (int method : { vtkFXSSAOPass::Hemisphere, vtkFXSSAOPass::Horizon })
  for (bool directional : { false, true })
  {
    std::vector<float> raw[2], blurred[2], surfaces;
    for (bool skip : { true, false })
    {
      Setup s = MakeSetup(target);
      ViewPlane(s, 10.0);
      if (directional)
      {
        s.Pipeline->DirectionalOcclusionOn();
      }
      vtkFXSSAOPass* pass = directional
        ? static_cast<vtkFXSSAOPass*>(s.Pipeline->GetDirectionalOcclusionPass())
        : s.Pipeline->GetSSAOPass();
      pass->SetMethod(method);
      pass->SetRadius(radius);
      pass->SetHalfResolution(half);
      pass->SetSkipBackground(skip);
      vtkFXBilateralBlurPass* blur = directional ? s.Pipeline->GetDirectionalOcclusionBlurPass()
                                                 : s.Pipeline->GetOcclusionBlurPass();
      blur->SetSkipBackground(skip);
      blur->UpsampleOff(); // (its own passes' output, at the occlusion's resolution)
      target->Render();
      FX_CHECK(pass->GetSkippedBackground() == skip, "the background was " << (skip ? "not " : "")
        << "skipped");
      // (the blur skips it for one value with its depth only)
      FX_CHECK(blur->GetSkippedBackground() == (skip && !directional),
        "the blur's background was " << (blur->GetSkippedBackground() ? "" : "not ") << "skipped");
      // (one value and its depth, or three packed with normal and depth)
      raw[skip ? 0 : 1] = vtkFXTest::Download(pass->GetOutputTexture(), directional ? 4 : 2);
      blurred[skip ? 0 : 1] = vtkFXTest::Download(blur->GetOutputTexture(), directional ? 4 : 2);
      if (skip)
      {
        // What the depth test skipped against: 1 at background texels
        surfaces = vtkFXTest::Download(pass->GetOutput("occlusion").Surfaces, 1);
      }
    }
    size_t background = 0, misplaced = 0;
    const size_t stride = directional ? 4 : 2;
    FX_CHECK(surfaces.size() * stride == raw[1].size(), "the surfaces skipped against were read");
    for (size_t i = 0; i + stride - 1 < raw[1].size(); i += stride)
    {
      const bool open = !(raw[1][i + stride - 1] > 0.0f); // the depth rides along, last
      background += open ? 1 : 0;
      // (so a test that rejected nothing, or everything, would show here)
      misplaced += open == (surfaces[i / stride] == 1.0f) ? 0 : 1;
    }
    FX_CHECK(misplaced == 0, misplaced << " texels skipped where there is a surface, or "
                                          "shaded where there is none");
    std::cout << target->GetSize()[0] << " x " << target->GetSize()[1] << ", "
              << (half ? "half" : "full") << " resolution, " << (directional ? "directional, " : "")
              << (method == vtkFXSSAOPass::Horizon ? "horizon" : "hemisphere") << ": "
              << background << " background texels; skipped and shaded "
              << (raw[0] == raw[1] ? "identical" : "differ") << ", blurred "
              << (blurred[0] == blurred[1] ? "identical" : "differ") << std::endl;
    FX_CHECK(!blurred[0].empty() && blurred[0] == blurred[1], "SkipBackground changed the blur");
    FX_CHECK(!raw[0].empty() && raw[0] == raw[1] && background > (half ? 250u : 1000u),
      "SkipBackground changed the occlusion (or no background was in view)");
  }

  // 6. The separable blur against the full 2D joint-bilateral filter
  // (Separable off), half resolution, radius 4, the horizon estimator's
  // noisy raw occlusion as input. The 2D pass must be that filter: the
  // CPU's double-precision sum of the same raw texels within 1e-5 (float
  // sums of 81 terms of at most 1 round at about 1e-6). On a
  // rectangle facing the camera, with background around it, depth is
  // constant and the surface mask a product of a row mask and a column
  // mask, so the two passes compute exactly the 2D filter (their weights
  // factor): 1e-5 there too, at the texels whose window lies on the
  // rectangle (a block standing on it gives the occlusion to smooth). Where depth changes (a crease and a plane
  // floating over it), the two passes weigh a tap off the pixel's row
  // against the tap in its row, not the pixel: they differ from the 2D
  // filter there (measured: 0.035 at most, 0.0012 RMS over the image, where
  // the blur removes noise of 0.042 RMS; asserted: 0.005 RMS). The CPU
  // judges each tap against the pixel's tangent plane from the G-buffer's
  // normals and the camera's frustum rays, as the shader does.
  for (bool facing : { true, false })
  {
    std::vector<float> raw[2], blurred[2];
    std::unique_ptr<TangentPlanes> planes;
    int w = 0, h = 0;
    for (bool separable : { true, false })
    {
      Setup s = MakeSetup(window);
      vtkFXSSAOPass* pass = s.Pipeline->GetSSAOPass();
      if (facing)
      {
        const double o[3] = { -1.5, -0.9, 0 }, p1[3] = { 1.5, -0.9, 0 }, p2[3] = { -1.5, 0.9, 0 };
        s.Renderer->AddActor(Plane(o, p1, p2));
        // A block on the plane, whose occlusion gives the blur something
        // to smooth (an open plane's horizon estimate is 1 everywhere).
        vtkNew<vtkCubeSource> block;
        block->SetCenter(0.0, 0.0, 0.15);
        block->SetXLength(0.3), block->SetYLength(0.3), block->SetZLength(0.3);
        s.Renderer->AddActor(vtkFXTest::SurfaceActor(block));
        vtkCamera* camera = s.Renderer->GetActiveCamera();
        camera->SetFocalPoint(0, 0, 0);
        camera->SetPosition(0, 0, 6);
        camera->SetViewUp(0, 1, 0);
        s.Renderer->ResetCameraClippingRange();
      }
      else
      {
        AddCreaseAndFloatingPlane(s);
      }
      pass->SetMethod(vtkFXSSAOPass::Horizon);
      pass->SetRadius(radius);
      pass->SetHalfResolution(true);
      vtkFXBilateralBlurPass* blur = s.Pipeline->GetOcclusionBlurPass();
      blur->SetKernel(vtkFXBilateralBlurPass::Gaussian);
      blur->SetRadius(4);
      blur->UpsampleOff();
      blur->SetSeparable(separable);
      window->Render();
      vtkTextureObject* out = blur->GetOutputTexture();
      FX_CHECK(out && pass->GetOutputTexture(), "the occlusion and its blur were written");
      w = static_cast<int>(out->GetWidth());
      h = static_cast<int>(out->GetHeight());
      raw[separable ? 0 : 1] = vtkFXTest::Download(pass->GetOutputTexture(), 2);
      blurred[separable ? 0 : 1] = vtkFXTest::Download(out, 2);
      planes.reset(new TangentPlanes(s.Renderer, s.Pipeline->GetGBufferPass(), 2));
    }
    FX_CHECK(!raw[0].empty() && raw[0] == raw[1], "the raw occlusion changed between renders");
    const auto exact = JointBilateral2D(raw[1], w, h, 4, 0.02, *planes);
    const auto full = ValueDifference(blurred[1], exact);
    // (facing: at the plane's texels whose whole window lies on the
    // plane, where the two passes are the 2D filter)
    const double planeDepth = 6.0; // (the camera's distance to the facing plane)
    const auto onPlane = OnDepthOnly(raw[1], raw[1], w, h, 4, planeDepth);
    if (facing)
    {
      size_t kept = 0;
      for (size_t i = 1; i < onPlane.size(); i += 2)
      {
        kept += onPlane[i] > 0.0f ? 1 : 0;
      }
      FX_CHECK(kept > 1000, "texels whose window lies on the facing plane: " << kept);
    }
    const auto separable = ValueDifference(
      facing ? OnDepthOnly(blurred[0], raw[1], w, h, 4, planeDepth) : blurred[0], exact);
    const auto input = ValueDifference(facing ? onPlane : raw[1], exact);
    std::cout << (facing ? "rectangle facing the camera" : "crease and floating plane")
              << ": against the CPU's 2D joint-bilateral filter, the 2D pass differs by at most "
              << full[0] << ", the separable blur by at most " << separable[0] << " (RMS "
              << separable[1] << "), the unblurred input by RMS " << input[1] << std::endl;
    FX_CHECK(full[0] <= 1e-5, "the 2D pass is not the 2D joint-bilateral filter");
    // (the blur must move the values well past the tolerances: measured
    // 0.019 RMS around the block, 0.042 over the crease)
    FX_CHECK(input[1] > 0.005, "the input has no noise for the blur to remove");
    if (facing)
    {
      FX_CHECK(separable[0] <= 1e-5, "the separable blur differs from the 2D filter on a plane "
                                     "of constant depth");
    }
    else
    {
      FX_CHECK(separable[0] > 1e-3 && separable[1] <= 0.005,
        "the separable blur is not the approximation it should be at depth edges");
    }
  }

  // 7. The composite's depth-aware upsample of the half-resolution
  // occlusion (DepthAwareUpsample, with textureGather where it exists) is
  // the blur's upsample pass (vtkFXJointUpsample.glsl with texel fetches,
  // written as 8 bits): the occlusion views within 2 levels (the blur's
  // 8-bit output and the order of the sums), over the crease with a plane
  // floating above it; the bilinear read differs at its depth edges. Also
  // at an odd window size (the last half-resolution row and column stand
  // for one pixel, which the gathers clamp as the fetches do).
  for (vtkRenderWindow* target : { window.GetPointer(), oddWindow.GetPointer() })
  {
    std::vector<unsigned char> views[3];
    for (int k = 0; k < 3; ++k)
    {
      Setup s = MakeSetup(target);
      AddCreaseAndFloatingPlane(s);
      s.Pipeline->GetSSAOPass()->SetRadius(radius);
      s.Pipeline->GetSSAOPass()->SetDepthAwareUpsample(k != 2);
      s.Pipeline->GetOcclusionBlurPass()->SetUpsample(k == 1);
      s.Pipeline->GetCompositePass()->DebugOcclusionOn();
      target->Render();
      views[k] = vtkFXScenes::Capture(target);
    }
    const int joint = vtkFXScenes::MaxDifference(views[0], views[1]);
    const int bilinear = vtkFXScenes::MaxDifference(views[2], views[1]);
    std::cout << target->GetSize()[0] << " x " << target->GetSize()[1]
              << ", composite's depth-aware upsample against the blur's: at most " << joint
              << " levels apart (bilinear: " << bilinear << ")" << std::endl;
    FX_CHECK(!views[0].empty() && joint <= 2 && bilinear > 10,
      "the composite's upsample is not the blur's joint-bilateral one");
  }
  return EXIT_SUCCESS;
}
