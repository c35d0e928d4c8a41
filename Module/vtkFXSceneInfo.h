/**
 * @class   vtkFXSceneInfo
 * @brief   What vtkFXPipelinePass's scene analysis found in one frame.
 *
 * The frame's props, listed by the steps that draw them (a prop can be in
 * more than one list: a 2D actor is an overlay with an opaque step, an
 * emissive prop is also opaque), and the lights that are on.
 * vtkFXEffectPass::HasWork receives it, so an effect decides from the scene
 * itself whether it has work (shadows cast by translucent data need
 * translucent props and a light; a glow needs emissive props). The
 * pointers are valid during the frame that produced them only.
 */
#ifndef vtkFXSceneInfo_h
#define vtkFXSceneInfo_h

#include <vector>

class vtkLight;
class vtkProp;
class vtkRenderer;

struct vtkFXSceneInfo
{
  vtkRenderer* Renderer = nullptr; // whose frame (its camera places the props on screen)
  std::vector<vtkProp*> OpaqueProps;        // captured by the G-buffer
  std::vector<vtkProp*> ForwardOpaqueProps; // opaque, drawn forward (vtkFXForwardOpaquePass)
  std::vector<vtkProp*> TranslucentProps;   // with translucent polygonal geometry
  // Every visible prop of the renderer with translucent polygonal geometry,
  // also those VTK's frustum culler left out of the frame (they can still
  // shadow what the camera sees).
  std::vector<vtkProp*> TranslucentViewProps;
  // Props VTK's volume step draws: volumes, vtkLODProp3D, assemblies
  // holding a volume.
  std::vector<vtkProp*> VolumeProps;
  // 2D props, widgets, actors of classes other than vtkOpenGLActor (which
  // may draw overlays: vtkCubeAxesActor's 2D mode)
  std::vector<vtkProp*> OverlayProps;
  // Props with light-independent colour: unlit opaque props (their colour is
  // their emission) and props with vtkFXGBufferPass::EMISSIVE_COLOR().
  std::vector<vtkProp*> EmissiveProps;
  std::vector<vtkLight*> Lights; // switched on, in VTK's order

  bool AnyLitProp = false;       // a captured prop with Lighting on and VTK's Phong model (not PBR)
  bool AnyAmbient = false;       // a lit captured prop with an ambient term
  bool AnySpecular = false;      // a lit captured prop with a specular term
  bool AnyEmissiveColor = false;    // an opaque prop has an EMISSIVE_COLOR
  bool AnyEmissionAboveOne = false; // an EMISSIVE_COLOR component exceeds 1
  double LargestColor = 1.0; // largest material colour component (diffuse, ambient, specular), at least 1
  bool AnyPerturbedNormal = false; // an opaque prop's shading normal is not its mesh normal
                                   // (vtkFXGBufferPass::PerturbsNormal)
  int LightingComplexity = 0;    // vtkOpenGLRenderer's, 0 when no light is on
  // The renderer keeps the depth of the layers below or of an earlier frame
  // (PreserveDepthBuffer, or Erase off on it or its window): what they
  // drew can hide the G-buffer's surfaces.
  bool KeepsLowerDepth = false;
  // The renderer peels volumes with its translucent geometry
  // (UseDepthPeeling and UseDepthPeelingForVolumes): VTK draws them in its
  // translucent step, not in the volume step.
  bool PeelsVolumes = false;
  bool UsesFXAA = false; // the renderer's UseFXAA (vtkFXAntiAliasingPass)
  bool Multisampled = false; // the framebuffer the renderer draws into has samples
  // The renderer's UseHiddenLineRemoval, with a wireframe prop to apply it to
  bool RemovesHiddenLines = false;
};

#endif
// VTK-HeaderTest-Exclude: vtkFXSceneInfo.h
