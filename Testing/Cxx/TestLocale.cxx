// The shaders vtkFX generates compile whatever the program's locale. A
// host application may set its locale from the environment (Qt does, and
// Python's locale.setlocale(LC_ALL, "")); under German, C's printf and
// std::to_string write 0.02 as "0,02", and a C++ global locale also groups
// digits ("1.024"). Code that wrote such numbers into GLSL made the
// composite's shader fail to compile (no opaque props drawn) and the blur's
// tap weights wrong. This test makes the same frames under the classic
// locale and under de_DE.UTF-8 (C and C++ both; made by localedef when the
// tests are configured, found through LOCPATH) and requires the same bytes:
// ambient occlusion (the composite's depth-aware upsample and the blur's
// weights), directional occlusion, toon bands and lines (which failed
// without the locale-independent writing), and bloom, shadows of
// translucent props and 256 point lights (whose code holds integers only
// today; kept so that a float written into it later is caught).

#include "vtkFXPipelinePass.h"
#include "vtkFXRenderUtilities.h"
#include "vtkFXScenes.h"
#include "vtkFXTestUtilities.h"

#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"

#include <clocale>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <locale>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
const char* const CommaLocale = "de_DE.UTF-8";

struct Case
{
  const char* Scene;
  const char* Effect; // ao, do, toon, bloom, avsm or none
};
const Case Cases[] = { { "scene:corner", "ao" }, { "scene:bumps", "do" },
  { "scene:corner", "toon" }, { "scene:glow", "bloom" }, { "scene:isoshadow", "avsm" },
  { "scene:pointlights", "none" } };

// `scene` drawn by a fresh pipeline with `effect`, so that every shader is
// generated anew.
std::vector<unsigned char> RenderWith(
  vtkRenderWindow* window, const std::string& scene, const std::string& effect)
{
  window->GetRenderers()->RemoveAllItems();
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  std::string error;
  if (!vtkFXScenes::Populate(renderer, scene, vtkFXScenes::Options(), error))
  {
    std::cerr << error << std::endl;
    return {};
  }
  vtkNew<vtkFXPipelinePass> pipeline;
  if (effect != "none" && !vtkFXTest::AddEffect(pipeline, effect))
  {
    std::cerr << "no effect " << effect << std::endl;
    return {};
  }
  renderer->SetPass(pipeline);
  window->Render();
  auto image = vtkFXScenes::Capture(window);
  renderer->SetPass(nullptr);
  return image;
}

// The helpers that write numbers into shader code, under the current
// (comma) locale.
int CheckLiterals()
{
  using U = vtkFXRenderUtilities;
  const std::string sigma = U::GLSLFloat(0.02), one = U::GLSLFloat(1.0),
                    tiny = U::GLSLFloat(1e-12), nan = U::GLSLFloat(std::nan(""));
  U::CodeStream code;
  code << 1024 << " " << 0.5;
  std::cout << "under " << CommaLocale << ": std::to_string(0.02) '" << std::to_string(0.02)
            << "', GLSLFloat: '" << sigma << "', '" << one << "', '" << tiny << "', '" << nan
            << "'; CodeStream: '" << code.str() << "'" << std::endl;
  FX_CHECK(std::to_string(0.02).find(',') != std::string::npos,
    "the comma locale is not in effect: the test would prove nothing");
  FX_CHECK(sigma == "0.02" && one == "1.0" && tiny == "1e-12" && nan == "0.0",
    "GLSL literals written in the program's locale");
  FX_CHECK(code.str() == "1024 0.5", "shader code written in the program's locale");
  return EXIT_SUCCESS;
}
}

int TestLocale(int, char*[])
{
  auto window = vtkFXTest::MakeWindow(200, 150);
  std::vector<std::vector<unsigned char>> classic;
  for (const Case& c : Cases)
  {
    classic.push_back(RenderWith(window, c.Scene, c.Effect));
    FX_CHECK(!classic.back().empty(), c.Scene << " did not render");
  }

  // (a locale made for the tests: see Testing/CMakeLists.txt)
  const bool cLocale = std::setlocale(LC_ALL, CommaLocale) != nullptr;
  bool cxxLocale = false;
  try
  {
    std::locale::global(std::locale(CommaLocale));
    cxxLocale = true;
  }
  catch (const std::runtime_error&)
  {
  }
  const char* locpath = std::getenv("LOCPATH");
  FX_CHECK(cLocale && cxxLocale,
    "no locale " << CommaLocale << " (LOCPATH " << (locpath ? locpath : "unset")
                 << "; the tests' configuration makes it with localedef, from Debian's "
                    "locales package)");
  int result = CheckLiterals();
  for (size_t i = 0; i < classic.size() && result == EXIT_SUCCESS; ++i)
  {
    const Case& c = Cases[i];
    const auto image = RenderWith(window, c.Scene, c.Effect);
    const int largest =
      image.size() == classic[i].size() ? vtkFXScenes::MaxDifference(classic[i], image) : 256;
    std::cout << c.Scene << ", " << c.Effect << ", under " << CommaLocale
              << ": largest difference " << largest << " levels from the classic locale's frame"
              << std::endl;
    if (largest != 0)
    {
      std::cerr << c.Scene << ", " << c.Effect << ": a different frame under " << CommaLocale
                << std::endl;
      result = EXIT_FAILURE;
    }
  }
  std::locale::global(std::locale::classic());
  std::setlocale(LC_ALL, "C");
  return result;
}
