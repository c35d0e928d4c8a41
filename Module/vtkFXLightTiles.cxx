#include "vtkFXLightTiles.h"

#include "vtkFXRenderUtilities.h"

#include "vtkFXTileDepthFS.h"

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkFXOpenGL.h"

#include <algorithm>
#include <cmath>
#include <limits>

vtkFXLightTiles::vtkFXLightTiles() = default;
vtkFXLightTiles::~vtkFXLightTiles() = default;

double vtkFXLightTiles::Range(double intensity, const double attenuation[3], double cutoff)
{
  const double infinity = std::numeric_limits<double>::infinity();
  if (!(cutoff > 0.0))
  {
    return infinity;
  }
  // Solve a0 + a1 d + a2 d^2 = 2 intensity / cutoff for the largest d >= 0.
  const double target = 2.0 * intensity / cutoff;
  const double a0 = attenuation[0], a1 = attenuation[1], a2 = attenuation[2];
  if (!std::isfinite(target))
  {
    return infinity; // a light too bright (or raised too easily) to bound
  }
  if (a2 < 0.0 || (a2 == 0.0 && a1 < 0.0))
  {
    // The denominator falls and reaches 0 at some distance, where the
    // light is infinite: no range bounds it.
    return infinity;
  }
  if (a1 < 0.0)
  {
    // (a2 > 0) The denominator dips to a0 - a1^2 / (4 a2) at d = -a1 /
    // (2 a2) before it grows: brightest there, not at the light.
    const double lowest = a0 - a1 * a1 / (4.0 * a2);
    if (!(lowest > 0.0))
    {
      return infinity; // infinite there
    }
    if (!(lowest < target))
    {
      return -1.0; // dimmer than the cutoff everywhere
    }
    return (-a1 + std::sqrt(4.0 * a2 * (target - lowest))) / (2.0 * a2);
  }
  if (!(a0 < target))
  {
    return -1.0; // dimmer than the cutoff even at the light
  }
  if (a2 > 0.0)
  {
    // The root as 2c / (a1 + sqrt(a1^2 + 4 a2 c)), c = target - a0: the
    // textbook (-a1 + sqrt(...)) / (2 a2) cancels to 0 when a2 is tiny
    // against a1 (attenuation (1, 1, 1e-20) gave range 0 instead of ~1e3).
    const double c = target - a0;
    const double root = std::sqrt(a1 * a1 + 4.0 * a2 * c);
    return 2.0 * c / (a1 + root); // (a1 >= 0 here)
  }
  return a1 > 0.0 ? (target - a0) / a1 : infinity;
}

bool vtkFXLightTiles::CoveredTiles(const Light& light, const double p[16], int box[4]) const
{
  box[0] = 0;
  box[1] = 0;
  box[2] = this->TilesX - 1;
  box[3] = this->TilesY - 1;
  if (!(light.Radius >= 0.0))
  {
    return false; // never brighter than the cutoff (Range < 0)
  }
  if (!std::isfinite(light.Radius))
  {
    return true;
  }
  double sphereBox[6] = { light.Center[0] - light.Radius, light.Center[0] + light.Radius,
    light.Center[1] - light.Radius, light.Center[1] + light.Radius,
    light.Center[2] - light.Radius, light.Center[2] + light.Radius };
  if (this->DepthRange[1] > 0.0)
  {
    // Visible surfaces lie between the clipping planes (view z from -far to
    // -near): the box's part there still holds all the sphere can light,
    // and in perspective it lies in front of the camera.
    sphereBox[4] = std::max(sphereBox[4], -this->DepthRange[1]);
    sphereBox[5] = std::min(sphereBox[5], -this->DepthRange[0]);
    if (!(sphereBox[4] <= sphereBox[5]))
    {
      return false; // it reaches no visible depth
    }
  }
  double lo[3], hi[3];
  const int behind = vtkFXRenderUtilities::ProjectBox(sphereBox, p, lo, hi);
  if (behind == 8)
  {
    return false; // wholly behind the camera: it reaches no visible surface
  }
  if (behind > 0)
  {
    return true; // it reaches the camera's plane: anywhere on screen
  }
  if (lo[0] > 1.0 || lo[1] > 1.0 || hi[0] < -1.0 || hi[1] < -1.0)
  {
    return false; // off screen
  }
  const int tiles[2] = { this->TilesX, this->TilesY };
  const int pixels[2] = { this->Width, this->Height };
  for (int a = 0; a < 2; ++a)
  {
    // Pixels from the viewport's corner (the viewport's own size, not the
    // tiles' rounded-up one); tiles past the last are clamped.
    const double first = std::floor((0.5 * lo[a] + 0.5) * pixels[a] / TileSize);
    const double last = std::floor((0.5 * hi[a] + 0.5) * pixels[a] / TileSize);
    box[a] = static_cast<int>(std::max(0.0, std::min(first, tiles[a] - 1.0)));
    box[a + 2] = static_cast<int>(std::max(0.0, std::min(last, tiles[a] - 1.0)));
  }
  return true;
}

bool vtkFXLightTiles::Build(const std::vector<Light>& lights, const double projection[16],
  int width, int height, const double depthRange[2], size_t pointLights, int firstRow)
{
  const bool ranged = depthRange && depthRange[0] >= 0.0 && depthRange[1] > depthRange[0] &&
    std::isfinite(depthRange[1]);
  this->DepthRange[0] = ranged ? depthRange[0] : 0.0;
  this->DepthRange[1] = ranged ? depthRange[1] : 0.0;
  this->Width = std::max(1, width);
  this->Height = std::max(1, height);
  this->TilesX = std::max(1, (width + TileSize - 1) / TileSize);
  this->TilesY = std::max(1, (height + TileSize - 1) / TileSize);
  const size_t tiles = static_cast<size_t>(this->TilesX) * this->TilesY;
  std::vector<int> boxes(4 * lights.size());
  std::vector<char> visible(lights.size());
  for (size_t i = 0; i < lights.size(); ++i)
  {
    visible[i] = this->CoveredTiles(lights[i], projection, &boxes[4 * i]);
  }
  // Calls visit(tile) for every tile light i covers: once to count the
  // lists, once to fill them.
  // With measured tile depths, a tile counts only where the light's
  // sphere reaches depths its surfaces have.
  const bool depthTested = this->TileDepthSize[0] == this->Width &&
    this->TileDepthSize[1] == this->Height && this->TileDepths.size() == 2 * tiles;
  const auto forEachCoveredTile = [&](size_t i, auto&& visit) {
    const int* box = &boxes[4 * i];
    const double depth = -lights[i].Center[2];
    const double nearest = depth - lights[i].Radius, farthest = depth + lights[i].Radius;
    const bool bounded = depthTested && std::isfinite(lights[i].Radius);
    for (int y = box[1]; visible[i] && y <= box[3]; ++y)
    {
      for (int x = box[0]; x <= box[2]; ++x)
      {
        const size_t t = static_cast<size_t>(y) * this->TilesX + x;
        if (!bounded || (farthest >= this->TileDepths[2 * t] && nearest <= this->TileDepths[2 * t + 1]))
        {
          visit(t);
        }
      }
    }
  };
  // Per tile, the point lights (lights[0, pointLights)) and the spot
  // lights covering it; filled in the lights' order, so points come first.
  const size_t points = std::min(pointLights, lights.size());
  std::vector<size_t> counts(2 * tiles, 0);
  for (size_t i = 0; i < lights.size(); ++i)
  {
    const size_t kind = i < points ? 0 : 1;
    forEachCoveredTile(i, [&](size_t t) { ++counts[2 * t + kind]; });
  }
  size_t total = 0;
  for (size_t c : counts)
  {
    total += c;
  }
  this->HeaderData.assign(HeaderValues * tiles, 0.0f);
  // Entries: copies of the lights' rows while they fit, else the rows'
  // indices (one shared list of every light past GetEntryLimit()), each
  // within what a texture of the context can hold.
  const size_t indexLimit = this->GetEntryLimit();
  const size_t rowLimit =
    std::min(this->RowEntryBudget, size_t(this->MaximumTextureSize) * this->RowsPerRowUsed());
  const bool overflow = total > indexLimit || lights.size() > indexLimit;
  this->EntriesAreRows = std::max(overflow ? lights.size() : total, size_t(1)) <= rowLimit;
  this->EntriesPerRowUsed = this->EntriesAreRows ? this->RowsPerRowUsed() : this->IndicesPerRowUsed();
  const size_t entryFloats = this->EntriesAreRows ? EntryTexels * 4 : 1;
  const auto writeEntry = [&](size_t entry, size_t light) {
    if (this->EntriesAreRows)
    {
      std::copy(lights[light].Row, lights[light].Row + entryFloats,
        this->EntryData.begin() + entry * entryFloats);
    }
    else
    {
      this->EntryData[entry] = static_cast<float>(firstRow + light);
    }
  };
  if (overflow)
  {
    this->EntryData.assign(entryFloats * std::max<size_t>(lights.size(), 1), 0.0f);
    for (size_t i = 0; i < lights.size(); ++i)
    {
      writeEntry(i, i);
    }
    for (size_t t = 0; t < tiles; ++t)
    {
      this->HeaderData[HeaderValues * t + 1] = static_cast<float>(points);
      this->HeaderData[HeaderValues * t + 2] = static_cast<float>(lights.size() - points);
    }
    return false;
  }
  total = 0;
  std::vector<size_t> next(tiles);
  for (size_t t = 0; t < tiles; ++t)
  {
    this->HeaderData[HeaderValues * t] = static_cast<float>(total);
    this->HeaderData[HeaderValues * t + 1] = static_cast<float>(counts[2 * t]);
    this->HeaderData[HeaderValues * t + 2] = static_cast<float>(counts[2 * t + 1]);
    next[t] = total;
    total += counts[2 * t] + counts[2 * t + 1];
  }
  this->EntryData.assign(entryFloats * std::max<size_t>(total, 1), 0.0f);
  for (size_t i = 0; i < lights.size(); ++i)
  {
    forEachCoveredTile(i, [&](size_t t) { writeEntry(next[t]++, i); });
  }
  return true;
}

void vtkFXLightTiles::Upload(vtkOpenGLRenderWindow* window)
{
  vtkFXRenderUtilities::EnsureTexture(
    this->Headers, window, this->TilesX, this->TilesY, vtkFXRenderUtilities::RGBA32F);
  this->Headers->Activate(); // its own unit: binding elsewhere could replace a sampler's texture
  glTexSubImage2D(
    GL_TEXTURE_2D, 0, 0, 0, this->TilesX, this->TilesY, GL_RGBA, GL_FLOAT, this->HeaderData.data());
  // Rows: GetEntriesPerRow() entries of EntryTexels texels to a row (an
  // entry never straddles two); indices: GetEntriesPerRow() to a row.
  const size_t entryFloats = this->EntriesAreRows ? EntryTexels * 4 : 1;
  const int texelsPerEntry = this->EntriesAreRows ? EntryTexels : 1;
  const int perRow = this->EntriesPerRowUsed;
  const int entries = static_cast<int>(this->EntryData.size() / entryFloats);
  const int rows = (entries + perRow - 1) / perRow;
  // Whole rows, and rows to a power of two (within the context's limit),
  // kept while they hold the entries and are not four times what they
  // need: the count changes nearly every frame while the camera or the
  // lights move, and a texture sized to it was allocated again each time.
  // Only the rows in use are uploaded.
  const int columns = texelsPerEntry * perRow;
  const int format = this->EntriesAreRows ? vtkFXRenderUtilities::RGBA32F : vtkFXRenderUtilities::R32F;
  int height = 1;
  while (height < rows)
  {
    height *= 2;
  }
  height = std::max(rows, std::min(height, this->MaximumTextureSize));
  const int keptHeight = this->Entries ? static_cast<int>(this->Entries->GetHeight()) : 0;
  if (keptHeight >= rows && keptHeight <= 4 * rows &&
    static_cast<int>(this->Entries->GetWidth()) == columns)
  {
    height = keptHeight; // (EnsureTexture checks the format)
  }
  this->EntryData.resize(static_cast<size_t>(rows) * columns * (this->EntriesAreRows ? 4 : 1), 0.0f);
  vtkFXRenderUtilities::EnsureTexture(this->Entries, window, columns, height, format);
  this->Entries->Activate();
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, columns, rows, this->EntriesAreRows ? GL_RGBA : GL_RED,
    GL_FLOAT, this->EntryData.data());
}

double vtkFXLightTiles::GetMeanLightsPerTile() const
{
  const size_t tiles = this->HeaderData.size() / HeaderValues;
  double sum = 0.0;
  for (size_t t = 0; t < tiles; ++t)
  {
    sum += this->HeaderData[HeaderValues * t + 1] + this->HeaderData[HeaderValues * t + 2];
  }
  return tiles ? sum / tiles : 0.0;
}

bool vtkFXLightTiles::MeasureTileDepths(
  vtkOpenGLRenderWindow* window, vtkTextureObject* linearDepth, int width, int height)
{
  this->TileDepths.clear();
  this->TileDepthSize[0] = this->TileDepthSize[1] = 0;
  if (!window || !linearDepth || width < 1 || height < 1)
  {
    return false;
  }
  const int tiles[2] = { (width + TileSize - 1) / TileSize, (height + TileSize - 1) / TileSize };
  vtkFXRenderUtilities::EnsureTexture(
    this->DepthRanges, window, tiles[0], tiles[1], vtkFXRenderUtilities::RG32F);
  vtkFXRenderUtilities::RenderTargetScope target(window, this->DepthFrameBuffer, this->DepthRanges);
  std::string fs = vtkFXTileDepthFS;
  vtkShaderProgram::Substitute(
    fs, "//VTK::System::Dec", "//VTK::System::Dec\n#define FX_TILE " + std::to_string(TileSize) + "\n",
    false);
  vtkShaderProgram* program = vtkFXRenderUtilities::ReadyQuad(this->DepthQuad, window, fs);
  if (!program || !target.IsComplete())
  {
    return false;
  }
  // (a texture the caller already bound stays bound)
  const bool bound = linearDepth->GetTextureUnit() >= 0;
  linearDepth->Activate();
  program->SetUniformi("fxLinearDepth", linearDepth->GetTextureUnit());
  const int size[2] = { width, height };
  program->SetUniform2i("fxSize", size);
  this->DepthQuad.Helper->Render();
  if (!bound)
  {
    linearDepth->Deactivate();
  }
  this->TileDepths.resize(2 * static_cast<size_t>(tiles[0]) * tiles[1]);
  this->DepthFrameBuffer->ActivateReadBuffer(0);
  glReadPixels(0, 0, tiles[0], tiles[1], GL_RG, GL_FLOAT, this->TileDepths.data());
  this->TileDepthSize[0] = width;
  this->TileDepthSize[1] = height;
  return true;
}

void vtkFXLightTiles::ReleaseGraphicsResources(vtkWindow* window)
{
  vtkFXRenderUtilities::ReleaseQuad(this->DepthQuad, window);
  vtkFXRenderUtilities::Release(this->DepthRanges, window);
  vtkFXRenderUtilities::Release(this->DepthFrameBuffer, window);
  this->TileDepths.clear();
  vtkFXRenderUtilities::Release(this->Headers, window);
  vtkFXRenderUtilities::Release(this->Entries, window);
}
