// vtkfx-compare: PSNR (dB) and largest channel difference between two
// images of the same size, e.g. a vtkFX render and a plain VTK render.
//
//   vtkfx-compare A.png B.png [--min-psnr DB]
// Exits 1 when the images differ in size or the PSNR is below --min-psnr.
#include "vtkFXArguments.h"
#include "vtkFXScenes.h"

#include "vtkNew.h"

#include <cstdlib>
#include <iostream>
#include <string>


int main(int argc, char* argv[])
{
  if (argc != 3 && !(argc == 5 && std::string(argv[3]) == "--min-psnr"))
  {
    std::cerr << "usage: vtkfx-compare A.png B.png [--min-psnr DB]\n";
    return 2;
  }
  double minimum = 0.0;
  if (argc == 5 && !vtkFXArguments::ParseInRange(argv[4], -1e6, 1e6, minimum))
  {
    std::cerr << "vtkfx-compare: bad --min-psnr '" << argv[4] << "' (a number of dB)\n";
    return 2;
  }
  std::vector<unsigned char> a, b;
  int sa[2], sb[2];
  for (int i = 1; i <= 2; ++i)
  {
    if (!vtkFXScenes::LoadRGB(argv[i], i == 1 ? a : b, i == 1 ? sa : sb))
    {
      std::cerr << "vtkfx-compare: cannot read '" << argv[i] << "' as an 8-bit PNG image\n";
      return 2;
    }
  }
  if (sa[0] != sb[0] || sa[1] != sb[1])
  {
    std::cerr << "vtkfx-compare: sizes differ (" << sa[0] << "x" << sa[1] << " vs " << sb[0] << "x"
              << sb[1] << ")\n";
    return 1;
  }
  int maxDiff = 0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    maxDiff = std::max(maxDiff, std::abs(static_cast<int>(a[i]) - static_cast<int>(b[i])));
  }
  const double psnr = vtkFXScenes::PSNR(a, b);
  std::cout << "PSNR " << psnr << " dB, largest difference " << maxDiff << "/255\n";
  if (argc == 5 && psnr < minimum)
  {
    std::cerr << "vtkfx-compare: PSNR below " << argv[4] << " dB\n";
    return 1;
  }
  return 0;
}
