// vtkFXAVSMCapture: appended to VTK's fragment shader of a translucent prop
// rendered from a light view (whose square of the atlas the viewport
// selects), after its colour (textures included) is final.
// The fragment becomes a segment of its texel's list and is not drawn.
// - A surface of opacity a is a segment of zero thickness with
//   transmittance 1 - a (seed 003: "1 = completely translucent, 0 = fully
//   opaque").
// - A point-gaussian splat (FX_SPLAT; its inputs are named VSOutput here,
//   VTK renames them GSOutput) is a sphere of uniform density, of
//   radius fxSplatRadius in the splat's scale units, centred on the splat
//   (seed 003's particles): the fragment whose ray passes at distance d
//   from the centre (its offset on the light-facing triangle in an
//   orthographic view; in a perspective one, where VTK turns the triangle
//   to face the light, d^2 = |o|^2 |c|^2 / (|c|^2 + |o|^2) for the centre c
//   seen from the light) is the chord of half-length r sqrt(1 - d^2 / R^2) around the splat's depth
//   (its extent along the view's axis: fxSplatScale carries the cosine to
//   the axis for a spot or point light's view),
//   and its optical depth is the centre chord's, -ln(1 - a_centre), times
//   the same fraction (uniform density: proportional to length). a_centre
//   is the splat's opacity before VTK's gaussian falloff (fxSplatFalloff;
//   1 for custom splat shaders, whose opacity is taken as it is).
// Opacity 0 (or NaN) casts nothing, opacity 1 blocks all (an optical depth
// of 1e4: exp(-1e4) is 0 in float). Past the buffer's capacity a fragment
// is counted and dropped; the pass grows the buffer for the next frame.
  {
    float fxAlpha = gl_FragData[0].a;
    // The fragment's light depth, from its clip coordinates (w = 1 /
    // gl_FragCoord.w; z / w from the window depth).
    float fxEntry = fxLightDepthFromClip(vec4(0.0, 0.0, (2.0 * gl_FragCoord.z - 1.0) / gl_FragCoord.w,
      1.0 / gl_FragCoord.w), fxAVSMPerspective, fxAVSMNearFar);
    float fxExit = fxEntry;
    float fxShare = 1.0;
#ifdef FX_SPLAT
    fxAlpha = min(fxAlpha / max(fxSplatFalloff, 1e-30), 1.0);
    float fxD2 = dot(offsetVCVSOutput, offsetVCVSOutput);
    if (fxAVSMPerspective != 0)
    {
      // VTK's triangle faces the light: the offset o is at right angles
      // to the centre c (both from the light), and the ray through c + o
      // passes c at |o| |c| / |c + o|.
      float fxC2 = dot(fxSplatCenterVSOutput, fxSplatCenterVSOutput);
      fxD2 *= fxC2 / max(fxC2 + fxD2, 1e-30);
    }
    fxD2 /= fxSplatRadius * fxSplatRadius;
    fxShare = sqrt(max(1.0 - fxD2, 0.0));
    float fxHalf = fxSplatRadius * fxSplatScaleVSOutput * fxShare /
      (fxAVSMNearFar.y - fxAVSMNearFar.x);
    fxEntry -= fxHalf;
    fxExit += fxHalf;
#endif
    if (fxAlpha > 0.0 && fxShare > 0.0)
    {
      float fxTau = fxAlpha >= 1.0 ? 1e4 : min(-log(1.0 - fxAlpha) * fxShare, 1e4);
      uint fxIndex = fxAVSMNewSlot(ivec2(gl_FragCoord.xy));
      if (fxIndex < uint(fxAVSMCapacity))
      {
        ivec2 fxTexel = clamp(ivec2(gl_FragCoord.xy), ivec2(0), fxAVSMAtlas - 1);
        int fxSlot = fxTexel.y * fxAVSMAtlas.x + fxTexel.x;
#ifdef FX_TILE_FLAGS
        // The resolve runs at flagged tiles only (vtkFXTilePointsVS).
        imageStore(fxAVSMTileMask, fxTexel / FX_TILE_FLAGS, vec4(1.0));
#endif
        uint fxHead = atomicExchange(fxAVSMHeads[fxSlot], fxIndex);
        fxAVSMNodes[fxIndex] = fxAVSMNode(fxEntry, fxTau, fxHead, fxExit);
        // The frame's longest list: atomically only when this one may be
        // it. A plain read of the maximum may be stale but is never above
        // it, so no longer list is missed; one atomic on one word for every
        // fragment took a third of the capture on llvmpipe.
        uint fxLength = atomicAdd(fxAVSMCounts[fxSlot], 1u) + 1u;
        if (fxLength > fxAVSMLongestList)
        {
          atomicMax(fxAVSMLongestList, fxLength);
        }
      }
    }
    discard;
  }
