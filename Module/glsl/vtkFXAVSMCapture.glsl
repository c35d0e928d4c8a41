// vtkFXAVSMCapture: appended to VTK's fragment shader of a translucent prop
// rendered from the light, after its colour (textures included) is final.
// The fragment becomes a node of its texel's list and is not drawn. A
// surface of opacity a is a segment of zero thickness with transmittance
// 1 - a (seed 003: "1 = completely translucent, 0 = fully opaque");
// opacity 0 (or NaN) casts nothing, opacity 1 blocks all (an optical depth
// of 1e4: exp(-1e4) is 0 in float). Past the buffer's capacity a fragment
// is counted and dropped; the pass grows the buffer for the next frame.
  {
    float fxAlpha = gl_FragData[0].a;
    if (fxAlpha > 0.0)
    {
      float fxTau = fxAlpha >= 1.0 ? 1e4 : min(-log(1.0 - fxAlpha), 1e4);
      uint fxIndex = atomicAdd(fxAVSMNodeCount, 1u);
      if (fxIndex < uint(fxAVSMCapacity))
      {
        ivec2 fxTexel = clamp(ivec2(gl_FragCoord.xy), ivec2(0), ivec2(fxAVSMSize - 1));
        int fxSlot = fxTexel.y * fxAVSMSize + fxTexel.x;
        uint fxHead = atomicExchange(fxAVSMHeads[fxSlot], fxIndex);
        fxAVSMNodes[fxIndex] = fxAVSMNode(fxLightDepthOfFragment(), fxTau, fxHead, 0u);
        atomicMax(fxAVSMLongestList, atomicAdd(fxAVSMCounts[fxSlot], 1u) + 1u);
      }
    }
    discard;
  }
