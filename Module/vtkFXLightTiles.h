/**
 * @class   vtkFXLightTiles
 * @brief   Per-screen-tile light lists for the composite's light-texture path.
 *
 * The viewport is cut into TileSize x TileSize pixel tiles; each light
 * goes into the list of every tile its sphere of influence covers on the
 * screen (the bounding rectangle of the sphere's projected bounding box;
 * a sphere reaching the camera's plane covers every tile, unless Build is
 * given the visible depth range, as the composite does) and, after
 * MeasureTileDepths, reaches in depth (the tile's surfaces' range). A light's
 * sphere of influence ends where VTK's attenuation, 1 / (a0 + a1 d + a2 d^2),
 * brings the most it can add to a colour (twice its intensity times
 * colour: diffuse and specular coefficients at most 1 each) below a
 * cutoff (Range); a light that VTK never attenuates (a1 = a2 = 0) and
 * is brighter than the cutoff, a directional light, and any light when the
 * cutoff is 0 go into every tile; a light dimmer than the cutoff
 * everywhere goes into none, and so does one wholly behind the camera. The composite then loops per pixel over its tile's list only, so
 * the cost grows with the lights that reach a pixel, not with the lights
 * in the scene; the error is below the cutoff per light and channel.
 *
 * Textures (uploaded by Upload): headers, RGBA32F, one texel per tile
 * (first entry, point lights, spot lights); entries, RGBA32F, 1024 to a
 * row, each a copy of its light's row of the composite's light texture (4
 * texels), so the composite reads a light straight from its tile's list
 * (with an index per entry instead, that index's fetch was a tenth of a
 * 1024-light frame). Past 2^20 entries (MaximumRowEntries, 64 MiB of
 * copies) the entries are the rows' indices instead (R32F, 4096 to a row;
 * GetEntriesAreRows false), exact in floats up to 2^24 entries
 * (MaximumEntries, 64 MiB); lists past that (a thousand lights that each
 * cover a 4K viewport's 32,400 tiles) are not built: every tile then
 * lists every light, the untiled loop's cost, and Build says so.
 * Those layouts need textures 4096 texels wide, and 1024 (rows) or 4096
 * (indices) high; OpenGL 3 promises 1024 only. Under a smaller
 * SetMaximumTextureSize (the composite passes GL_MAX_TEXTURE_SIZE) a row
 * holds fewer entries (GetEntriesPerRow) and the thresholds shrink to
 * what the textures can hold: rows up to MaximumTextureSize rows of
 * entries, then indices up to MaximumTextureSize rows of those.
 *
 * A plain C++ helper of vtkFXCompositePass (not wrapped).
 */
#ifndef vtkFXLightTiles_h
#define vtkFXLightTiles_h

#include "vtkFXModule.h"
#include "vtkFXRenderUtilities.h" // for the depth pass's quad
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h" // for the textures held

#include <algorithm>
#include <limits>
#include <vector>

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkWindow;

class VTKFX_EXPORT vtkFXLightTiles
{
public:
  static constexpr int TileSize = 16;        // pixels
  static constexpr int EntryTexels = 4;      // RGBA32F texels an entry holds (a light's row)
  static constexpr int EntriesPerRow = 1024; // of the entries' texture, entries with rows
  static constexpr int IndicesPerRow = 4096; // of the entries' texture, entries with indices
  static constexpr size_t MaximumRowEntries = size_t(1) << 20; // 64 MiB of rows
  static constexpr size_t MaximumEntries = size_t(1) << 24;    // 64 MiB of indices
  static constexpr size_t HeaderValues = 4; // per tile, see GetHeaderData

  vtkFXLightTiles();
  ~vtkFXLightTiles();

  /**
   * Distance at which a positional light of `intensity` (the largest of
   * its colour's components times its intensity) with VTK's `attenuation`
   * coefficients can no longer add `cutoff` to a colour: 2 x intensity /
   * (a0 + a1 d + a2 d^2) = cutoff. Negative when it never reaches the
   * cutoff anywhere; infinite when it never falls below it.
   */
  static double Range(double intensity, const double attenuation[3], double cutoff);

  /**
   * A light as the composite uploads it: its sphere of influence in view
   * coordinates (Radius infinite: every tile), and the EntryTexels x 4
   * floats of its row in the composite's light texture, which every tile
   * entry of it carries.
   */
  struct Light
  {
    double Center[3];
    double Radius;
    float Row[EntryTexels * 4];
  };

  /**
   * Lists for a width x height viewport; `projection` is the camera's
   * view-to-clip matrix (row-major). The first `pointLights` of `lights`
   * are point lights, the rest spot lights, which each tile lists after
   * its point lights (the composite loops over each kind with its own
   * code). With `depthRange` (the camera's clipping range, near and far
   * distances), a light counts only for surfaces between those depths: one
   * whose sphere crosses the camera's plane no longer reaches every tile
   * unless its sphere reaches the visible depths there. Returns false when
   * the lists would exceed GetEntryLimit(): every tile then lists every
   * light.
   */
  bool Build(const std::vector<Light>& lights, const double projection[16], int width, int height,
    const double depthRange[2] = nullptr,
    size_t pointLights = std::numeric_limits<size_t>::max(), int firstRow = 0);

  /**
   * Whether the last Build's entries are copies of the lights' rows
   * (EntryTexels RGBA32F texels each), or, for lists past the row budget
   * (SetRowEntryBudget) or past what MaximumTextureSize rows of copies
   * hold, their rows' indices in the light texture (one R32F texel each:
   * light i of Build is row firstRow + i).
   */
  bool GetEntriesAreRows() const { return this->EntriesAreRows; }

  /**
   * The most entries the lists may have (MaximumEntries, or what
   * MaximumTextureSize rows of indices hold when that is less).
   */
  size_t GetEntryLimit() const
  {
    return std::min(size_t(MaximumEntries), size_t(this->MaximumTextureSize) * this->IndicesPerRowUsed());
  }

  /**
   * Entries to a row of the entries' texture in the last Build: entry e
   * is at texel (e % GetEntriesPerRow(), e / GetEntriesPerRow()), times
   * EntryTexels horizontally when the entries are rows. EntriesPerRow or
   * IndicesPerRow unless the maximum texture size is smaller.
   */
  int GetEntriesPerRow() const { return this->EntriesPerRowUsed; }

  /**
   * The largest width and height a texture may have (texels; the
   * context's GL_MAX_TEXTURE_SIZE, at least EntryTexels); later Builds lay
   * their entries out within it. Default 16384.
   */
  void SetMaximumTextureSize(int texels)
  {
    this->MaximumTextureSize = std::max(texels, EntryTexels);
  }

  /**
   * Entries up to which they carry copies of their lights' rows (64 bytes
   * each; default MaximumRowEntries, at most that, and at most what
   * MaximumTextureSize rows of copies hold); past it, indices.
   */
  void SetRowEntryBudget(size_t entries)
  {
    this->RowEntryBudget = std::min(entries, size_t(MaximumRowEntries));
  }

  /**
   * Measures each tile's range of linear depth (its nearest and farthest
   * surface) in `linearDepth`, a width x height G-buffer channel, on the
   * GPU (one pass over the channel into a texel per tile) and reads it
   * back: until the next call, Build for that size counts a light for a
   * tile only where its sphere's depth extent (view-space depth of its
   * centre plus or minus its radius) meets the tile's range, and never for
   * a tile without a surface. Binds its own program and framebuffer (the
   * caller binds its program again). Returns false, and forgets earlier
   * ranges, when the pass cannot run.
   */
  bool MeasureTileDepths(
    vtkOpenGLRenderWindow* window, vtkTextureObject* linearDepth, int width, int height);
  /**
   * Drop the measured ranges (Build then tests no depths).
   */
  void ForgetTileDepths() { this->TileDepths.clear(); }
  /**
   * The ranges measured (nearest, farthest per tile, rows bottom-up), for
   * tests.
   */
  const std::vector<float>& GetTileDepths() const { return this->TileDepths; }

  ///@{
  /**
   * What the last Build made (for tests): per tile HeaderValues floats
   * (first entry, point lights, spot lights, 0), and the entries, each the
   * EntryTexels x 4 floats of its light's row, or its row's index.
   */
  const std::vector<float>& GetHeaderData() const { return this->HeaderData; }
  const std::vector<float>& GetEntryData() const { return this->EntryData; }
  ///@}

  /**
   * Uploads the lists of the last Build into the two textures.
   */
  void Upload(vtkOpenGLRenderWindow* window);
  vtkTextureObject* GetHeaderTexture() const { return this->Headers; }
  vtkTextureObject* GetEntryTexture() const { return this->Entries; }

  /**
   * Mean list length over the tiles of the last Build (lights per pixel,
   * as far as tiles can tell).
   */
  double GetMeanLightsPerTile() const;

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  // Entries to a row of the entries' texture, of copies and of indices,
  // within MaximumTextureSize.
  int RowsPerRowUsed() const
  {
    return std::min(EntriesPerRow, std::max(this->MaximumTextureSize / EntryTexels, 1));
  }
  int IndicesPerRowUsed() const { return std::min(IndicesPerRow, this->MaximumTextureSize); }
  // The tiles (inclusive ranges) a sphere covers; false when none.
  bool CoveredTiles(const Light& light, const double projection[16], int box[4]) const;
  double DepthRange[2] = { 0.0, 0.0 }; // near, far; far 0: none

  int Width = 0; // the viewport's pixels
  int Height = 0;
  int TilesX = 0;
  int TilesY = 0;
  std::vector<float> HeaderData; // (first, point lights, spot lights, 0) per tile
  std::vector<float> EntryData;
  bool EntriesAreRows = true;
  int EntriesPerRowUsed = EntriesPerRow;
  int MaximumTextureSize = 16384;
  size_t RowEntryBudget = MaximumRowEntries;
  vtkSmartPointer<vtkTextureObject> Headers;
  vtkSmartPointer<vtkTextureObject> Entries;
  // The tiles' depth ranges (MeasureTileDepths), for a viewport of
  // TileDepthSize pixels.
  std::vector<float> TileDepths;
  int TileDepthSize[2] = { 0, 0 };
  vtkFXRenderUtilities::FullScreenQuad DepthQuad;
  vtkSmartPointer<vtkTextureObject> DepthRanges;
  vtkSmartPointer<vtkOpenGLFramebufferObject> DepthFrameBuffer;
};

#endif
// VTK-HeaderTest-Exclude: vtkFXLightTiles.h
