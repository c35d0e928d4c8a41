/**
 * @class   vtkFXToonPass
 * @brief   Toon shading: diffuse light in bands, and feature lines from the G-buffer.
 *
 * Two parts, each can be used alone.
 *
 * Bands (composite code, no pass of its own): each light's diffuse factor
 * (max(0, n.l) times its attenuation) is raised to the next band value, as
 * in the deferred toon shader of seed 004: with thresholds t0 < t1 < ... <
 * tk, a factor below t0 becomes 0, one in [ti, ti+1) becomes ti+1, and one
 * at or above tk becomes 1. The default thresholds are the seed's 0.05,
 * 0.25, 0.5, 0.75 (bands 0, 0.25, 0.5, 0.75, 1). Highlights, ambient and
 * emission are left as they are.
 *
 * Feature lines (a post-process step drawn onto the lit HDR image, before
 * the 2D overlay): between two neighbouring G-buffer pixels there is
 * - a silhouette where one is background and the other is not, or where
 *   either pixel's view-space position lies off the other's tangent plane by
 *   more than SilhouetteThreshold times the nearer depth (in parallel
 *   projection, times the distance at which a 30-degree view angle, VTK's
 *   default, spans the parallel view, so that neither moving the camera
 *   back nor its view angle changes anything): a test
 *   relative to depth, so it does not depend on the scene's scale, and exact for
 *   planes at any angle, so a plane seen at a grazing angle is not taken
 *   for an edge;
 * - a crease where the two normals differ by more than CreaseAngle.
 * Both read the surfaces' own normals (the G-buffer's GeometricNormal
 * where a visible prop has a bump or a normal texture): lines outline the
 * geometry, while the bands shade with the perturbed normal (read with the
 * shading normal, a normal-mapped plane seen at a grazing angle took its
 * bumps for silhouettes and creases).
 * Lines of LineWidth pixels (at LineReferenceHeight output rows; the width
 * scales with the height the renderer covers in the image: its viewport's,
 * or in a scaled screenshot, which vtkWindowToImageFilter renders in tiles
 * of the window's size (whose seams lines do not cross), its viewport's
 * height in the whole scaled window) are centred on those pixel
 * boundaries, with a coverage ramp of one pixel (anti-aliased), in
 * LineColor. Lines are drawn over translucent props and volumes in front
 * of them; opaque ones hide them (each line pixel is depth-tested at the
 * depth of the surface it belongs to), also props the G-buffer does not
 * capture (drawn forward) and a lower layer's preserved depth.
 *
 * Reads: the G-buffer's normals (bands and lines) and linear depth (lines).
 * Writes: composite code (bands); lines blended onto the image (the
 * framebuffer, or the HDR target when another effect has the pipeline keep
 * one). With lines on, its stage is PostProcess, otherwise Composite.
 * Cost: bands, a few instructions per light and pixel; lines, an edges
 * pass over the pixels with a surface (the G-buffer's depth test rejects
 * the others before the shader: SkipBackgroundEdges) of 4 gathers of
 * G-buffer 2x2 blocks per pixel, which stores the marks into an R8 edge
 * texture (1 byte per pixel) and flags, in an R8 texture of one byte per
 * 8x8 tile, the tiles lines can reach (CullLineTiles); then the lines, one
 * point per flagged tile, of 1 (lines under 1 px), 4 (under 3 px) or 9
 * (under 5 px) gathers of edge blocks per pixel (wider lines read texel
 * by texel up to the two nearest marks), and 3 fetches of the G-buffer's
 * depth per line pixel. Without image stores (or with
 * CullLineTiles off) the edges are the colour output of a pass over the
 * pixels that a mask pass (one gather per pixel) lets through, and the
 * lines cover the whole image. Where GL lacks textureGather (GLSL 4.00 or
 * ARB_gpu_shader5), each gather becomes 4 texel fetches.
 */
#ifndef vtkFXToonPass_h
#define vtkFXToonPass_h

#include "vtkFXEffectPass.h"
#include "vtkFXModule.h"
#include "vtkFXSetGet.h" // for vtkFXSetClampMacro
#include "vtkFXRenderUtilities.h" // for the full-screen quads
#include "vtkNew.h"     // for the tiles' vertex array
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;

class VTKFX_EXPORT vtkFXToonPass : public vtkFXEffectPass
{
public:
  static vtkFXToonPass* New();
  vtkTypeMacro(vtkFXToonPass, vtkFXEffectPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Quantise the diffuse light into bands (default on).
   */
  vtkSetMacro(Bands, bool);
  vtkGetMacro(Bands, bool);
  vtkBooleanMacro(Bands, bool);

  ///@{
  /**
   * Band thresholds, increasing, in (0, 1]; at most 16.
   * AddBandThreshold refuses (with an error) a value that is not above the
   * last one or outside (0, 1]. SetDefaultBandThresholds restores the seed's
   * 0.05, 0.25, 0.5, 0.75. With no threshold, every lit side is 1.
   */
  void AddBandThreshold(double threshold);
  void RemoveAllBandThresholds();
  void SetDefaultBandThresholds();
  int GetNumberOfBandThresholds() const;
  double GetBandThreshold(int i) const;
  ///@}

  /**
   * Draw feature lines (default on). Changes the stage: PostProcess with
   * lines, Composite without.
   */
  virtual void SetFeatureLines(bool lines);
  vtkGetMacro(FeatureLines, bool);
  vtkBooleanMacro(FeatureLines, bool);

  /**
   * Lines at silhouettes (depth discontinuities; default on).
   */
  vtkSetMacro(Silhouettes, bool);
  vtkGetMacro(Silhouettes, bool);
  vtkBooleanMacro(Silhouettes, bool);

  /**
   * Lines at creases (normal discontinuities; default on).
   */
  vtkSetMacro(Creases, bool);
  vtkGetMacro(Creases, bool);
  vtkBooleanMacro(Creases, bool);

  /**
   * Smallest gap between a pixel's position and its neighbour's tangent
   * plane that makes a silhouette, as a fraction of the nearer depth (in
   * parallel projection of ParallelScale / tan(15 degrees)) (1e-5..10,
   * default 0.02).
   */
  vtkFXSetClampMacro(SilhouetteThreshold, double, 1e-5, 10.0);
  vtkGetMacro(SilhouetteThreshold, double);

  /**
   * Smallest angle between neighbouring normals that makes a crease, in
   * degrees (1..179, default 30, vtkPolyDataNormals' feature angle).
   */
  vtkFXSetClampMacro(CreaseAngle, double, 1.0, 179.0);
  vtkGetMacro(CreaseAngle, double);

  /**
   * Line width in pixels at LineReferenceHeight rows of output
   * (0.25..16, default 2); in an image of H rows (a viewport, or a scaled
   * screenshot) lines are
   * LineWidth x H / LineReferenceHeight pixels wide, within a quarter
   * of a pixel and 32 pixels, so an image rendered at twice the size
   * shows the same drawing.
   */
  vtkFXSetClampMacro(LineWidth, double, 0.25, 16.0);
  vtkGetMacro(LineWidth, double);

  /**
   * Output rows at which lines are LineWidth pixels wide (1..100000,
   * default 720).
   */
  vtkSetClampMacro(LineReferenceHeight, int, 1, 100000);
  vtkGetMacro(LineReferenceHeight, int);

  /**
   * Line colour, linear RGB (components 0..65504, HDR allowed; default
   * black). A colour with a NaN component is refused with an error.
   */
  vtkFXSetClampVector3Macro(LineColor, double, 0.0, 65504.0);
  vtkGetVector3Macro(LineColor, double);

  /**
   * Draw lines only over the 8x8-pixel tiles that a marked pixel side can
   * reach (default on). The edges pass stores its marks and flags those
   * tiles with image stores (GL 4.2, texture clears, GL 4.4, and
   * framebuffers without attachments, GL 4.3, or their ARB extensions;
   * points 8 pixels wide); without them, or with this off, its marks are
   * its colour output and lines are drawn over the whole image, as they
   * are on a multisampled target. The image is the same either way; off
   * is for comparison.
   */
  vtkSetMacro(CullLineTiles, bool);
  vtkGetMacro(CullLineTiles, bool);
  vtkBooleanMacro(CullLineTiles, bool);

  /**
   * Find edges only at pixels that need it (default on): with culled line
   * tiles, the G-buffer's depth rejects the pixels without a surface
   * before the edges shader runs (a covered pixel stores the marks of its
   * background neighbours too); otherwise a depth image of the pixels
   * where the pixel, its right neighbour or the one above holds a surface
   * (one pass of one gather per pixel, 4 bytes per pixel) rejects the
   * others. A software rasteriser otherwise runs the shader in full on
   * every background pixel. The image is the same either way; off is for
   * comparison.
   */
  vtkSetMacro(SkipBackgroundEdges, bool);
  vtkGetMacro(SkipBackgroundEdges, bool);
  vtkBooleanMacro(SkipBackgroundEdges, bool);

  /**
   * Read the G-buffer and the marks four texels at a time with
   * textureGather where the context has it (GLSL 4.00 or
   * ARB_gpu_shader5; default on); off, or without it, texel by texel.
   * The image is the same either way; off is for comparison (and for a
   * driver whose gathers misbehave).
   */
  vtkSetMacro(UseTextureGather, bool);
  vtkGetMacro(UseTextureGather, bool);
  vtkBooleanMacro(UseTextureGather, bool);

  /**
   * Whether the last frame with lines drew them over flagged tiles only.
   */
  bool GetLineTilesCulled() const { return this->LineTilesCulled; }

  /**
   * Whether the current OpenGL context can flag line tiles (image stores,
   * texture clears, framebuffers without attachments and points as wide
   * as a tile; see CullLineTiles). Needs a current context.
   */
  static bool CanFlagLineTiles();

  /**
   * Line width in pixels for a viewport `height` rows high (see LineWidth).
   */
  double GetEffectiveLineWidth(int height) const;

  /**
   * The R8 edge texture of the last frame with lines: (r + 2 g) / 3, r = 1
   * at an edge between a pixel and its right neighbour, g = 1 with the one
   * above (for tests and debugging).
   */
  vtkTextureObject* GetEdgeTexture();

  /**
   * Work when bands or lines are on and some prop is in the G-buffer.
   */
  /**
   * Some opaque prop, and bands with a light on or feature lines of some
   * kind (silhouettes or creases); the lines' textures and the linear-depth
   * channel only with lines.
   */
  bool HasWork(const vtkFXSceneInfo& scene) override;
  /** The first band threshold, with bands on: factors from it on are raised. */
  double GetSmallestRaisedDiffuse() override;
  unsigned int GetRequiredChannels() override;
  /**
   * Lines follow the surfaces' own orientation, not a bump's or a normal
   * texture's: true while lines are drawn.
   */
  bool GetReadsGeometricNormal() override { return this->DrawsLines(); }
  /** Lines blend displayable colours: no HDR target needed. */
  bool GetNeedsHDRTarget() override { return false; }
  std::string GetCompositeCode(int hook) override;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

protected:
  bool DrawsLines() const; // FeatureLines with silhouettes or creases
  vtkFXToonPass();
  ~vtkFXToonPass() override;

  std::string BandCode() const;
  bool FindEdges(const vtkRenderState* s, vtkOpenGLRenderWindow* window);
  /** The edges shader, marks as image stores or as its colour output. */
  std::string EdgesSource(bool imageStores) const;
  /** Marks and tile flags by image stores, at covered pixels only. */
  bool StoreEdgeMarks(const vtkRenderState* s, vtkOpenGLRenderWindow* window, const int size[2]);
  /** Marks as the colour output, at pixels the edge mask lets through. */
  bool DrawEdgeMarks(const vtkRenderState* s, vtkOpenGLRenderWindow* window, const int size[2]);
  void RenderEdgesQuad(const vtkRenderState* s, vtkShaderProgram* program, const int size[2]);
  bool MakeEdgeMask(vtkOpenGLRenderWindow* window, vtkTextureObject* depth, const int size[2]);
  /** Texel offsets a line pixel reads marks from (first, last) at `height` rows. */
  void GetLineWindow(int height, int window[2]) const;
  void DrawLines(const vtkRenderState* s, vtkOpenGLRenderWindow* window);
  /**
   * The lines shader's reads of the 2x2 mark blocks of texel offsets
   * first..last, and its pick of the nearest marked side midpoints.
   */
  static std::string MidpointCode(int first, int last);

  bool Bands = true;
  std::vector<double> BandThresholds;
  bool FeatureLines = true;
  bool Silhouettes = true;
  bool Creases = true;
  double SilhouetteThreshold = 0.02;
  double CreaseAngle = 30.0;
  double LineWidth = 2.0;
  int LineReferenceHeight = 720;
  double LineColor[3] = { 0.0, 0.0, 0.0 };

  bool CullLineTiles = true;
  bool SkipBackgroundEdges = true;
  bool UseTextureGather = true;
  int OutputRows = 1; // the image's rows (tiles of a scaled screenshot included)
  bool TilesFlagged = false; // this frame's edges pass flagged the tiles
  // The last lines were drawn over the flagged tiles only (not where the
  // target is multisampled: DrawTiles draws every pixel there)
  bool LineTilesCulled = false;
  vtkSmartPointer<vtkTextureObject> Edges;
  vtkSmartPointer<vtkOpenGLFramebufferObject> EdgeFrameBuffer; // Edges as colour
  vtkSmartPointer<vtkOpenGLFramebufferObject> MarkFrameBuffer;  // none: image stores
  vtkFXRenderUtilities::FullScreenQuad EdgeQuad;
  // Depth32F, 0 where the edges pass can mark (SkipBackgroundEdges,
  // marks drawn as colour: without image stores or with CullLineTiles off)
  vtkFXRenderUtilities::DepthMask EdgeMask;
  bool EdgeMaskFailed = false;
  vtkFXRenderUtilities::TilePoints LineTiles; // 8x8 tiles that lines reach (Mask: R8)
  std::string LineSource; // the lines' fragment shader, generated
  bool LineSourceGathers = true; // UseTextureGather when LineSource was made
  int LineSourceWindow[2] = { 0, 0 };           // for this line window

private:
  vtkFXToonPass(const vtkFXToonPass&) = delete;
  void operator=(const vtkFXToonPass&) = delete;
};

#endif
