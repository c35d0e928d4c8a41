// vtkFXScenes::DetailScore (vtkfx-bench ao's detail column) on image pairs
// whose score is known:
// - an image against itself, against an affine copy: 1; against its
//   negative: -1; a constant image: 0 (no fine band);
// - white noise against its own Gaussian blur (sigma 3, the score's own
//   split): the fine bands are (1 - G) N and (G - G^2) N, whose correlation
//   for white noise is the ratio of spectral integrals
//     Int (1-G)(G-G^2) / sqrt(Int (1-G)^2 Int (G-G^2)^2),
//   G(w) = exp(-sigma^2 |w|^2 / 2) over [-pi, pi]^2, about 0.156: a blurred
//   image keeps little detail;
// - background pixels (negative in the reference) never count, whatever
//   the image holds there, nor geometry pixels within 8 px of them.
#include "vtkFXScenes.h"
#include "vtkFXTestUtilities.h"

namespace
{
const int W = 240, H = 200;

std::vector<float> Noise(unsigned int seed)
{
  std::vector<float> v(static_cast<size_t>(W) * H);
  for (float& x : v)
  {
    seed = seed * 1664525u + 1013904223u;
    x = static_cast<float>((seed >> 8) & 0xffff) / 65535.0f;
  }
  return v;
}

// Separable Gaussian (sigma 3, radius 9), edges clamped.
std::vector<float> Blur(const std::vector<float>& in)
{
  std::vector<double> k(19);
  double sum = 0.0;
  for (int i = -9; i <= 9; ++i)
  {
    sum += k[i + 9] = std::exp(-i * i / 18.0);
  }
  std::vector<float> tmp(in.size()), out(in.size());
  for (int pass = 0; pass < 2; ++pass)
  {
    const std::vector<float>& src = pass ? tmp : in;
    std::vector<float>& dst = pass ? out : tmp;
    for (int y = 0; y < H; ++y)
    {
      for (int x = 0; x < W; ++x)
      {
        double acc = 0.0;
        for (int i = -9; i <= 9; ++i)
        {
          const int xx = pass ? x : std::min(W - 1, std::max(0, x + i));
          const int yy = pass ? std::min(H - 1, std::max(0, y + i)) : y;
          acc += k[i + 9] * src[static_cast<size_t>(yy) * W + xx];
        }
        dst[static_cast<size_t>(y) * W + x] = static_cast<float>(acc / sum);
      }
    }
  }
  return out;
}

double SpectralExpectation()
{
  const int n = 400;
  const double pi = 3.14159265358979323846, s2 = 9.0;
  double ab = 0.0, aa = 0.0, bb = 0.0;
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      const double wx = -pi + 2 * pi * (i + 0.5) / n, wy = -pi + 2 * pi * (j + 0.5) / n;
      const double g = std::exp(-s2 * (wx * wx + wy * wy) / 2);
      const double a = 1 - g, b = g - g * g;
      ab += a * b;
      aa += a * a;
      bb += b * b;
    }
  }
  return ab / std::sqrt(aa * bb);
}
}

int TestDetailScore(int, char*[])
{
  const auto noise = Noise(7u);
  using vtkFXScenes::DetailScore;
  FX_CHECK(std::fabs(DetailScore(noise, noise, W, H) - 1.0) < 1e-9, "itself: 1");
  std::vector<float> affine(noise), negative(noise), constant(noise.size(), 0.5f);
  for (size_t i = 0; i < noise.size(); ++i)
  {
    affine[i] = 0.3f * noise[i] + 0.2f;
    negative[i] = 1.0f - noise[i];
  }
  FX_CHECK(std::fabs(DetailScore(affine, noise, W, H) - 1.0) < 1e-6, "scale-free: 1");
  FX_CHECK(std::fabs(DetailScore(negative, noise, W, H) + 1.0) < 1e-6, "inverted: -1");
  FX_CHECK(DetailScore(constant, noise, W, H) == 0.0, "no fine band: 0");

  const double expected = SpectralExpectation();
  const double blurred = DetailScore(Blur(noise), noise, W, H);
  std::cout << "white noise against its blur: " << blurred << ", spectral expectation "
            << expected << std::endl;
  // 224 x 184 = 41216 interior pixels; the reference's fine band is nearly
  // white, so the correlation's standard error is about 1/sqrt(41216) =
  // 0.005: three of them.
  FX_CHECK(std::fabs(blurred - expected) < 0.015, "a blurred image keeps little detail");

  // Left half background: what the image holds there does not count.
  std::vector<float> reference(noise), image(noise);
  for (int y = 0; y < H; ++y)
  {
    for (int x = 0; x < W / 2; ++x)
    {
      reference[static_cast<size_t>(y) * W + x] = -1.0f;
      image[static_cast<size_t>(y) * W + x] = (x * 7 + y * 13) % 5 * 0.25f;
    }
  }
  FX_CHECK(std::fabs(DetailScore(image, reference, W, H) - 1.0) < 1e-9,
    "background pixels are left out");
  // Geometry pixels within 8 px of the background are left out too: the
  // image brighter by 1 along the column next to the background (x = W/2)
  // changes only what the blur (radius 9) carries past the margin
  // (measured 0.999995); the same column 20 px inside the geometry is
  // counted (0.954).
  const auto withColumn = [&](int column) {
    std::vector<float> shifted(noise);
    for (int y = 0; y < H; ++y)
    {
      shifted[static_cast<size_t>(y) * W + column] += 1.0f;
    }
    return DetailScore(shifted, reference, W, H);
  };
  const double atEdge = withColumn(W / 2), inside = withColumn(W / 2 + 20);
  std::cout << "a column 1 brighter next to the background: " << atEdge << "; 20 px inside: "
            << inside << std::endl;
  FX_CHECK(atEdge > 0.995 && inside < 0.99, "the 8 px margin along the silhouette");
  return EXIT_SUCCESS;
}
