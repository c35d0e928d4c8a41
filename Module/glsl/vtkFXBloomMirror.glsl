// vtkFXBloomMirror: where the bloom's filters read a level, mirrored at the
// image's edges. A level holds ceil(size / 2^k) texels, so past an odd
// size its last texel is partly outside the image, and mirroring at the
// texture's edge (GL_MIRRORED_REPEAT) would reflect light about a line
// up to half a texel of that level past the image's edge: an emitter at
// the top or right border then glowed up to 1.8 times too much (TestBloom).
// Reflecting the read position about the image's own edge, `extent`
// texels from 0, keeps the mirror exact at every level (the texture's
// wrap still mirrors at 0, which is the image's edge there).
// Positions and extent in the level's texels; returns a position in them.
vec2 fxMirrorInside(vec2 at, vec2 extent)
{
  return min(at, 2.0 * extent - at);
}
