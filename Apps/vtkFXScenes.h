// vtkFXScenes: scenes shared by vtkfx-render, the benchmarks and the tests.
//
// A scene is a set of props put into a renderer with a good default camera,
// VTK's default light kit and (optionally) a ground plane under the data.
#ifndef vtkFXScenes_h
#define vtkFXScenes_h

#include <string>
#include <vector>

class vtkRenderer;
class vtkRenderWindow;

namespace vtkFXScenes
{
/**
 * Directory of the project's Data/ folder (VTKFX_DATA environment variable,
 * else the source tree's Data/ compiled in).
 */
std::string DataDirectory();

/**
 * Names of the built-in scenes ("scene:spheres", ...).
 */
std::vector<std::string> BuiltInSceneNames();

struct Options
{
  bool Ground = true;   // a ground plane under the data
  bool LightKit = true; // VTK's default vtkLightKit instead of the headlight
};

/**
 * Whether INPUT names a built-in scene or a readable file, before any
 * work; otherwise false and a message in `error`.
 */
bool CheckInput(const std::string& input, std::string& error);

/**
 * Fill `renderer` with INPUT: a built-in scene name or a file VTK can read
 * (.obj, .ply, .stl, .vtp, .vtk, .pdb). Frames the camera. On failure returns
 * false and puts a message in `error`; the renderer is then left empty.
 * `dataBounds`, when given, receives the bounds of the data without the
 * ground plane.
 */
bool Populate(vtkRenderer* renderer, const std::string& input, const Options& options,
  std::string& error, double dataBounds[6] = nullptr);

/**
 * Peak signal-to-noise ratio in dB between two RGB 8-bit images of the same
 * size. With `background` (an RGB byte triple), pixels that show it (within
 * 1) in both images are left out, so that the ratio measures the rendered
 * data, not the empty screen around it. Returns +inf for identical images,
 * -1 if the sizes differ or no pixel is left to compare (two renders that
 * show nothing do not agree on anything).
 */
double PSNR(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b,
  const unsigned char* background = nullptr);

/**
 * How much of the reference's fine structure an image keeps (AO detail
 * score): both images (one value per pixel, rows bottom-up; the
 * reference's negative values mark background) are split at a Gaussian of
 * sigma 3 pixels, blurred over the geometry pixels only (normalised
 * convolution); the score is the correlation of the two fine bands (image
 * minus its blur) over the geometry pixels at least 8 pixels from the
 * background and from the image's border. 1: every crease kept (up to
 * scale); 0: none (or a fine band without variance); negative: inverted.
 */
double DetailScore(const std::vector<float>& image, const std::vector<float>& reference,
  int width, int height);

/**
 * Largest difference of one channel between two RGB 8-bit images.
 */
int MaxDifference(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b);

/**
 * The renderer's background as the bytes an 8-bit framebuffer stores.
 */
void BackgroundBytes(vtkRenderer* renderer, unsigned char rgb[3]);

/**
 * Replaces the renderer's lights with `count` coloured point lights on a
 * jittered grid over the ground that Populate puts under `bounds`, hovering
 * 1/20 of the grid spacing above it. Each is attenuated as VTK does,
 * 1 / (1 + k d^2), with k such that it can add at most 1/512 to a colour
 * (vtkFXCompositePass's default LightCutoff) at `reach` grid spacings: so
 * each point of the ground is reached by about pi reach^2 lights whatever
 * the count. Returns the grid spacing.
 */
double AddPointLights(vtkRenderer* renderer, int count, const double bounds[6], double reach = 1.5);

/**
 * The window's current image as RGB bytes (bottom row first).
 */
std::vector<unsigned char> Capture(vtkRenderWindow* window);

/**
 * An 8-bit PNG file (grey, grey and alpha, RGB or RGBA) as RGB bytes
 * (bottom row first, as Capture; grey in all three, alpha dropped), and its
 * size; false when it cannot be read or has 16-bit samples.
 */
bool LoadRGB(const std::string& path, std::vector<unsigned char>& rgb, int size[2]);
}

#endif
