/**
 * @class   vtkFXAVSMPass
 * @brief   Shadows cast by translucent props onto opaque and translucent ones: adaptive volumetric shadow maps.
 *
 * After Salvi, Vidimce, Lauritzen, Lefohn, "Adaptive Volumetric Shadow
 * Maps" (EGSR 2010; seed 003). Lights cast when they are on, are not
 * headlights and have a ShadowAttenuation above 0 (VTK's vtkLight
 * setting: the shadow darkens the light by that fraction of its
 * opacity); the MaximumNumberOfLights brightest cast (intensity times the
 * colour's largest component), each from where VTK shades it (a camera
 * light moved by the renderer's user light transform, as
 * vtkOpenGLRenderer moves it). Each casting light gets views of
 * ShadowMapSize texels square, side by side in one atlas:
 * - a directional light, one orthographic view along it, fitted to the
 *   visible props' bounding sphere;
 * - a spot light (a cone below 89 degrees), the perspective view of its
 *   cone, from just in front of it to the far side of the props; but
 *   farther than sqrt(2) radii from the props' centre, with a cone wider
 *   than their bounding sphere seen from there, the view aimed at and
 *   fitted to that sphere (as any other positional light's);
 * - any other positional light: farther than sqrt(2) times the props'
 *   bounding radius from their centre, one perspective view aimed at the
 *   sphere that just holds it; nearer, six perspective views of 90
 *   degrees, the faces of a cube around it;
 * - a positional light (spot or not) farther than 1000 radii: its rays are
 *   parallel there within 1e-3 rad, and it gets the directional light's
 *   view, along the line from it to the centre (a perspective view from
 *   1e8 radii cannot tell the props' depths apart in float).
 * The translucent props are rendered from every view. Every fragment, instead of being
 * drawn, joins its texel's linked list (shader storage buffers and an
 * atomic counter: OpenGL 4.3) as a segment along the light: a light-space
 * entry and exit depth and an optical depth, so that products of
 * transmittances are sums and never underflow. A surface is a segment of
 * zero length and optical depth -ln(1 - opacity); a point-gaussian splat
 * (vtkPointGaussianMapper) is a sphere of uniform density (SplatRadius),
 * each fragment the chord through it along the light ray. Then, per texel:
 * - AVSM (default): the lists are resolved into curves of NumberOfNodes
 *   nodes (4, 8 or 16) by the paper's rule (segments inserted in depth
 *   order; past the budget, the node whose removal changes the area under
 *   the transmittance curve least goes); up to NumberOfNodes / 2 surfaces
 *   per texel are kept exactly;
 * - Exact: the lists themselves are the deep shadow map; the look-up sums
 *   the optical depth of every segment in front of the receiver (the
 *   reference the AVSM is measured against), of lists up to
 *   30000 / (4 x casting lights) segments long (llvmpipe's loop budget;
 *   past that, the earliest captured segments of a list are left out).
 * Segments are inserted in order (of entry depth, then optical depth, then
 * exit depth), so the result does not depend on the order they arrived in.
 *
 * The look-up runs per G-buffer pixel (Bilinear: four texels blended, or
 * the nearest, in the view that sees the receiver) and writes each casting
 * light's visibility at the receiver, the output "visibility" (full
 * resolution, a channel per casting light: R32F for one, RG32F for two,
 * RGBA32F for three or four); in the composite it scales that light's contribution
 * (LightVisibility hook).
 *
 * Left out: volumes neither cast nor receive; PBR materials and opaque
 * props drawn forward (not in the G-buffer) receive no shadow.
 *
 * Work: some prop is translucent, a light can cast, and something
 * receives: an opaque prop, or, with TranslucentReceivers on, the
 * translucent props themselves (HasWork finds them, each frame:
 * vtkFXPipelinePass calls it); otherwise the pass, its buffers and the
 * G-buffer's linear depth it reads are left out. Without an opaque prop
 * the pass runs at the LightSpace stage (capture and resolve, no look-up,
 * no G-buffer): a particle cloud alone still shadows itself. HasWork sets
 * the stage each frame (AfterGBuffer with opaque props): SetStage has no
 * lasting effect on this pass. A list buffer too small for a frame (counted by the
 * atomic counter; no out-of-bounds write happens) drops the extra fragments
 * that frame, warns once and grows for the next one.
 *
 * Receivers: opaque props (the look-up above) and translucent props, whose
 * VTK shaders scale each casting light's terms by its visibility at each
 * fragment during the pipeline's translucent step. A translucent surface
 * does not shadow itself: casters within Bias of a fragment do not
 * count, and its look-up point moves along its normal, towards the light,
 * by 1.5 texels of the light's view (normal offset: a surface tilted to the
 * light would otherwise read itself in part of each texel, in stripes). VTK draws splats unlit; their diffuse colour is taken as the
 * brightest casting light's and scaled by its visibility at the splat's
 * centre (looked up once per splat), so a particle cloud shadows itself (a
 * splat by the half of its own sphere in front of its centre too).
 *
 * Cost, per view: the translucent props drawn once more at
 * ShadowMapSize^2, 16 bytes per captured fragment plus 8 per texel (list
 * head and count); the resolve, one pass over the atlas's tiles that
 * hold lists (CullResolveTiles; NumberOfNodes x 8 bytes per texel kept)
 * that reads each texel's list about n^2 / 4 times
 * for n segments (in order, four per walk; at most 64 inserted exactly,
 * the rest summed into one last segment; of lists over 15000 segments the
 * rest is left out, llvmpipe's loop budget again)
 * and inserts each segment into the curve; the look-up, one full-resolution pass of 1 (4
 * bilinear) curve reads per casting light, or a walk of the lists (Exact),
 * over the pixels that hold a surface (SkipBackground) inside the
 * rectangle where casters can shadow (CullLookUp).
 * A positional light without a cone inside the props costs six views.
 * A frame whose casters, casting lights and settings are those of the
 * frame before (the camera alone moved) keeps that frame's curves or lists
 * and costs the look-up only (ReuseShadowMaps, default on).
 */
#ifndef vtkFXAVSMPass_h
#define vtkFXAVSMPass_h

#include "vtkFXEffectPass.h"
#include "vtkFXModule.h"
#include "vtkFXSetGet.h" // for vtkFXSetClampMacro
#include "vtkFXRenderUtilities.h" // for the full-screen quads
#include "vtkSmartPointer.h"
#include "vtkTimeStamp.h" // for the shader stage time
#include "vtkWeakPointer.h" // for the buffers' window
#include "vtkWrappingHints.h" // for VTK_WRAPEXCLUDE

#include <array>
#include <string>
#include <vector>

class vtkCamera;
class vtkLight;
class vtkMatrix4x4;
class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLRenderer;
class vtkRenderer;
class vtkTextureObject;
class vtkTranslucentPass;

class VTKFX_EXPORT vtkFXAVSMPass : public vtkFXEffectPass
{
public:
  static vtkFXAVSMPass* New();
  vtkTypeMacro(vtkFXAVSMPass, vtkFXEffectPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Texels per side of each light view (16..4096, default 512).
   */
  vtkSetClampMacro(ShadowMapSize, int, 16, 4096);
  vtkGetMacro(ShadowMapSize, int);

  /**
   * Nodes per texel of the AVSM curve: 4, 8 (default) or 16; other values
   * are rounded up to one of those.
   */
  vtkSetClampMacro(NumberOfNodes, int, 4, 16);
  vtkGetMacro(NumberOfNodes, int);

  /**
   * What the lists are resolved into: AdaptiveNodes (default, the AVSM
   * curves of NumberOfNodes nodes) or RegularSlices, an opacity shadow map
   * (Kim and Neumann 2001) of 2 x NumberOfNodes regular slices of the
   * casters' depth range: the same bytes per texel, for comparison.
   */
  enum Representation
  {
    AdaptiveNodes = 0,
    RegularSlices = 1
  };
  vtkSetClampMacro(Representation, int, AdaptiveNodes, RegularSlices);
  vtkGetMacro(Representation, int);

  /**
   * Look up the uncompressed lists (the exact deep shadow map) instead of
   * the resolved curves (default off).
   */
  vtkSetMacro(Exact, bool);
  vtkGetMacro(Exact, bool);
  vtkBooleanMacro(Exact, bool);

  /**
   * Shadow the translucent props too (default on). Each of their fragments
   * looks the light up during VTK's translucent step: in Exact mode a walk
   * of the whole list, so a cloud of n layers costs n x n steps per pixel.
   */
  vtkSetMacro(TranslucentReceivers, bool);
  vtkGetMacro(TranslucentReceivers, bool);
  vtkBooleanMacro(TranslucentReceivers, bool);

  /**
   * Blend the four nearest texels' transmittances (default on) or take
   * the nearest.
   */
  vtkSetMacro(Bilinear, bool);
  vtkGetMacro(Bilinear, bool);
  vtkBooleanMacro(Bilinear, bool);

  /**
   * Resolve only the 8x8-texel tiles of the atlas that hold lists (default
   * on): the capture flags them with image stores
   * (GL_ARB_shader_image_load_store) and texture clears (GL 4.4 or
   * GL_ARB_clear_texture; points 8 pixels wide), the
   * curve textures are cleared to the empty curve and the resolve is drawn
   * as one point per flagged tile. Without those features, or with this
   * off, the resolve runs at every texel. The curves are the same either
   * way (the particles' resolve at 1024^2: 192 ms every texel, 93 culled,
   * with a tenth of the atlas's tiles flagged); off is for comparison.
   */
  vtkSetMacro(CullResolveTiles, bool);
  vtkGetMacro(CullResolveTiles, bool);
  vtkBooleanMacro(CullResolveTiles, bool);

  /**
   * Whether the last capture's resolve ran over the flagged tiles only
   * (false after a capture without a resolve: exact lists).
   */
  bool GetResolveTilesCulled() const { return this->ResolveTilesCulled; }

  /**
   * The last capture's flags (for tests and debugging): one R8 texel per
   * 8x8 tile of the atlas, nonzero where the resolve ran; nullptr when the
   * tiles were not culled.
   */
  vtkTextureObject* GetResolveTileMask();

  /**
   * Receiver depth offset towards the light, as a fraction of the visible
   * props' bounding-sphere diameter (0..0.1, default 1e-3; distances along
   * the light, for spot lights too): casters closer to a receiver than
   * this do not shadow it. (A fixed distance for every light: a point
   * light's depth range grows with its distance, and a fraction of it made
   * a far lamp's bias larger than the scene's details.)
   */
  vtkFXSetClampMacro(Bias, double, 0.0, 0.1);
  vtkGetMacro(Bias, double);

  /**
   * Lights that cast at most (1..4, default 1: the brightest; each costs
   * one view, six for a positional light without a cone within sqrt(2)
   * times the visible props' bounding radius).
   */
  vtkSetClampMacro(MaximumNumberOfLights, int, 1, 4);
  vtkGetMacro(MaximumNumberOfLights, int);

  /**
   * Radius of the uniform-density sphere a point-gaussian splat
   * (vtkPointGaussianMapper) casts as, in the splat's scale units (0.1..3,
   * default sqrt(3) = 1.732: for low opacity, the optical depth integrated
   * over the sphere's shadow equals that over VTK's default gaussian splat,
   * whose opacity falls as exp(-d^2 / 2)). The sphere's density makes its
   * centre chord as opaque as the splat's centre; fragments of the splat
   * outside the sphere cast nothing.
   */
  vtkFXSetClampMacro(SplatRadius, double, 0.1, 3.0);
  vtkGetMacro(SplatRadius, double);

  /**
   * Fragments the list buffer holds, per shadow-map texel, before it first
   * grows (1..1024, default 4); never more than GetCapacityLimit(). The
   * buffer grows for the frames that need more and does not shrink until
   * ReleaseGraphicsResources.
   */
  vtkSetClampMacro(InitialNodesPerTexel, int, 1, 1024);
  vtkGetMacro(InitialNodesPerTexel, int);

  ///@{
  /**
   * Of the last frame: fragments captured (counted, stored or not), the
   * list slots they asked for (each fragment takes a slot from one of
   * several counters, see vtkFXAVSMLists.glsl: the slots span a few
   * percent more than the fragments, at most twice as many), the buffer's
   * capacity in slots (a fragment each), the casting lights, the index of
   * the k-th (brightest first) among the lights that are on (-1: none),
   * and the views of all of them.
   */
  vtkGetMacro(CapturedFragments, vtkIdType);
  vtkGetMacro(UsedSlots, vtkIdType);
  vtkGetMacro(Capacity, vtkIdType);
  /**
   * The longest list of the last capture, in fragments (what the exact
   * look-up walks; at most 30000 / (4 x casting lights)).
   */
  vtkGetMacro(LongestList, vtkIdType);
  /**
   * The most fragments the list buffer can hold: what one shader storage
   * block can address (GL_MAX_SHADER_STORAGE_BLOCK_SIZE, 128 MiB on
   * llvmpipe: 8 Mi fragments of 16 bytes), at most 2^27. Fragments beyond
   * it are left out of the frame (a warning says so once). 0 before the
   * first frame.
   */
  vtkGetMacro(CapacityLimit, vtkIdType);
  int GetNumberOfCastingLights() const { return static_cast<int>(this->CastingLights.size()); }
  int GetCastingLightIndex(int k) const;
  int GetLightIndex() const { return this->GetCastingLightIndex(0); }
  int GetNumberOfViews() const { return static_cast<int>(this->Views.size()); }
  ///@}

  /**
   * Look the shadows up only at pixels that hold a surface (default on):
   * the look-up pass is depth-tested against the G-buffer's depth, which
   * rejects the background before the shader runs (on llvmpipe it halved
   * the look-up of scene:particles, 66 -> 34-52 ms at 1280x720, AVSM-8).
   * The result is the same either way; off is for comparison.
   */
  vtkSetMacro(SkipBackground, bool);
  vtkGetMacro(SkipBackground, bool);
  vtkBooleanMacro(SkipBackground, bool);

  /**
   * Look the shadows up only inside the screen rectangle that the region
   * the casters can shadow projects to (default on): in each light view,
   * the casters' extent across the view, two texels wider, from their
   * nearest depth to the farthest receiver, cut by each opaque prop's
   * bounds (so a large tilted ground does not carry it to its lowest
   * corner) and seen by the viewer; the whole screen when that region
   * reaches the viewer's plane. Splats count with their spheres
   * (SplatRadius times their scale; a receiver's with its triangle), which
   * VTK's bounds leave out. A prop drawn past what can be told of it (an
   * assembly part with UseBounds off, points or lines wider than a pixel,
   * whose impostors also write nearer depths) makes it the whole view
   * (casters) or screen (receivers). Pixels outside are unshadowed
   * without running the shader. The result is the same either way; off is
   * for comparison. (AVSM-8, 1280x720, three alternating runs: look-up 32
   * -> 23 ms on scene:particles, 30 -> 21 on scene:cloud, 29 -> 11 on
   * scene:isoshadow.)
   */
  vtkSetMacro(CullLookUp, bool);
  vtkGetMacro(CullLookUp, bool);
  vtkBooleanMacro(CullLookUp, bool);

  /**
   * The pixels (x0, y0, x1, y1, ends excluded) the last look-up ran over:
   * the whole target unless CullLookUp left some out.
   */
  const int* GetLookUpPixels() const { return this->LookUpPixels; }

  /**
   * Keep the shadow maps while nothing they are made from changes (default
   * on): the casters (each part's transform, property, textures and their
   * images, shader property and uniforms, mapper, clipping planes, splat
   * transfer functions and input data, and their pipelines upstream), the
   * casting lights' views (position, direction, cone, and the visible
   * props' bounds they are fitted to) and this pass's settings (its MTime).
   * A frame that only moves the camera then skips the capture and the
   * resolve and costs the look-up alone. A camera light (the light kit's)
   * moves with the camera, so its shadow maps are made again every frame,
   * as are those of data that changes, of scenes whose bounds follow
   * the camera (followers, cube axes), and of casters that pick what they
   * draw as they render (vtkLODActor, vtkQuadricLODActor, vtkLODProp3D,
   * ParaView's vtkPVLODActor). Data edited in place without
   * Modified() is not seen (VTK's own mappers keep their buffers then
   * too): call Modified() on this pass to make the maps again.
   */
  vtkSetMacro(ReuseShadowMaps, bool);
  vtkGetMacro(ReuseShadowMaps, bool);
  vtkBooleanMacro(ReuseShadowMaps, bool);

  /**
   * Whether the last frame reused the shadow maps of the frame before it
   * (no capture, no resolve; see ReuseShadowMaps).
   */
  vtkGetMacro(ReusedShadowMaps, bool);

  /**
   * Measure the capture, resolve and look-up of each frame with a
   * glFinish between them (default off: it stalls the pipeline; for
   * benchmarks).
   */
  vtkSetMacro(Profile, bool);
  vtkGetMacro(Profile, bool);
  vtkBooleanMacro(Profile, bool);

  /**
   * Milliseconds of the last frame's capture (0), resolve (1) and look-up
   * (2), with Profile on; 0 otherwise (and for the capture and resolve of a
   * frame that reused the shadow maps).
   */
  double GetPhaseMilliseconds(int phase) const
  {
    return (phase >= 0 && phase < 3) ? this->PhaseMilliseconds[phase] : 0.0;
  }

  /**
   * Bytes per shadow-map texel the curves keep between frames (8 x nodes;
   * 0 in Exact mode), and, of the last capture, the list bytes per texel
   * (16 per list slot the fragments took, plus 8 for the head and count;
   * the slots span a few percent more than the fragments: see
   * vtkFXAVSMLists.glsl's node counters).
   */
  int GetCurveBytesPerTexel() const { return this->Exact ? 0 : 8 * this->Nodes(); }
  double GetListBytesPerTexel() const;

  ///@{
  /**
   * The curves of the last frame (for tests and debugging), n = the nodes
   * used; the views lie side by side in them (the atlas, see
   * GetViewOrigin). AdaptiveNodes: textures 0 .. n/4 - 1 hold the nodes' depths
   * (RGBA32F, four nodes each, light depth 0..1 (vtkFXAVSMLightDepth.glsl), 3e38 for unused
   * nodes), n/4 .. n/2 - 1 their optical depths. RegularSlices: the n/2
   * textures hold the 2n slices' accumulated optical depths, nearest first.
   * None in Exact mode.
   */
  int GetNumberOfCurveTextures() const { return static_cast<int>(this->Curves.size()); }
  vtkTextureObject* GetCurveTexture(int i);
  ///@}

  ///@{
  /**
   * One light ray of the last frame, for plots and tests (call with the
   * window's context current, after a frame): the segments of texel
   * (x, y)'s list (entry light depths 0..1, see vtkFXAVSMLightDepth.glsl,
   * optical depths and, if asked, exit light depths, equal to the entry for
   * a surface; in list order), and its resolved curve (AdaptiveNodes: node depths and
   * optical depths; RegularSlices: the slices' accumulated optical depths
   * in `opticalDepths`, `depths` empty). False when there is none.
   */
  VTK_WRAPEXCLUDE bool GetTexelFragments(int x, int y, std::vector<double>& depths,
    std::vector<double>& opticalDepths, std::vector<double>* exitDepths = nullptr);
  VTK_WRAPEXCLUDE bool GetTexelCurve(
    int x, int y, std::vector<double>& depths, std::vector<double>& opticalDepths);
  /** The texel with the longest list of the last frame (false: none). */
  VTK_WRAPEXCLUDE bool GetLongestListTexel(int& x, int& y);
  /** The casters' light depth range (0..1) in a view, as the slices use it. */
  VTK_WRAPEXCLUDE void GetCasterDepthRange(double range[2], int view = 0) const;
  /** The atlas texel of a view's lower left corner (false: no such view). */
  VTK_WRAPEXCLUDE bool GetViewOrigin(int view, int origin[2]) const;
  ///@}

  bool HasWork(const vtkFXSceneInfo& scene) override;
  unsigned int GetRequiredChannels() override;
  Output GetOutput(const char* name) override;
  std::string GetCompositeCode(int hook) override;
  void BindCompositeResources(vtkShaderProgram* program, const std::string& prefix) override;
  void UnbindCompositeResources() override;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  // Shader replacement in the translucent props' shaders during capture.
  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;
  vtkMTimeType GetShaderStageMTime() override;

  /**
   * Translucent receivers: around the pipeline's translucent step, VTK's
   * shaders of the translucent props scale the casting light's diffuse and
   * specular terms by the transmittance at each fragment (read from the
   * curves, or the lists in Exact mode, as for opaque receivers).
   */
  bool GetShadesForward() override;
  void BeginForwardShading(const vtkRenderState* s) override;
  void EndForwardShading(const vtkRenderState* s) override;

protected:
  vtkFXAVSMPass();
  ~vtkFXAVSMPass() override;

  // One view of a casting light: a square of the atlas.
  struct LightView
  {
    vtkSmartPointer<vtkCamera> Camera;
    vtkSmartPointer<vtkMatrix4x4> Projection;
    vtkSmartPointer<vtkMatrix4x4> ViewToLight; // this frame's viewer view -> light clip
    bool Perspective = false;                 // a spot or point light's
    double NearFar[2] = { 1.0, 3.0 };         // its depth range
    float SliceRange[2] = { 0.0f, 1.0f };     // this frame's casters' light depths
    // The region its casters can shadow, in its normalized device
    // coordinates: their x, y range (within the view) and from their
    // nearest depth to the far plane (xmin, xmax, ymin, ymax, zmin, zmax).
    double ShadowedBox[6] = { -1.0, 1.0, -1.0, 1.0, -1.0, 1.0 };
    int Origin[2] = { 0, 0 };                 // atlas texel of its corner
  };
  // A casting light and its views.
  struct CastingLight
  {
    vtkLight* Light = nullptr;
    int Index = -1; // among the lights that are on
    int FirstView = 0;
    int NumberOfViews = 0;
    float Attenuation = 1.0f; // vtkLight::ShadowAttenuation
  };

  int Nodes() const; // NumberOfNodes rounded to 4, 8 or 16
  void FitLightViews(vtkOpenGLRenderer* ren);
  void AddView(const double position[3], const double direction[3], vtkMatrix4x4* projection,
    bool perspective, const double nearFar[2]);
  void ComputeCasterDepthRange(LightView& view) const; // its SliceRange and ShadowedBox
  // This frame's CasterExtents, from Casters.
  void MeasureCasters();
  struct CasterExtent
  {
    int Kind;          // GetDrawnBounds's, of Bounds
    double Bounds[6];  // what it draws (splats' centres)
    int ReachKind;     // DrawnExtent's, of Reached
    double Reached[6]; // what its splats reach
  };
  std::vector<CasterExtent> CasterExtents;
  // The viewer's pixels (x0, y0, x1, y1, ends excluded) of a width x height
  // target where a receiver can be in some view's ShadowedBox.
  void ComputeShadowedPixels(vtkOpenGLRenderer* ren, int width, int height, int rect[4]) const;
  bool EnsureBuffers(vtkOpenGLRenderWindow* window);
  // Texel (x, y) of an RGBA32F texture, by downloading it (GetTexelCurve's
  // way without GL 4.5's glGetTextureSubImage).
  static bool ReadTexel(vtkTextureObject* texture, int x, int y, float texel[4]);
  void BindBuffers(vtkShaderProgram* program);
  void Capture(const vtkRenderState* s, vtkOpenGLRenderWindow* window);
  // Both return false when their target could not be allocated.
  bool Resolve(vtkOpenGLRenderWindow* window);
  // Writes `emptyOutput` (the empty curve) over StaleTiles' flagged tiles
  // of the bound curves; false where it cannot (the caller clears all).
  bool EmptyStaleTiles(
    vtkOpenGLRenderWindow* window, const std::string& emptyOutput, const int origin[2]);
  // Eight node counters or one for the next capture, from this one's spread.
  void ChooseNodeCounters();
  bool LookUp(vtkOpenGLRenderer* ren, vtkOpenGLRenderWindow* window);
  void ComputeViewToLight(vtkOpenGLRenderer* ren);
  std::string CurveDefines(bool exact) const;
  std::string CurveCode() const;
  void SetCurveUniforms(vtkShaderProgram* program);
  void SetCaptureViewUniforms(vtkShaderProgram* program);
  void SetViewUniforms(vtkShaderProgram* program);
  // One channel per casting light (1, 2 or 4: R32F, RG32F, RGBA32F).
  int VisibilityChannels() const
  {
    const size_t lights = this->CastingLights.size();
    return lights <= 1 ? 1 : lights == 2 ? 2 : 4;
  }
  int VisibilityFormat() const;
  static double LightDepthFromNDC(const LightView& view, double ndcZ); // vtkFXAVSMLightDepth.glsl
  void ReleaseCurveUnits();
  void AbandonFrame(vtkOpenGLRenderWindow* window); // no shadows this frame
  // Everything the capture and the resolve read, as numbers: equal keys,
  // equal shadow maps (ReuseShadowMaps).
  std::vector<double> CaptureKey();

  int ShadowMapSize = 512;
  int NumberOfNodes = 8;
  bool Exact = false;
  int Representation = AdaptiveNodes;
  bool Bilinear = true;
  bool CullResolveTiles = true;
  double Bias = 1e-3;
  double BoundingDiameter = 2.0; // this frame's visible props' (FitLightViews)
  double SplatRadius = 1.7320508075688772;
  int MaximumNumberOfLights = 1;
  int InitialNodesPerTexel = 4;

  vtkIdType CapturedFragments = 0;
  vtkIdType Capacity = 0;
  bool SkipBackground = true;
  bool CullLookUp = true;
  std::vector<std::array<double, 6>> ReceiverBounds; // where this frame's opaque props are drawn
  bool ReceiversAnywhere = false; // one of them may be drawn anywhere
  int LookUpPixels[4] = { 0, 0, 0, 0 };
  vtkIdType CapacityLimit = 0;
  vtkIdType UsedSlots = 0;       // list slots the capture asked for (vtkFXAVSMLists.glsl)
  int CountersInUse = 8;         // node counters the next capture uses (ChooseNodeCounters)
  int CapturesSinceCountersChosen = 0;
  vtkIdType StoredFragments = 0; // slots this frame's lists hold (up to the capacity)
  bool WarnedOverflow = false;
  // The last error reported: each is said once, again only after a frame
  // without one (an error per frame would flood the output window).
  std::string LastError;
  bool ErrorThisFrame = false;
  void ReportError(const std::string& message);
  // The context the storage buffers (bare GL names) were made in, so that
  // the destructor can free them (vtkRenderer::SetPass does not release
  // the pass it replaces).
  vtkWeakPointer<vtkOpenGLRenderWindow> BuffersWindow;
  void ReleaseBuffers();
  bool Profile = false;
  bool TranslucentReceivers = true;
  bool Receiving = false; // between Begin- and EndForwardShading
  // Some prop is opaque this frame: the look-up runs after the G-buffer.
  // Without one, the pass runs at the LightSpace stage, captures and
  // resolves only, for the translucent receivers.
  bool OpaqueReceivers = true;
  bool FrameReady = false; // this frame's curves (or lists) are there to read
  vtkTimeStamp ShaderStageTime;
  double PhaseMilliseconds[3] = { 0.0, 0.0, 0.0 };
  bool WarnedUnsupported = false;
  bool WarnedGeometryLists = false; // Exact splats left unshadowed (said once)
  bool ReuseShadowMaps = true;
  bool ReusedShadowMaps = false;
  // The key of the shadow maps in the buffers and curves, while they are
  // whole (every fragment stored); empty when there are none to reuse.
  std::vector<double> KeptKey;

  // This frame's casters and casting lights (from HasWork), the lights'
  // views (from Render, kept for the translucent step) and the atlas
  // holding them (texels).
  std::vector<vtkProp*> Casters;
  std::vector<CastingLight> CastingLights;
  std::vector<LightView> Views;
  int AtlasSize[2] = { 0, 0 };
  int CaptureView = 0;  // the view being captured
  int AtlasColumns = 1; // views per row of the atlas

  vtkSmartPointer<vtkTranslucentPass> CasterPass;
  unsigned int Buffers[4] = { 0, 0, 0, 0 }; // heads, nodes, counter, counts per texel
  vtkIdType LongestList = 0;                // of the last capture
  vtkIdType BufferTexels = 0;
  vtkSmartPointer<vtkOpenGLFramebufferObject> CaptureFrameBuffer;
  std::vector<vtkSmartPointer<vtkTextureObject>> Curves; // depths then optical depths
  vtkSmartPointer<vtkOpenGLFramebufferObject> ResolveFrameBuffer;
  vtkSmartPointer<vtkTextureObject> Visibility;
  vtkSmartPointer<vtkOpenGLFramebufferObject> LookUpFrameBuffer;
  // The atlas's 8x8 tiles that hold lists (flagged by the capture): the
  // resolve runs there only (about a tenth of the particles' map).
  vtkFXRenderUtilities::TilePoints ResolveTiles;
  bool FlagResolveTiles = false;   // this frame's capture flags them
  bool ResolveTilesCulled = false; // the last resolve drew the flagged tiles only
  // The tiles the last culled resolve wrote, whose curves this frame's
  // resolve empties before drawing its own (the texture clear of every
  // texel took 7.5 ms at 1024^2 with 8 nodes), and whether the curves are
  // empty everywhere else: true after a culled resolve into curves that
  // were, false after anything else (allocation, a resolve of every texel).
  vtkFXRenderUtilities::TilePoints StaleTiles;
  bool CurvesEmptyOutsideResolved = false; // outside ResolveTiles' flags
  bool CurvesEmptyOutsideStale = false;    // outside StaleTiles' flags
  bool CurvesHoldSlices = false;           // the representation the curves were emptied for
  vtkFXRenderUtilities::FullScreenQuad LookUpQuad;

private:
  vtkFXAVSMPass(const vtkFXAVSMPass&) = delete;
  void operator=(const vtkFXAVSMPass&) = delete;
};

#endif
