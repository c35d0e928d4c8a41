// TestDirectionalOcclusion: vtkFXDirectionalOcclusionPass and the G-buffer's
// shading normals (vtkFXGBufferPass::SetBump), on the inner crease of a
// floor (y = 0, z > 0) and a wall (z = 0), visibility within R = 0.5:
// 1. each channel, blurred, against its exact value: the visibility under
//    the lobe 3 w_k(direction) x cosine, integrated over the hemisphere by
//    quadrature for a floor point at distance h from the wall (the basis in
//    world coordinates from the same frame as the shader); the mean of the
//    channels against the crease's closed form, as TestSSAO checks plain
//    AO; the channel facing the wall darker than the one facing away;
// 2. with no bump the composite's ambient visibility is the channels' mean
//    (the resolve with weights 1/3), within 8-bit rounding, and what plain
//    AO (the same samples, radius, resolution and blur) shows, within 0.06
//    per band;
// 3. a floor bumped by a ramp of slope s (height s z), as a scalar bump and
//    as VTK's normal texture (tangents along +z): its shading normal
//    (the Normal channel) is the analytic (0, 1, -s) / |.|, its geometric
//    normal stays +y, and the composite shows sum_k c_k(n_s) channel_k
//    exactly; turned towards the wall it reads darker than the mean, away
//    from it lighter;
// 4. the geometric-normal channel is allocated only while an occlusion
//    effect runs and a visible prop has a bump; a prop without a bump
//    beside one with it (bump or normal texture) has the same normal in
//    both channels, bit for bit;
// 5. the bumped crease (scalar bump and normal texture) under scale 1e-6 /
//    1e6, translated by 1e6, parallel
//    projection and near/far 1e-6: channels finite in [0, 1], both normals
//    finite and of unit length;
// 6. diffuse bleeding off by default (no texture, no pass); on, with a red
//    wall lit by one directional light, the floor receives
//    rho_wall x D_wall x (1 - A(h)) (every blocked ray ends on the wall,
//    whose direct light D_wall is uniform), red before green and blue in
//    the wall's proportions; in the lit image at half resolution, a plate
//    floating in front of that band bounces nothing: no pixel of it
//    changes with bleeding on (the bleeding is read by depth, as the
//    channels are).
#include "vtkInformation.h"
#include "vtkActorCollection.h"
#include "vtkFXDirectionalOcclusionPass.h"
#include "vtkFXCompositePass.h"
#include "vtkFXOcclusionTestUtilities.h"
#include "vtkFXScenes.h"

#include "vtkFloatArray.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPolyDataMapper.h"
#include "vtkTexture.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkProperty.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <array>

namespace
{
using namespace vtkFXOcclusionTest;
const double Radius = 0.5;

// vtkFXOcclusionBasis.glsl: the basis in tangent coordinates, and the
// frame of a view-space normal.
const double BasisTangent[3][3] = { { 0.816496581, 0.0, 0.577350269 },
  { -0.408248290, 0.707106781, 0.577350269 }, { -0.408248290, -0.707106781, 0.577350269 } };

void Frame(const double n[3], double t[3], double b[3])
{
  const double k = 1.0 / std::max(1.0 + n[2], 1e-4);
  const double xy = -n[0] * n[1] * k;
  t[0] = 1.0 - n[0] * n[0] * k;
  t[1] = xy;
  t[2] = -n[0];
  b[0] = xy;
  b[1] = 1.0 - n[1] * n[1] * k;
  b[2] = -n[1];
}

// The basis of a world-space normal, in world coordinates (the shader
// builds it in view space).
void WorldBasis(vtkRenderer* ren, const double normal[3], double basis[3][3])
{
  vtkMatrix4x4* view = ren->GetActiveCamera()->GetViewTransformMatrix();
  double n[3] = { 0, 0, 0 };
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      n[r] += view->GetElement(r, c) * normal[c];
    }
  }
  double t[3], b[3];
  Frame(n, t, b);
  for (int k = 0; k < 3; ++k)
  {
    double v[3];
    for (int r = 0; r < 3; ++r)
    {
      v[r] = BasisTangent[k][0] * t[r] + BasisTangent[k][1] * b[r] + BasisTangent[k][2] * n[r];
    }
    for (int c = 0; c < 3; ++c) // rotation inverse: the transpose
    {
      basis[k][c] = view->GetElement(0, c) * v[0] + view->GetElement(1, c) * v[1] +
        view->GetElement(2, c) * v[2];
    }
  }
}

void Weights(const double d[3], const double basis[3][3], double w[3])
{
  double sum = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    const double c = std::max(0.0, vtkMath::Dot(d, basis[k]));
    w[k] = c * c;
    sum += w[k];
  }
  for (int k = 0; k < 3; ++k)
  {
    w[k] = sum > 1e-12 ? w[k] / sum : 1.0 / 3.0;
  }
}

// Exact channels at a floor point h in front of the wall: 3 x the mean of
// w_k x visibility over cosine-distributed directions (a 400 x 400
// midpoint grid; a ray is blocked when it reaches the wall before R).
std::array<double, 3> ExactChannels(double h, const double basis[3][3])
{
  const int n = 400;
  std::array<double, 3> sum = { 0, 0, 0 };
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      const double u1 = (i + 0.5) / n, u2 = (j + 0.5) / n;
      const double s = std::sqrt(1.0 - u2), phi = 2.0 * vtkMath::Pi() * u1;
      const double d[3] = { s * std::cos(phi), std::sqrt(u2), s * std::sin(phi) };
      const bool blocked = d[2] < 0.0 && h < -d[2] * Radius;
      if (blocked)
      {
        continue;
      }
      double w[3];
      Weights(d, basis, w);
      for (int k = 0; k < 3; ++k)
      {
        sum[k] += w[k];
      }
    }
  }
  for (double& v : sum)
  {
    v *= 3.0 / (static_cast<double>(n) * n);
  }
  return sum;
}

// The composite's output, red channel, one byte per pixel (rows bottom-up).
std::vector<unsigned char> Grab(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  auto* bytes = vtkUnsignedCharArray::SafeDownCast(grab->GetOutput()->GetPointData()->GetScalars());
  std::vector<unsigned char> red(static_cast<size_t>(Width) * Height);
  for (size_t i = 0; i < red.size(); ++i)
  {
    red[i] = bytes->GetValue(3 * i);
  }
  return red;
}

// The floor's ramp as VTK's normal texture instead of a scalar bump: a
// 2 x 2 texture of the tangent-space normal (-s, 0, 1) / |.|, with
// tangents along +z (so that the bitangent, normal x tangent, is +x): the
// shading normal is the ramp's, (0, 1, -s) / |.|, up to the texture's 8
// bits.
void UseNormalTexture(vtkActor* floor, double slope)
{
  auto* mapper = vtkPolyDataMapper::SafeDownCast(floor->GetMapper());
  mapper->Update();
  vtkNew<vtkPolyData> data;
  data->DeepCopy(mapper->GetInput());
  const vtkIdType points = data->GetNumberOfPoints();
  vtkNew<vtkFloatArray> tangents, tcoords;
  tangents->SetNumberOfComponents(3);
  tangents->SetName("Tangents");
  tcoords->SetNumberOfComponents(2);
  tcoords->SetName("TCoords");
  for (vtkIdType i = 0; i < points; ++i)
  {
    const double* p = data->GetPoint(i);
    tangents->InsertNextTuple3(0.0, 0.0, 1.0);
    tcoords->InsertNextTuple2(p[2], p[0]); // u along the tangent
  }
  data->GetPointData()->SetTangents(tangents);
  data->GetPointData()->SetTCoords(tcoords);
  mapper->SetInputData(data);
  const double length = std::sqrt(1.0 + slope * slope);
  const double normal[3] = { -slope / length, 0.0, 1.0 / length };
  vtkNew<vtkImageData> image;
  image->SetDimensions(2, 2, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* texels = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int t = 0; t < 4; ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      texels[3 * t + c] = static_cast<unsigned char>(std::lround(255.0 * (0.5 + 0.5 * normal[c])));
    }
  }
  vtkNew<vtkTexture> texture;
  texture->SetInputData(image);
  texture->InterpolateOn();
  floor->GetProperty()->SetNormalTexture(texture);
}

// The floor (with a ramp height s z when s != 0, as a bump or, with
// `normalTexture`, as VTK's normal texture) and the wall; as
// vtkFXOcclusionTest::AddCrease sets them up.
vtkActor* BuildCrease(Setup& s, double slope, bool normalTexture = false)
{
  vtkActor* floor = AddCrease(s);
  if (slope != 0.0 && normalTexture)
  {
    UseNormalTexture(floor, slope);
  }
  else if (slope != 0.0)
  {
    auto* mapper = vtkPolyDataMapper::SafeDownCast(floor->GetMapper());
    mapper->Update();
    vtkNew<vtkPolyData> data;
    data->DeepCopy(mapper->GetInput());
    vtkNew<vtkFloatArray> height;
    height->SetName("height");
    for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
    {
      height->InsertNextValue(static_cast<float>(slope * data->GetPoint(i)[2]));
    }
    data->GetPointData()->AddArray(height);
    mapper->SetInputData(data);
    vtkFXGBufferPass::SetBump(floor, "height", 1.0);
  }
  return floor;
}

Setup MakeDOSetup(vtkRenderWindow* window, int samples)
{
  Setup s = MakeSetup(window);
  s.Pipeline->DirectionalOcclusionOn(); // (turns the AO off)
  vtkFXDirectionalOcclusionPass* dop = s.Pipeline->GetDirectionalOcclusionPass();
  dop->SetRadius(Radius);
  dop->SetNumberOfSamples(samples);
  dop->SetHalfResolution(false);
  s.Pipeline->GetCompositePass()->DebugOcclusionOn();
  return s;
}

// The three channels of an RGBA float texture finite and within [0, 1]; the
// depth alongside (A) finite and not negative.
int CheckAllInRange(vtkTextureObject* texture, int components, const char* what)
{
  const auto values = vtkFXTest::Download(texture, components);
  FX_CHECK(!values.empty(), what << ": read back");
  for (size_t i = 0; i < values.size(); ++i)
  {
    const bool depth = i % components == 3;
    FX_CHECK(std::isfinite(values[i]) && values[i] >= 0.0f && (depth || values[i] <= 1.0f),
      what << ": " << values[i] << " at texel " << i / components << ", component "
           << i % components);
  }
  return EXIT_SUCCESS;
}

// The pass's own output, packed (vtkFXEffectPass::Output::Packing 1): R
// holds two 12-bit channels, G the third, B the 12-bit octahedral normal,
// A the depth; every part finite and in range.
int CheckPackedInRange(vtkTextureObject* texture, const char* what)
{
  const auto values = vtkFXTest::Download(texture, 4);
  FX_CHECK(!values.empty(), what << ": read back");
  for (size_t i = 0; i < values.size(); i += 4)
  {
    const float r = values[i], g = values[i + 1], b = values[i + 2], a = values[i + 3];
    FX_CHECK(std::isfinite(r) && r >= 0.0f && r < 16777216.0f && r == std::floor(r) &&
        std::isfinite(g) && g >= 0.0f && g <= 1.0f && std::isfinite(b) && b >= 0.0f &&
        b < 16777216.0f && std::isfinite(a) && a >= 0.0f,
      what << ": packed texel " << i / 4 << " (" << r << ", " << g << ", " << b << ", " << a
           << ")");
  }
  return EXIT_SUCCESS;
}

bool OnFloorNearWall(const std::array<double, 4>& p)
{
  return p[3] > 0.0 && std::fabs(p[1]) < 1e-4 && std::fabs(p[0]) < 1.2 && p[2] < Radius;
}
}

// A bump on an actor drawn by vtkCompositePolyDataMapper2: VTK 9.1's
// composite mapper does not hand its vertex-attribute mappings to the
// helpers that draw its blocks, so the bump cannot reach the shader. It is
// refused (a warning; no bump), so nothing counts on it: no
// geometric-normal channel either. (It was accepted silently, the channel
// allocated, and the blocks drawn without a bump.)
int CheckBumpOnCompositeMapper(vtkRenderWindow* window)
{
  Setup s = MakeDOSetup(window, 15);
  vtkActor* floor = AddCrease(s);
  auto* plain = vtkPolyDataMapper::SafeDownCast(floor->GetMapper());
  plain->Update();
  vtkNew<vtkPolyData> data;
  data->DeepCopy(plain->GetInput());
  vtkNew<vtkFloatArray> height;
  height->SetName("height");
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
  {
    height->InsertNextValue(static_cast<float>(0.3 * data->GetPoint(i)[2]));
  }
  data->GetPointData()->AddArray(height);
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, data);
  vtkNew<vtkCompositePolyDataMapper2> composite;
  composite->SetInputDataObject(blocks);
  floor->SetMapper(composite);
  vtkFXGBufferPass::SetBump(floor, "height", 1.0);
  window->Render();
  const bool geometric =
    (s.Pipeline->GetGBufferChannels() & GB::ChannelBit(GB::GeometricNormal)) != 0;
  std::cout << "a bump on a composite mapper: has bump " << vtkFXGBufferPass::HasBump(floor)
            << ", geometric-normal channel " << geometric << std::endl;
  FX_CHECK(!vtkFXGBufferPass::HasBump(floor) && !vtkFXGBufferPass::PerturbsNormal(floor) &&
      !geometric,
    "a bump on a composite mapper was taken");
  return EXIT_SUCCESS;
}

int TestDirectionalOcclusion(int, char*[])
{
  auto window = vtkFXTest::MakeWindow(Width, Height);
  const double up[3] = { 0, 1, 0 };
  FX_CHECK(CheckBumpOnCompositeMapper(window) == EXIT_SUCCESS, "bump on a composite mapper");

  // 1 and 2: the crease without a bump, 63 samples, blurred.
  std::array<double, 3> meanChannels = { 0, 0, 0 };
  {
    Setup s = MakeDOSetup(window, 63);
    BuildCrease(s, 0.0);
    window->Render();
    vtkFXDirectionalOcclusionPass* dop = s.Pipeline->GetDirectionalOcclusionPass();
    FX_CHECK(dop->GetEffectiveNumberOfSamples() == 63, "63 samples used");
    FX_CHECK(!(s.Pipeline->GetGBufferChannels() & GB::ChannelBit(GB::GeometricNormal)),
      "no bump: no geometric-normal channel");
    if (CheckPackedInRange(dop->GetOutputTexture(), "raw channels") != EXIT_SUCCESS)
    {
      return EXIT_FAILURE;
    }
    vtkTextureObject* blurred = s.Pipeline->GetDirectionalOcclusionBlurPass()->GetOutputTexture();
    std::vector<float> channel[3];
    for (int k = 0; k < 3; ++k)
    {
      channel[k] = OcclusionAtPixels(blurred, k);
    }
    const auto world = WorldPositions(s.Renderer, s.Pipeline->GetGBufferPass());
    const auto shown = Grab(window);
    double basis[3][3];
    WorldBasis(s.Renderer, up, basis);
    // The channel whose direction leans most towards the wall (-z), and
    // the one leaning most away.
    int toward = 0, away = 0;
    for (int k = 1; k < 3; ++k)
    {
      toward = basis[k][2] < basis[toward][2] ? k : toward;
      away = basis[k][2] > basis[away][2] ? k : away;
    }
    // Exact channels tabulated in (h/R)^(1/3), bins as TestSSAO's.
    const int table = 64;
    std::vector<std::array<double, 3>> exact(table + 1);
    for (int i = 0; i <= table; ++i)
    {
      const double x = static_cast<double>(i) / table;
      exact[i] = ExactChannels(x * x * x * Radius, basis);
    }
    double binDO[10][4] = {}, binExact[10][4] = {};
    int binCount[10] = {};
    double worstResolve = 0.0;
    for (size_t i = 0; i < world.size(); ++i)
    {
      const auto& p = world[i];
      if (!OnFloorNearWall(p))
      {
        continue;
      }
      const double x = std::cbrt(p[2] / Radius) * table;
      const int j = std::min(table - 1, static_cast<int>(x));
      const int bin = std::min(9, static_cast<int>(x / table * 10));
      double mean = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        binDO[bin][k] += channel[k][i];
        binExact[bin][k] += exact[j][k] + (x - j) * (exact[j + 1][k] - exact[j][k]);
        mean += channel[k][i] / 3.0;
      }
      binDO[bin][3] += mean;
      binExact[bin][3] += vtkFXTest::CreaseOcclusionBinary(p[2], Radius);
      ++binCount[bin];
      worstResolve = std::max(worstResolve, std::fabs(shown[i] - 255.0 * mean));
      for (int k = 0; k < 3; ++k)
      {
        meanChannels[k] += channel[k][i];
      }
    }
    double worstChannelBin = 0.0, worstMeanBin = 0.0;
    int bins = 0;
    for (int b = 4; b < 10; ++b) // h >= 0.064 R: every pixel resolves the wall
    {
      if (binCount[b] < 20)
      {
        continue;
      }
      ++bins;
      std::cout << "  (h/R)^(1/3) in [" << b / 10.0 << ", " << (b + 1) / 10.0 << "): channels";
      for (int k = 0; k < 4; ++k)
      {
        const double got = binDO[b][k] / binCount[b], want = binExact[b][k] / binCount[b];
        std::cout << (k == 3 ? ", mean " : " ") << got << " (exact " << want << ")";
        (k < 3 ? worstChannelBin : worstMeanBin) =
          std::max(k < 3 ? worstChannelBin : worstMeanBin, std::fabs(got - want));
      }
      std::cout << " over " << binCount[b] << " pixels" << std::endl;
      if (b < 8) // h < 0.51 R: the wall is within reach of the leaning lobe
      {
        FX_CHECK(binDO[b][toward] < binDO[b][away] - 0.1 * binCount[b],
          "the channel facing the wall is darker than the one facing away (bin " << b << ")");
      }
    }
    std::cout << "crease: worst bin " << worstChannelBin << " (channels), " << worstMeanBin
              << " (their mean against the closed form); composite against the mean: worst "
              << worstResolve << " levels" << std::endl;
    FX_CHECK(bins >= 4, "bands near the crease");
    // The mean is vtkFXSSAOPass's hemisphere estimate, held by TestSSAO to
    // 0.03 per bin at 64 samples; a channel takes a third of the samples'
    // weight, so its noise is sqrt(3) times that: 0.052.
    FX_CHECK(worstMeanBin <= 0.03, "the channels' mean follows the crease's closed form");
    FX_CHECK(worstChannelBin <= 0.052, "each channel follows its exact lobe visibility");
    // 8-bit rounding (0.5), plus 0.13 for the float arithmetic of the two
    // sides (measured: 0.5 at most).
    FX_CHECK(worstResolve <= 0.5 + 0.13, "without a bump the composite shows the channels' mean");

    // Without a bump directional occlusion shows what plain AO shows: the
    // pipeline's vtkFXSSAOPass (hemisphere, the same samples, radius,
    // resolution and blur) on the same crease, composited, band by band.
    // Each is held to the closed form within 0.03 per band (above; TestSSAO
    // for plain AO at 64 samples), so the two within 0.06.
    Setup plain = MakeSetup(window);
    BuildCrease(plain, 0.0);
    vtkFXSSAOPass* ssao = plain.Pipeline->GetSSAOPass();
    ssao->SetMethod(vtkFXSSAOPass::Hemisphere);
    ssao->SetNumberOfSamples(63);
    ssao->SetRadius(Radius);
    ssao->SetHalfResolution(false);
    plain.Pipeline->GetCompositePass()->DebugOcclusionOn();
    window->Render();
    const auto shownPlain = Grab(window);
    double binShown[10][2] = {};
    int binPixels[10] = {};
    for (size_t i = 0; i < world.size() && i < shownPlain.size(); ++i)
    {
      if (!OnFloorNearWall(world[i]))
      {
        continue;
      }
      const int bin = std::min(9, static_cast<int>(std::cbrt(world[i][2] / Radius) * 10));
      binShown[bin][0] += shown[i] / 255.0;
      binShown[bin][1] += shownPlain[i] / 255.0;
      ++binPixels[bin];
    }
    double worstPlain = 0.0;
    for (int b = 4; b < 10; ++b)
    {
      if (binPixels[b] >= 20)
      {
        worstPlain =
          std::max(worstPlain, std::fabs(binShown[b][0] - binShown[b][1]) / binPixels[b]);
      }
    }
    std::cout << "crease without a bump: directional against plain AO, worst band " << worstPlain
              << std::endl;
    FX_CHECK(worstPlain <= 0.06, "without a bump directional occlusion differs from plain AO by "
        << worstPlain);
  }

  // 3. A floor bumped by ramps of slope +-0.5, by a scalar bump and by
  // VTK's normal texture: shading normals and their resolve.
  for (bool normalTexture : { false, true })
  for (double slope : { 0.5, -0.5 })
  {
    Setup s = MakeDOSetup(window, 63);
    BuildCrease(s, slope, normalTexture);
    window->Render();
    FX_CHECK(s.Pipeline->GetGBufferChannels() & GB::ChannelBit(GB::GeometricNormal),
      "a bump: the geometric-normal channel is allocated");
    vtkFXGBufferPass* gbuffer = s.Pipeline->GetGBufferPass();
    const auto shading = vtkFXTest::Download(gbuffer->GetChannelTexture(GB::Normal), 2);
    const auto geometric = vtkFXTest::Download(gbuffer->GetChannelTexture(GB::GeometricNormal), 2);
    vtkTextureObject* blurred = s.Pipeline->GetDirectionalOcclusionBlurPass()->GetOutputTexture();
    std::vector<float> channel[3];
    for (int k = 0; k < 3; ++k)
    {
      channel[k] = OcclusionAtPixels(blurred, k);
    }
    const auto world = WorldPositions(s.Renderer, gbuffer);
    const auto shown = Grab(window);
    vtkMatrix4x4* view = s.Renderer->GetActiveCamera()->GetViewTransformMatrix();
    double expected[3] = { 0.0, 1.0, -slope }, expectedView[3] = { 0, 0, 0 }, upView[3] = { 0, 0, 0 };
    vtkMath::Normalize(expected);
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        expectedView[r] += view->GetElement(r, c) * expected[c];
        upView[r] += view->GetElement(r, c) * up[c];
      }
    }
    double basis[3][3];
    WorldBasis(s.Renderer, up, basis);
    double c[3];
    Weights(expected, basis, c);
    double worstAngle = 0.0, worstGeometric = 0.0, worstResolve = 0.0, resolvedSum = 0.0,
           meanSum = 0.0;
    int n = 0;
    for (size_t i = 0; i < world.size(); ++i)
    {
      // (inner pixels: derivatives of the quads at the plane's edge mix in
      // the wall)
      const auto& p = world[i];
      if (!OnFloorNearWall(p) || p[2] < 0.05)
      {
        continue;
      }
      double ns[3], ng[3];
      vtkFXTest::DecodeNormal(shading[2 * i], shading[2 * i + 1], ns);
      vtkFXTest::DecodeNormal(geometric[2 * i], geometric[2 * i + 1], ng);
      worstAngle = std::max(worstAngle, vtkFXTest::Angle(ns, expectedView));
      worstGeometric = std::max(worstGeometric, vtkFXTest::Angle(ng, upView));
      const double resolved = c[0] * channel[0][i] + c[1] * channel[1][i] + c[2] * channel[2][i];
      worstResolve = std::max(worstResolve, std::fabs(shown[i] - 255.0 * resolved));
      resolvedSum += resolved;
      meanSum += (channel[0][i] + channel[1][i] + channel[2][i]) / 3.0;
      ++n;
    }
    std::cout << (normalTexture ? "normal-texture ramp " : "ramp ") << slope << ": " << n
              << " floor pixels, shading normal off by "
              << worstAngle << " rad at most (geometric " << worstGeometric
              << "), weights " << c[0] << " " << c[1] << " " << c[2] << ", resolved mean "
              << resolvedSum / n << " against the channels' mean " << meanSum / n
              << ", composite off by " << worstResolve << " levels" << std::endl;
    FX_CHECK(n > 500, "floor pixels near the wall");
    // Octahedral normals in two half floats: 1e-3 rad (vtkFXNormalCoding);
    // an 8-bit normal texture adds up to half a level per component, 1/255
    // after the map to [-1, 1]: 5.5e-3 rad for two components (measured
    // 3.9e-3).
    FX_CHECK(worstAngle <= (normalTexture ? 2e-3 + 5.5e-3 : 2e-3),
      "the shading normal is the ramp's normal");
    FX_CHECK(worstGeometric <= 2e-3, "the geometric normal is the floor's");
    FX_CHECK(worstResolve <= 0.5 + 0.13, "the composite shows the weighted channels");
    if (slope > 0.0)
    {
      FX_CHECK(resolvedSum / n < meanSum / n - 0.02, "turned to the wall: darker than the mean");
    }
    else
    {
      FX_CHECK(resolvedSum / n > meanSum / n + 0.02, "turned away: lighter than the mean");
    }
  }

  // 4. What is allocated; a prop without a bump beside one with it.
  for (bool normalTexture : { true, false }) // the bump's case goes on below
  {
    Setup s = MakeDOSetup(window, 15);
    vtkActor* floor = BuildCrease(s, 0.5, normalTexture);
    window->Render();
    vtkFXGBufferPass* gbuffer = s.Pipeline->GetGBufferPass();
    const auto shading = vtkFXTest::Download(gbuffer->GetChannelTexture(GB::Normal), 2);
    const auto geometric = vtkFXTest::Download(gbuffer->GetChannelTexture(GB::GeometricNormal), 2);
    const auto world = WorldPositions(s.Renderer, gbuffer);
    int wallPixels = 0, floorPixels = 0;
    for (size_t i = 0; i < world.size(); ++i)
    {
      const auto& p = world[i];
      if (p[3] > 0.0 && std::fabs(p[2]) < 1e-4 && p[1] > 0.05)
      {
        FX_CHECK(shading[2 * i] == geometric[2 * i] && shading[2 * i + 1] == geometric[2 * i + 1],
          "the wall (no bump) keeps its normal, pixel " << i);
        ++wallPixels;
      }
      else if (p[3] > 0.0 && std::fabs(p[1]) < 1e-4 && p[2] > 0.05)
      {
        floorPixels += shading[2 * i] != geometric[2 * i] || shading[2 * i + 1] != geometric[2 * i + 1];
      }
    }
    FX_CHECK(wallPixels > 1000 && floorPixels > 1000, "both props seen, the floor bumped");
    std::cout << (normalTexture ? "normal texture" : "bump") << " on the floor only: " << wallPixels
              << " wall pixels keep their normal, " << floorPixels << " floor pixels tilted"
              << std::endl;
    if (normalTexture)
    {
      continue;
    }
    // Ambient occlusion instead samples around the geometric normal too.
    s.Pipeline->AmbientOcclusionOn();
    FX_CHECK(!s.Pipeline->GetDirectionalOcclusion(), "ambient occlusion replaced the directional");
    window->Render();
    FX_CHECK(s.Pipeline->GetGBufferChannels() & GB::ChannelBit(GB::GeometricNormal),
      "SSAO with a bumped prop reads the geometric normals");
    // Neither occlusion effect: released.
    s.Pipeline->AmbientOcclusionOff();
    window->Render();
    FX_CHECK(!(s.Pipeline->GetGBufferChannels() & GB::ChannelBit(GB::GeometricNormal)),
      "no occlusion effect: the channel is released");
    // Directional occlusion again, the bump removed: none either.
    s.Pipeline->DirectionalOcclusionOn();
    vtkFXGBufferPass::SetBump(floor, nullptr, 0.0);
    window->Render();
    FX_CHECK(!(s.Pipeline->GetGBufferChannels() & GB::ChannelBit(GB::GeometricNormal)),
      "no bump left: the channel is released");
  }

  // 5. The bumped crease (scalar bump and normal texture) under extreme
  // scales, offsets and projections: channels finite and in range, normal
  // codes valid, and the occlusion view within 40 dB of the unmoved scene's
  // (in the same projection), as TestSSAOScale holds plain AO.
  struct Case
  {
    const char* Name;
    double Scale, Offset;
    bool Parallel;
    double NearRatio;
  };
  const Case cases[] = { { "scale 1e-6", 1e-6, 0.0, false, 0.0 }, { "scale 1e6", 1e6, 0.0, false, 0.0 },
    { "translated 1e6", 1.0, 1e6, false, 0.0 }, { "parallel", 1.0, 0.0, true, 0.0 },
    { "near/far 1e-6", 1.0, 0.0, false, 1e-6 } };
  for (int method : { vtkFXSSAOPass::Hemisphere, vtkFXSSAOPass::Horizon })
  for (bool normalTexture : { false, true })
  {
  // The unmoved crease's occlusion view, in perspective and parallel.
  std::vector<unsigned char> unmoved[2];
  unsigned char background[3] = { 0, 0, 0 };
  const auto renderCrease = [&](const Case& c) {
    Setup s = MakeDOSetup(window, 15);
    s.Pipeline->GetDirectionalOcclusionPass()->SetMethod(method);
    s.Pipeline->GetDirectionalOcclusionPass()->SetRadius(0.0); // a fraction of the bounds
    s.Pipeline->GetDirectionalOcclusionPass()->SetHalfResolution(true);
    BuildCrease(s, 0.5, normalTexture);
    vtkFXTest::MoveScene(s.Renderer, c.Scale, c.Offset, c.Parallel, c.NearRatio);
    // A scalar bump's height is in world units: scaled with the scene, so
    // that the scene is the same one, smaller or larger.
    vtkActorCollection* actors = s.Renderer->GetActors();
    actors->InitTraversal();
    while (vtkActor* actor = actors->GetNextActor())
    {
      vtkInformation* keys = actor->GetPropertyKeys();
      if (keys && keys->Has(GB::BUMP_SCALE()))
      {
        keys->Set(GB::BUMP_SCALE(), keys->Get(GB::BUMP_SCALE()) * c.Scale);
      }
    }
    window->Render();
    vtkFXScenes::BackgroundBytes(s.Renderer, background);
    return s;
  };
  for (bool parallel : { false, true })
  {
    renderCrease({ "unmoved", 1.0, 0.0, parallel, 0.0 });
    unmoved[parallel ? 1 : 0] = vtkFXScenes::Capture(window);
  }
  for (const Case& c : cases)
  {
    Setup s = renderCrease(c);
    const double psnr =
      vtkFXScenes::PSNR(unmoved[c.Parallel ? 1 : 0], vtkFXScenes::Capture(window), background);
    vtkFXGBufferPass* gbuffer = s.Pipeline->GetGBufferPass();
    if (CheckPackedInRange(s.Pipeline->GetDirectionalOcclusionPass()->GetOutputTexture(), c.Name) !=
        EXIT_SUCCESS ||
      CheckAllInRange(s.Pipeline->GetDirectionalOcclusionBlurPass()->GetOutputTexture(), 4, c.Name) !=
        EXIT_SUCCESS)
    {
      return EXIT_FAILURE;
    }
    int surface = 0;
    for (int channel : { GB::Normal, GB::GeometricNormal })
    {
      const auto normals = vtkFXTest::Download(gbuffer->GetChannelTexture(channel), 2);
      for (size_t i = 0; i < normals.size(); i += 2)
      {
        // (4, 4): unlit; anything else an octahedral code, within the
        // square [-1, 1]^2 (the upper hemisphere in its diamond, the lower
        // in its corners)
        const float x = normals[i], y = normals[i + 1];
        if (x == 4.0f && y == 4.0f)
        {
          continue;
        }
        FX_CHECK(std::isfinite(x) && std::isfinite(y) && std::fabs(x) <= 1.0f && std::fabs(y) <= 1.0f,
          c.Name << ": " << GB::GetChannelName(channel) << " code (" << x << ", " << y
                 << ") at pixel " << i / 2);
        surface += channel == GB::Normal;
      }
    }
    std::cout << c.Name << (normalTexture ? ", normal texture" : ", scalar bump")
              << (method == vtkFXSSAOPass::Horizon ? ", horizon" : ", hemisphere") << ": "
              << surface << " surface pixels, channels in range, occlusion view " << psnr
              << " dB from the unmoved one" << std::endl;
    FX_CHECK(surface > 1000, c.Name << ": the crease is seen");
    FX_CHECK(psnr >= 40.0, c.Name << ": the occlusion moved with the scene (" << psnr << " dB)");
  }
  }

  // 6. Diffuse bleeding.
  {
    Setup s = MakeDOSetup(window, 63);
    BuildCrease(s, 0.0);
    vtkFXDirectionalOcclusionPass* dop = s.Pipeline->GetDirectionalOcclusionPass();
    window->Render();
    FX_CHECK(dop->GetBleeding() == 0.0 && !dop->GetOutputTexture("bleeding") &&
        vtkFXTest::Passes(s.Pipeline).find("bleed") == std::string::npos,
      "bleeding is off by default: no texture, no blur");
    const double rho[3] = { 0.8, 0.3, 0.1 };
    s.Renderer->GetActors()->GetLastActor()->GetProperty()->SetColor(rho[0], rho[1], rho[2]);
    vtkNew<vtkLight> sun; // from (0, 1, 1) towards the crease: n . l = 1/sqrt 2 on both planes
    sun->SetLightTypeToSceneLight();
    sun->SetPosition(0, 1, 1);
    sun->SetFocalPoint(0, 0, 0);
    s.Renderer->RemoveAllLights();
    s.Renderer->AddLight(sun);
    dop->SetBleeding(1.0);
    window->Render();
    FX_CHECK(vtkFXTest::Passes(s.Pipeline).find("do-bleed-blur") != std::string::npos,
      "the bleeding is blurred: " << vtkFXTest::Passes(s.Pipeline));
    vtkTextureObject* bled = s.Pipeline->GetEffect("do-bleed-blur")->GetOutputTexture();
    FX_CHECK(bled, "blurred bleeding");
    std::vector<float> bleed[3];
    for (int k = 0; k < 3; ++k)
    {
      bleed[k] = OcclusionAtPixels(bled, k);
    }
    const auto world = WorldPositions(s.Renderer, s.Pipeline->GetGBufferPass());
    const double direct = std::sqrt(0.5);
    double binGot[10][3] = {}, binWant[10] = {};
    int binCount[10] = {};
    double far = 0.0;
    for (size_t i = 0; i < world.size(); ++i)
    {
      const auto& p = world[i];
      for (int k = 0; k < 3; ++k)
      {
        FX_CHECK(std::isfinite(bleed[k][i]) && bleed[k][i] >= 0.0f, "bleeding at pixel " << i);
      }
      if (p[3] > 0.0 && std::fabs(p[1]) < 1e-4 && p[2] > 2.5 * Radius)
      {
        far = std::max(far, static_cast<double>(bleed[0][i]));
      }
      if (!OnFloorNearWall(p))
      {
        continue;
      }
      const int bin = std::min(9, static_cast<int>(std::cbrt(p[2] / Radius) * 10));
      for (int k = 0; k < 3; ++k)
      {
        binGot[bin][k] += bleed[k][i] / (rho[k] * direct);
      }
      binWant[bin] += 1.0 - vtkFXTest::CreaseOcclusionBinary(p[2], Radius);
      ++binCount[bin];
    }
    double worst = 0.0;
    int bins = 0;
    for (int b = 4; b < 10; ++b)
    {
      if (binCount[b] < 20)
      {
        continue;
      }
      ++bins;
      const double want = binWant[b] / binCount[b];
      std::cout << "  bleeding / (rho D) in bin " << b << ": ";
      for (int k = 0; k < 3; ++k)
      {
        const double got = binGot[b][k] / binCount[b];
        std::cout << got << " ";
        worst = std::max(worst, std::fabs(got - want));
      }
      std::cout << "(1 - A: " << want << ")" << std::endl;
    }
    std::cout << "bleeding: worst bin " << worst << ", largest far from the wall " << far
              << std::endl;
    FX_CHECK(bins >= 4, "bands near the crease");
    // The blocked fraction is the estimate of 1 - A that the channels' mean
    // is held to (0.03 per bin); the wall's albedo in 8 bits is off by at
    // most half a level, 0.002, which relative to its smallest component
    // (0.1) is 2% of a value below 1 - A <= 0.44 here: 0.01 more (measured
    // worst 0.019 in all).
    FX_CHECK(worst <= 0.03 + 0.01, "the floor receives the wall's light times 1 - A(h)");
    FX_CHECK(far <= 1e-3, "no bleeding beyond R from the wall");

    // A PBR wall bounces nothing: the G-buffer holds VTK's lit colour for
    // it, not its albedo (lit again, the wall's colour bounced squared into
    // the light: 0.139 on the floor).
    vtkProperty* wall = s.Renderer->GetActors()->GetLastActor()->GetProperty();
    wall->SetInterpolationToPBR();
    window->Render();
    const auto pbrBleed =
      OcclusionAtPixels(s.Pipeline->GetEffect("do-bleed-blur")->GetOutputTexture(), 0);
    // (from 0.1 R on: nearer, a texel of the reduced resolution may hold
    // the wall, which receives the floor's light)
    double pbrLargest = 0.0;
    for (size_t i = 0; i < world.size() && i < pbrBleed.size(); ++i)
    {
      if (OnFloorNearWall(world[i]) && world[i][2] >= 0.1 * Radius)
      {
        pbrLargest = std::max(pbrLargest, static_cast<double>(pbrBleed[i]));
      }
    }
    wall->SetInterpolationToGouraud();
    std::cout << "bleeding off a PBR wall: largest on the floor " << pbrLargest << std::endl;
    FX_CHECK(pbrLargest <= 1e-3, "a PBR wall bounces no light");

    // No light bleeds across a silhouette: a white plate 1 unit above the
    // floor and 1.2 to 1.8 from the wall (nothing within R of its top
    // side) hides part of the lit band. Its pixels, which bounce nothing,
    // must not change with bleeding on (read bilinearly at half
    // resolution, the floor's light behind its edge reached a pixel-wide
    // fringe: 55 of its pixels, up to 13 levels of red).
    // (grey floor and plate: white ones saturate before any light is added)
    const double po[3] = { -0.5, 1.0, 1.2 }, p1[3] = { 0.5, 1.0, 1.2 }, p2[3] = { -0.5, 1.0, 1.8 };
    auto plate = Plane(po, p1, p2);
    plate->GetProperty()->SetColor(0.4, 0.4, 0.4);
    vtkActor::SafeDownCast(s.Renderer->GetActors()->GetItemAsObject(0))
      ->GetProperty()
      ->SetColor(0.4, 0.4, 0.4);
    s.Renderer->AddActor(plate);
    s.Renderer->ResetCameraClippingRange();
    // The lit image, at the pipeline's resolution (half).
    s.Pipeline->GetCompositePass()->DebugOcclusionOff();
    dop->SetHalfResolution(true);
    window->Render();
    const auto withBleeding = vtkFXScenes::Capture(window);
    const auto plateWorld = WorldPositions(s.Renderer, s.Pipeline->GetGBufferPass());
    dop->SetBleeding(0.0);
    window->Render();
    const auto withoutBleeding = vtkFXScenes::Capture(window);
    int platePixels = 0, changed = 0, largest = 0, floorChanged = 0;
    for (size_t i = 0; i < plateWorld.size(); ++i)
    {
      const int difference = std::abs(int(withBleeding[3 * i]) - int(withoutBleeding[3 * i]));
      if (plateWorld[i][3] > 0.0 && std::fabs(plateWorld[i][1] - 1.0) < 1e-3)
      {
        ++platePixels;
        changed += difference > 1 ? 1 : 0;
        largest = std::max(largest, difference);
      }
      else
      {
        floorChanged += difference > 1 ? 1 : 0;
      }
    }
    std::cout << "plate over the lit band: " << platePixels << " pixels, " << changed
              << " changed by bleeding (at most " << largest << " levels of red); "
              << floorChanged << " pixels of the crease changed" << std::endl;
    FX_CHECK(platePixels > 1000 && floorChanged > 1000, "the plate hides part of the lit band");
    FX_CHECK(changed == 0, "bleeding crossed the plate's silhouette");
    // Off again: the texture goes.
    FX_CHECK(!dop->GetOutputTexture("bleeding"), "bleeding off frees its texture");
  }

  // 7. The horizon method: each channel is the visible part of the
  // (unclamped) cosine around its basis vector over the geometric
  // hemisphere, and the resolve weighs them by b_k . n_s.
  // - Without a bump the weights are 1/3 and the cosines add up to the
  //   normal's: the composite shows what plain horizon-based AO shows (the
  //   same steps, radius, resolution and blur), up to the per-lobe
  //   normalisation and the blur's guide; measured band by band (0.012 at
  //   most), held to 0.03.
  // - Beyond R from the wall nothing occludes: every lobe is wholly
  //   visible and the resolve is 1 for any shading normal, up to the
  //   floor's own texels, found as horizons on its tangent line only
  //   within the normal's 16-bit encoding and the fast acos (0.007 rad).
  //   Plain horizon AO reads the open floor 2 or 3 levels under 1 for
  //   that; the lobes, weighted near that line where the cosine is not,
  //   up to 5 under a tilted shading normal (measured): held to 6.
  // - A ramp turned to the wall reads darker than without the bump, one
  //   turned away lighter.
  {
    auto composite = [&](double slope, bool directional, std::vector<std::array<double, 4>>& world) {
      Setup s = directional ? MakeDOSetup(window, 32) : MakeSetup(window);
      BuildCrease(s, slope);
      if (directional)
      {
        vtkFXDirectionalOcclusionPass* dop = s.Pipeline->GetDirectionalOcclusionPass();
        dop->SetMethod(vtkFXSSAOPass::Horizon);
        dop->SetNumberOfSamples(32);
      }
      else
      {
        vtkFXSSAOPass* ssao = s.Pipeline->GetSSAOPass();
        ssao->SetMethod(vtkFXSSAOPass::Horizon);
        ssao->SetNumberOfSamples(32);
        ssao->SetRadius(Radius);
        ssao->SetHalfResolution(false);
        s.Pipeline->GetCompositePass()->DebugOcclusionOn();
      }
      window->Render();
      world = WorldPositions(s.Renderer, s.Pipeline->GetGBufferPass());
      return Grab(window);
    };
    std::vector<std::array<double, 4>> world;
    const auto plain = composite(0.0, false, world);
    const auto flat = composite(0.0, true, world);
    const auto toward = composite(0.5, true, world);
    const auto away = composite(-0.5, true, world);
    double bins[10][4] = {};
    int binPixels[10] = {};
    int farPixels = 0, farWorst = 0, farPlain = 0;
    for (size_t i = 0; i < world.size() && i < plain.size(); ++i)
    {
      const auto& p = world[i];
      if (p[3] > 0.0 && std::fabs(p[1]) < 1e-4 && std::fabs(p[0]) < 1.2 && p[2] > 1.2 * Radius &&
        p[2] < 3.0)
      {
        ++farPixels;
        farPlain = std::max(farPlain, 255 - static_cast<int>(plain[i]));
        for (const auto* image : { &flat, &toward, &away })
        {
          farWorst = std::max(farWorst, 255 - static_cast<int>((*image)[i]));
        }
      }
      if (!OnFloorNearWall(p) || p[2] < 0.05)
      {
        continue;
      }
      const int bin = std::min(9, static_cast<int>(std::cbrt(p[2] / Radius) * 10));
      bins[bin][0] += plain[i] / 255.0;
      bins[bin][1] += flat[i] / 255.0;
      bins[bin][2] += toward[i] / 255.0;
      bins[bin][3] += away[i] / 255.0;
      ++binPixels[bin];
    }
    double worstPlain = 0.0, towardSum = 0.0, awaySum = 0.0, flatSum = 0.0;
    int used = 0;
    for (int b = 4; b < 10; ++b)
    {
      if (binPixels[b] < 20)
      {
        continue;
      }
      worstPlain = std::max(worstPlain, std::fabs(bins[b][0] - bins[b][1]) / binPixels[b]);
      flatSum += bins[b][1];
      towardSum += bins[b][2];
      awaySum += bins[b][3];
      used += binPixels[b];
    }
    std::cout << "horizon method: against plain horizon AO worst band " << worstPlain
              << "; near the wall, no bump " << flatSum / used << ", turned to the wall "
              << towardSum / used << ", away " << awaySum / used << "; beyond R " << farWorst
              << " levels under 1 over " << farPixels << " pixels (plain AO " << farPlain << ")"
              << std::endl;
    FX_CHECK(used > 500 && farPixels > 500, "floor pixels");
    FX_CHECK(worstPlain <= 0.03, "horizon DO without a bump differs from plain AO by " << worstPlain);
    FX_CHECK(farWorst <= 6, "an open floor reads " << farWorst << " levels under 1");
    FX_CHECK(towardSum < flatSum - 0.02 * used && awaySum > flatSum + 0.02 * used,
      "the ramps' resolve does not follow their normals");
  }
  return EXIT_SUCCESS;
}
