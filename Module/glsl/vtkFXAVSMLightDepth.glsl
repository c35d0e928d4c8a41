// vtkFXAVSMLightDepth: depth along the light, 0 at the light view's near
// plane and 1 at its far plane, linear in distance for both views, so that
// vtkFXAVSMPass's bias means the same fraction of the light's depth range
// for a spot light (perspective) as for a directional one (orthographic),
// whose window depth is linear already. A perspective window depth crowds
// everything far from the light near 1: a slab 5 units above a floor 6
// units from the light would sit 6e-4 away, under the bias.
uniform int fxAVSMPerspective; // 1: spot light
uniform vec2 fxAVSMNearFar;    // the light view's near and far distances

// From clip coordinates of the light view.
float fxLightDepthFromClip(vec4 clip)
{
  return fxAVSMPerspective != 0
    ? (clip.w - fxAVSMNearFar.x) / (fxAVSMNearFar.y - fxAVSMNearFar.x)
    : 0.5 * clip.z / clip.w + 0.5;
}

