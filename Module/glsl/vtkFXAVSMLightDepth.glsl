// vtkFXAVSMLightDepth: depth along the light, 0 at a light view's near
// plane and 1 at its far plane, linear in distance for every view, so that
// vtkFXAVSMPass's bias means the same fraction of the light's depth range
// for a spot or point light (perspective) as for a directional one
// (orthographic), whose window depth is linear already. A perspective
// window depth crowds everything far from the light near 1: a slab 5 units
// above a floor 6 units from the light would sit 6e-4 away, under the bias.
uniform int fxAVSMPerspective; // the view being captured: 1 for a perspective one (a spot
                               // or point light's within 1000 radii of the props)
uniform vec2 fxAVSMNearFar;    // its near and far distances

// From clip coordinates of a light view (perspective: a spot or point
// light's; nearFar: its near and far distances).
float fxLightDepthFromClip(vec4 clip, int perspective, vec2 nearFar)
{
  return perspective != 0
    ? (clip.w - nearFar.x) / (nearFar.y - nearFar.x)
    : 0.5 * clip.z / clip.w + 0.5;
}
