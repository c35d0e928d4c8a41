/**
 * @class   vtkFXRenderUtilities
 * @brief   Small GL helpers shared by the vtkFX passes.
 *
 * Texture allocation in a named format (allocating only when the size or the
 * format changes), full-screen quad programs rebuilt only when their source
 * changes, the size of the renderer's viewport, and the affine per-pixel
 * frustum ray used by every pass that reconstructs view-space positions from
 * linear depth.
 */
#ifndef vtkFXRenderUtilities_h
#define vtkFXRenderUtilities_h

#include "vtkFXModule.h"
#include "vtkObject.h"
#include "vtkOpenGLState.h" // for the scoped state of RenderTargetScope
#include "vtkSmartPointer.h"

#include <functional>
#include <locale>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

class vtkDataObject;
class vtkLight;
class vtkTransform;
class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkOpenGLVertexArrayObject;
class vtkRenderWindow;
class vtkRenderer;
class vtkAssemblyPath;
class vtkMatrix4x4;
class vtkProp;
class vtkPropAssembly;
class vtkRenderState;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class VTKFX_EXPORT vtkFXRenderUtilities : public vtkObject
{
public:
  static vtkFXRenderUtilities* New();
  vtkTypeMacro(vtkFXRenderUtilities, vtkObject);

  /**
   * Texel formats used by vtkFX render targets.
   */
  enum TextureFormat
  {
    R32F = 0,  // 4 bytes: linear depth
    RG16F,     // 4 bytes: octahedral normals
    RGBA8,     // 4 bytes: colours in [0,1]
    RGBA16F,   // 8 bytes: HDR colours
    R8,        // 1 byte:  occlusion in [0,1]
    RG8,       // 2 bytes: two values in [0,1]
    RG32F,     // 8 bytes: a value and a linear depth (any scene scale)
    RGBA32F,   // 16 bytes: a normal and a linear depth (any scene scale)
    Depth32F,  // 4 bytes: hardware depth
    Depth24,   // 4 bytes: hardware depth, as some window framebuffers keep it
    Depth32,   // 4 bytes: 32-bit fixed-point hardware depth (VTK's window framebuffer)
    Depth24Stencil8, // 4 bytes: packed depth and stencil (stencil-capable windows)
    NumberOfTextureFormats
  };

  /**
   * "//VTK::System::Dec" and, after it, FX_GATHER 1 where textureGather can
   * read any component (GLSL 4.00, or GLSL 1.50 with ARB_gpu_shader5), else
   * 0 (and always 0 when `useTextureGather` is false): the start of a
   * fragment shader's defines.
   */
  static const char* GatherDefines(bool useTextureGather);

  /**
   * Bytes one texel of the format occupies.
   */
  static int GetBytesPerTexel(int format);

  /**
   * Whether the current OpenGL context has `name`: "GL_VERSION_4_3" (that
   * version or later) or an extension ("GL_ARB_clear_texture"). Asks the
   * context itself (core OpenGL 3.0 queries), whichever loader VTK uses,
   * once per driver (renderer and version strings) and name. Needs a
   * current, initialised context (as a pass has while it renders); false
   * without one that answers.
   */
  static bool IsOpenGLSupported(const char* name);

  /**
   * Clears the OpenGL errors pending before `caller`'s `step` (so that the
   * step can read its own), saying once, while `warned` is false, that an
   * earlier step (VTK's or an effect's) failed: read there, that error
   * would reach no later check.
   */
  static void ClearPendingErrors(vtkObject* caller, const char* step, bool& warned);

  /**
   * Whether every number of a light that VTK's light uniforms carry is
   * finite, also as a float: diffuse colour x intensity, position and focal
   * point (as transformed); for a positional light its attenuation, and for
   * a spot light its exponent. VTK's own shaders turn a light with a NaN
   * or infinite one into NaN (black) pixels; vtkFX's deferred lighting and
   * shadows leave such a light out (vtkFXPipelinePass warns).
   */
  static bool IsLightFinite(vtkLight* light);

  /**
   * The renderer's user light transform where VTK 9.1 applies it to
   * `light` (vtkOpenGLRenderer::UpdateLightingUniforms: a light that is not
   * a scene light, such as the headlight or a light kit's, in view
   * coordinates after the camera's view transform), else null.
   */
  static vtkTransform* GetUserLightTransform(vtkRenderer* renderer, vtkLight* light);

  /**
   * Where VTK shades `light` from, in world coordinates: its transformed
   * position and focal point, moved by GetUserLightTransform where that
   * applies (into view coordinates, through it, and back).
   */
  static void GetShadingLightFrame(
    vtkRenderer* renderer, vtkLight* light, double position[3], double focalPoint[3]);

  /**
   * After vtkOpenGLRenderer::UpdateLightingUniforms(program): the uniforms
   * of each light that is not IsLightFinite made those of a black
   * directional light, whose terms are all 0 (a colour of 0 alone would
   * leave 0 x NaN). Lights are numbered as VTK numbers them, counting the
   * lights that are on.
   */
  static void DarkenNonFiniteLights(vtkRenderer* renderer, vtkShaderProgram* program);

  /**
   * Make `texture` a width x height 2D texture of the given format.
   * Allocates only when it is missing or its size or format differ, and
   * then sets nearest filtering and clamped edges (a texture kept from an
   * earlier frame keeps whatever filtering and wrapping callers set);
   * returns true when it (re)allocated. An allocation OpenGL refuses (no
   * memory) leaves a texture that makes a framebuffer incomplete: callers
   * check RenderTargetScope::IsComplete.
   */
  static bool EnsureTexture(vtkSmartPointer<vtkTextureObject>& texture,
    vtkOpenGLRenderWindow* window, int width, int height, int format);

  /**
   * The TextureFormat of the bound read framebuffer's depth buffer, so that
   * a depth blit from or to it works (both sides of a depth blit must have
   * one format); where it has none of the depth formats above, the one
   * VTK 9.1's translucent pass would allocate for `window`.
   */
  static int GetReadDepthFormat(vtkOpenGLRenderWindow* window);

  /**
   * A full-screen quad and the fragment source its program was built from,
   * made by ReadyQuad and freed by ReleaseQuad.
   */
  struct FullScreenQuad
  {
    std::unique_ptr<vtkOpenGLQuadHelper> Helper;
    std::string Source;
    /**
     * Draw one triangle over the viewport instead of two (ReadyQuad
     * rebuilds the quad when this or AtFarPlane changed). On llvmpipe, a
     * loop whose trip count differs between neighbouring pixels ends early
     * in 2x2 groups that the quad's diagonal splits; a single triangle has
     * no inner edge, so such loops are safe. texCoord is 0..1 over the
     * viewport either way.
     */
    bool OneTriangle = false;
    /**
     * Put the quad at the far plane (window depth 1) instead of depth 0.5
     * (ReadyQuad rebuilds the quad when this or OneTriangle changed):
     * tested with GL_GREATER against a depth buffer, it covers the pixels
     * that hold a surface.
     */
    bool AtFarPlane = false;
    int BuiltVertexShader = -1; // (the flags the helper was built with; -1: none yet)
  };

  /**
   * Make `quad` a full-screen quad whose fragment shader is `fragmentSource`,
   * rebuilding it only when the source or the quad's flags (OneTriangle,
   * AtFarPlane) differ from those it was built with, and bind its program.
   * Returns the bound program, or nullptr (with an error) when the shader
   * does not compile.
   */
  static vtkShaderProgram* ReadyQuad(
    FullScreenQuad& quad, vtkOpenGLRenderWindow* window, const std::string& fragmentSource);

  /**
   * Makes `framebuffer` (created for `window` if there is none) one whose
   * recorded size is width x height: VTK's framebuffer object records its
   * size with its first attachment only, and VTK's own passes (the
   * translucent ones) size their buffers from it, so after a resize the
   * framebuffer is made anew.
   */
  static void FitFramebuffer(vtkSmartPointer<vtkOpenGLFramebufferObject>& framebuffer,
    vtkOpenGLRenderWindow* window, int width, int height);

  /**
   * Makes `framebuffer` (created for `window` if there is none) one whose
   * only attachment is the depth texture `depth`, with its draw and read
   * buffers off: a target for depth-only draws or a source for depth
   * blits. The bindings stay as they were. Returns whether it is complete.
   */
  static bool MakeDepthOnlyFramebuffer(vtkSmartPointer<vtkOpenGLFramebufferObject>& framebuffer,
    vtkOpenGLRenderWindow* window, vtkTextureObject* depth);

  /**
   * Fills the bound framebuffer's first colour target with `value` and its
   * other `targets - 1` with 0: what a pass writes when its shader failed,
   * so that consumers read a defined "no effect" instead of old texels.
   */
  static void ClearTargets(int targets, const float value[4]);

  /**
   * Releases a quad made by ReadyQuad and forgets its source, so that the
   * next ReadyQuad builds it again.
   */
  static void ReleaseQuad(FullScreenQuad& quad, vtkWindow* window);

  /**
   * Releases the GL resources of `object` (a texture or a framebuffer) in
   * `window` and drops it, if there is one.
   */
  template <typename T>
  static void Release(vtkSmartPointer<T>& object, vtkWindow* window)
  {
    if (object)
    {
      object->ReleaseGraphicsResources(window);
      object = nullptr;
    }
  }

  /**
   * Size in pixels of what a pass given `s` draws: the renderer's tiled
   * viewport, or where `s` carries a framebuffer (a pass such as
   * vtkSSAAPass draws its delegates into one of its own, and vtkCameraPass
   * then sets the viewport to its size), that framebuffer's size.
   */
  static void GetViewportSize(const vtkRenderState* s, int& width, int& height);

  /**
   * The view-space position of the surface seen at a pixel is
   *   P = origin(ndc) + depth * direction(ndc),
   * with depth the linear view depth (-z_view) and origin, direction affine
   * in the pixel's normalized device coordinates:
   *   origin(ndc) = O0 + ndc.x * Ox + ndc.y * Oy, likewise for direction.
   * Under perspective the origin is 0 and the direction is the frustum ray
   * scaled to z = -1; under parallel projection the direction is (0,0,-1)
   * and the origin spans the view rectangle. Computed in double precision
   * from the camera's projection matrix, so off-axis and parallel cameras
   * are exact. Sets uniforms `fxRayOrigin[3]` and `fxRayDirection[3]`
   * (vec3: constant, x, y) on `program` if it has them.
   */
  static void SetFrustumRayUniforms(vtkShaderProgram* program, vtkRenderer* renderer);

  /**
   * Rows the renderer covers in the image being made, whose viewport
   * shows `viewportRows` now: those, or in a scaled screenshot
   * (vtkWindowToImageFilter renders it tile by tile, each tile the
   * window's size, and a renderer may cover part of a tile) its viewport's
   * height in the whole scaled window. For effects sized in fractions or
   * pixels of the output (line widths, glow reach).
   */
  static int GetImageRows(vtkRenderer* renderer, int viewportRows);

  /**
   * Whether the renderer's window is drawing an image tile by tile (a
   * screenshot scaled by vtkWindowToImageFilter): an effect that reads a
   * neighbourhood of pixels then sees only the tile, and the image shows
   * seams where the tiles meet.
   */
  static bool IsRenderingTiles(vtkRenderer* renderer);

  /**
   * The view depths (-z_view) of the near and far planes of the projection
   * VTK draws with: the camera's projection matrix, which is the explicit
   * one where the camera uses one (its clipping range then says nothing).
   * False (range untouched) for a matrix of neither of VTK's two forms.
   */
  static bool ComputeViewDepthRange(vtkRenderer* renderer, double range[2]);

  /**
   * Whether the projection VTK draws with is parallel (the matrix's last
   * row is 0, 0, 0, 1; under an explicit matrix the camera's
   * ParallelProjection flag says nothing), and then the view's half height
   * in world units (1 / P11: the camera's ParallelScale when it makes the
   * matrix).
   */
  static bool ComputeParallelHalfHeight(vtkRenderer* renderer, double& halfHeight);

  /**
   * Ray terms as described above: origin[3][3] and direction[3][3] are the
   * constant, ndc.x and ndc.y coefficients. Exposed for tests and CPU code.
   */
  static void ComputeFrustumRay(vtkRenderer* renderer, double origin[3][3], double direction[3][3]);

  /**
   * Corner `i` (0..7) of the axis-aligned box `box` (xmin, xmax, ymin,
   * ymax, zmin, zmax): x from bit 0, y from bit 1, z from bit 2.
   */
  static void BoxCorner(const double box[6], int i, double corner[3]);

  /**
   * The data sets of `data`: the leaves of a composite dataset, in order,
   * or `data` itself (none for nullptr).
   */
  static std::vector<vtkDataObject*> Leaves(vtkDataObject* data);

  /**
   * `value` as a GLSL float literal, for code generated into shaders: with
   * a decimal point or an exponent always (a float, not an int), the point
   * a '.' whatever the program's locale, and 9 significant digits, which
   * give a float back exactly. (std::to_string and printf follow the C
   * locale: under a comma locale, such as a Qt application's in German,
   * they wrote "0,02", and the shader that read it did not compile.)
   * Callers pass finite values; a non-finite one gives 0.0, so that the
   * shader still compiles.
   */
  static std::string GLSLFloat(double value);

  /**
   * A string stream for generated shader code, in the classic "C" locale
   * whatever the program's global C++ locale (one with digit grouping
   * would write 1024 as "1.024", one with a decimal comma 0.5 as "0,5").
   */
  class CodeStream : public std::ostringstream
  {
  public:
    CodeStream() { this->imbue(std::locale::classic()); }
  };

  /** What GetDrawnBounds knows of where a prop draws. */
  enum DrawnBoundsKind
  {
    DrawsNothing,  // no geometry (empty data), or a 2D prop
    DrawsWithin,   // within the bounds returned
    DrawsAnywhere  // a 3D prop that reports no bounds
  };

  /**
   * The bounds of what `prop` draws (xmin, xmax, ymin, ymax, zmin, zmax):
   * its GetBounds, with what VTK leaves out put back. VTK's mappers bound
   * cells, and vtkPointGaussianMapper draws every point, with cells or
   * without (VTK 9.1 reports no bounds for composite input whose blocks
   * have no vertex cells); so for every point-gaussian actor, alone or a
   * part of an assembly (visible, UseBounds on), the bounds of its
   * polydata's points are added, through the actor's or the assembly
   * path's matrix (PathMatrix). Splats reach past their centres by their
   * radius: these are the centres' bounds, as VTK gives for polydata.
   * Returns DrawsWithin with the bounds; otherwise they are uninitialized.
   */
  static int GetDrawnBounds(vtkProp* prop, double bounds[6]);

  /**
   * Where `prop` draws: GetDrawnBounds grown by its splats' reach (a splat
   * reaches splatReach times its scale, or where splatReach < 0, its
   * triangle's corner, twice its TriangleScale: an opaque splat's extent),
   * down to the visible parts of assemblies. DrawsAnywhere where the
   * bounds do not hold what is drawn: a 3D prop without bounds, an
   * assembly part with UseBounds off or without bounds (its assembly's
   * bounds leave it out), points or lines wider than a pixel (they reach
   * past the bounds sideways, and sphere or tube impostors write depths
   * nearer the viewer). Used for the shadows' light views and the glow's
   * rectangle.
   */
  static int GetReachedBounds(vtkProp* prop, double splatReach, double bounds[6]);

  /**
   * The props through which `prop` draws volumes in VTK's volume step, each
   * holding the mapper's property keys: every vtkVolume on its paths (itself,
   * or a visible part of an assembly), or the prop itself for a
   * vtkLODProp3D, which hands its keys to the level it draws. Empty when it
   * draws none.
   */
  static std::vector<vtkProp*> GetVolumesDrawn(vtkProp* prop);

  /**
   * Whether the framebuffer holds depth from before this renderer's frame
   * (the layers below, or an earlier frame): the renderer preserves its
   * depth, or it or its window does not erase (vtkCameraPass clears only
   * when both do).
   */
  static bool KeepsEarlierDepth(vtkRenderer* renderer);

  /**
   * GetDrawnBounds of a vtkPropAssembly: the union of its visible parts'
   * that use bounds (DrawsAnywhere when one does).
   */
  static int GetPartsBounds(vtkPropAssembly* group, double bounds[6]);

  /**
   * The renderer's ComputeVisiblePropBounds (its event fires), with the
   * points of the visible props' point-gaussian actors added as in
   * GetDrawnBounds: uninitialized when nothing visible has bounds.
   */
  static void ComputeVisiblePropBounds(vtkRenderer* renderer, double bounds[6]);

  /**
   * The current matrix that places the last prop of `path`, one of the
   * paths of `prop`: the prop's own when the path is the prop alone (its
   * path holds a copy made once), the path's for an assembly's part (the
   * assembly rebuilds it), and the part's own where the path holds none
   * (a vtkPropAssembly's part). Null for a prop without a matrix.
   */
  static vtkMatrix4x4* PathMatrix(vtkProp* prop, vtkAssemblyPath* path);

  /**
   * Projects the 8 corners of the axis-aligned box `box` (xmin, xmax,
   * ymin, ymax, zmin, zmax) by `toClip` (row-major, to clip coordinates)
   * and returns the normalized device coordinates' range of those in front
   * of the camera (w > 0) in ndcMin / ndcMax (x, y, z). Returns how many
   * corners are not in front: 0, every corner projected; 8, the box is
   * wholly behind the camera; in between, it reaches the camera's plane and
   * may cover any part of the screen.
   */
  static int ProjectBox(const double box[6], const double toClip[16], double ndcMin[3],
    double ndcMax[3]);

  /**
   * While it lives, draws touch only `rect` (x0, y0, x1, y1 in pixels, ends
   * excluded) of the current target; with `clearColor`, the whole target is
   * cleared to it first. The scissor's box and switch and the clear colour
   * come back when it is destroyed.
   */
  class VTKFX_EXPORT ScissorScope
  {
  public:
    ScissorScope(vtkOpenGLState* state, const int rect[4], const float* clearColor = nullptr);

  private:
    vtkOpenGLState::ScopedglEnableDisable Enable;
    vtkOpenGLState::ScopedglScissor Box;
    vtkOpenGLState::ScopedglClearColor Clear;
  };

  /**
   * While it lives, draws go to `target` (the only colour attachment of
   * `framebuffer`, created on first use) over its whole size, with depth
   * test, blending and scissor off. The previous framebuffer, viewport and
   * those switches come back when it is destroyed.
   */
  class VTKFX_EXPORT RenderTargetScope
  {
  public:
    RenderTargetScope(vtkOpenGLRenderWindow* window,
      vtkSmartPointer<vtkOpenGLFramebufferObject>& framebuffer, vtkTextureObject* target);
    /** Several targets of one size, colour attachments 0, 1, ... in order. */
    RenderTargetScope(vtkOpenGLRenderWindow* window,
      vtkSmartPointer<vtkOpenGLFramebufferObject>& framebuffer,
      const std::vector<vtkTextureObject*>& targets);
    /**
     * No attachment at all, only a size (GL 4.3's framebuffer default width
     * and height): for draws whose shaders write buffers, not pixels.
     */
    RenderTargetScope(vtkOpenGLRenderWindow* window,
      vtkSmartPointer<vtkOpenGLFramebufferObject>& framebuffer, int width, int height);
    ~RenderTargetScope();

    /**
     * Whether the bound framebuffer can be drawn into (a target whose
     * storage OpenGL could not allocate leaves it incomplete).
     */
    bool IsComplete() const;

    /**
     * Until the scope ends, a quad drawn at the far plane
     * (FullScreenQuad::AtFarPlane) shades only the pixels where `depth`, a
     * depth texture of the target's size, is below 1: it becomes the depth
     * attachment, tested with GL_GREATER and never written. The test runs
     * before the fragment shader, and a software rasteriser (llvmpipe)
     * then skips whole 4x4 blocks, where a discard or a branch in the
     * shader saves nothing. Pixels left out keep what the target held:
     * clear it first to what the shader writes there. Returns false, and
     * does nothing, when `depth` is nullptr or not of the target's size.
     */
    bool SkipWhereDepthIsOne(vtkTextureObject* depth);

  private:
    RenderTargetScope(vtkOpenGLRenderWindow* window,
      vtkSmartPointer<vtkOpenGLFramebufferObject>& framebuffer,
      const std::vector<vtkTextureObject*>& targets, int width, int height);

    vtkOpenGLState* State;
    vtkOpenGLFramebufferObject* FrameBuffer;
    int Size[2];
    bool DepthAttached = false;
    vtkOpenGLState::ScopedglViewport Viewport;
    vtkOpenGLState::ScopedglDepthFunc DepthFunc;
    vtkOpenGLState::ScopedglDepthMask DepthMask;
    vtkOpenGLState::ScopedglEnableDisable DepthTest;
    vtkOpenGLState::ScopedglEnableDisable Blend;
    vtkOpenGLState::ScopedglEnableDisable Scissor;
  };

  /**
   * While it lives, draws blend onto the current framebuffer with
   * glBlendFuncSeparate(srcRGB, dstRGB, srcAlpha, dstAlpha), with depth
   * test and depth writes off (a post-process drawing over the image).
   * Those switches come back when it is destroyed.
   */
  class VTKFX_EXPORT BlendOntoScope
  {
  public:
    BlendOntoScope(vtkOpenGLRenderWindow* window, unsigned int srcRGB, unsigned int dstRGB,
      unsigned int srcAlpha, unsigned int dstAlpha);

  private:
    vtkOpenGLState::ScopedglEnableDisable Blend;
    vtkOpenGLState::ScopedglEnableDisable DepthTest;
    vtkOpenGLState::ScopedglBlendFuncSeparate BlendFunc;
    vtkOpenGLState::ScopedglDepthMask DepthMask;
  };

  /**
   * A depth mask for RenderTargetScope::SkipWhereDepthIsOne and what draws
   * it: the Depth32F texture, the framebuffer that holds it as its depth,
   * and the full-screen quad of the mask's shader.
   */
  struct DepthMask
  {
    vtkSmartPointer<vtkTextureObject> Texture;
    vtkSmartPointer<vtkOpenGLFramebufferObject> FrameBuffer;
    FullScreenQuad Quad;
  };

  /**
   * Draws `mask`: its texture (made a width x height Depth32F texture here)
   * takes, at every texel, the depth `fragmentShader` writes to
   * gl_FragDepth (0 where a later pass must run, 1 where it need not).
   * `setUniforms` sets the shader's uniforms (its textures activated by the
   * caller). State comes back as it was. Returns false when the framebuffer
   * or the shader cannot be made.
   */
  static bool DrawDepthMask(vtkOpenGLRenderWindow* window, DepthMask& mask, int width, int height,
    const std::string& fragmentShader, const std::function<void(vtkShaderProgram*)>& setUniforms);

  /** Frees the mask's quad, texture and framebuffer (which holds the texture while attached). */
  static void ReleaseDepthMask(DepthMask& mask, vtkWindow* window);

  /**
   * Drawing over flagged tiles only (see vtkFXTilePointsVS.glsl): an
   * earlier pass stores into Mask (R8, one texel per tile of TileSize
   * pixels square, bound as an image) a non-zero value at the tiles that
   * hold work, and a program built with ReadyTileProgram then runs at
   * those tiles' pixels only, one point per tile. On a software rasteriser
   * this skips what branches cannot: every pixel a primitive covers runs.
   */
  struct TilePoints
  {
    int TileSize = 8;
    vtkSmartPointer<vtkTextureObject> Mask;
    vtkSmartPointer<vtkOpenGLVertexArrayObject> Points; // no attributes
  };

  /**
   * Whether the current context can flag tiles of `tileSize` pixels: image
   * stores (GL_ARB_shader_image_load_store, which GLSL 1.50 shaders enable
   * by name), texture clears (GL 4.4) and points as wide as a tile.
   */
  static bool CanFlagTiles(int tileSize);

  /**
   * Makes `tiles.Mask` the size that covers width x height pixels and
   * clears it (no tile flagged). Returns false when it cannot be made.
   */
  static bool ClearTileMask(
    TilePoints& tiles, vtkOpenGLRenderWindow* window, int width, int height);

  /** The program of vtkFXTilePointsVS and `fragmentShader` (no inputs). */
  static vtkShaderProgram* ReadyTileProgram(
    vtkOpenGLRenderWindow* window, const std::string& fragmentShader);

  /**
   * Draws `program` (from ReadyTileProgram, bound) over the `size[0]` x
   * `size[1]` pixels from `origin` (the viewport's corner): over the tiles flagged in
   * `tiles.Mask` when `flagged` (and the target is not multisampled),
   * else over all of them as one triangle. Leaves texture units, viewport,
   * scissor and point size as they were. Returns whether it drew the
   * flagged tiles only.
   */
  static bool DrawTiles(TilePoints& tiles, vtkShaderProgram* program,
    vtkOpenGLRenderWindow* window, const int origin[2], const int size[2], bool flagged);

  /** Frees the mask and the vertex array. */
  static void ReleaseTilePoints(TilePoints& tiles, vtkWindow* window);

protected:
  vtkFXRenderUtilities() = default;
  ~vtkFXRenderUtilities() override = default;

private:
  vtkFXRenderUtilities(const vtkFXRenderUtilities&) = delete;
  void operator=(const vtkFXRenderUtilities&) = delete;
};

#endif
