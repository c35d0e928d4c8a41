//VTK::System::Dec
// vtkFXTilePointsVS: a pass whose work lies in a few percent of its pixels
// (feature lines, the occupied texels of a shadow map) is drawn only over
// the tiles an earlier pass flagged.
//
// A software rasteriser runs the fragment shader for every pixel a
// primitive covers, whatever the shader's branches (llvmpipe runs both
// sides of an if for a block of pixels, even where none of them takes
// one). Drawn over a whole 1280x720 image, the feature lines cost as much
// as the rest of the frame's post-processing, and an AVSM resolve over a
// 1024^2 map whose casters reach a tenth of its tiles took twice as long
// as over those tiles alone. So the earlier pass flags (fxTileMask, one texel
// per tile, image stores) every tile (fxTileSize pixels square) with work,
// and this draws one point per tile, fxTileSize pixels wide (a square
// centred on the tile covers exactly its pixels), flagged tiles only: an
// unflagged tile's point lies outside the view and is clipped. One draw of
// points: as many instances of a quad cost llvmpipe about as much again as
// the lines themselves (2.5 ms for 14400 tiles at 1280x720). The viewport
// is padded to whole tiles, so that a partial tile's centre is inside it;
// the scissor box keeps its pixels in the image (see
// vtkFXRenderUtilities::DrawTiles). Where there are no flags (no image
// stores, or points too small for a tile), or the target is multisampled
// (a point's square has no rule for samples on its sides), fxEveryTile
// draws one triangle over the viewport: no edge inside it splits a 2x2
// block (on llvmpipe a loop whose trip count differs between neighbouring
// pixels goes wrong along a primitive's inner edge).

uniform sampler2D fxTileMask;
uniform int fxTileSize;
uniform int fxTilesPerRow;
uniform ivec2 fxPaddedSize; // the viewport: whole tiles
uniform bool fxEveryTile;

void main()
{
  if (fxEveryTile)
  {
    // (-1, -1), (3, -1), (-1, 3): the viewport is its lower-left half
    vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);
    gl_Position = vec4(4.0 * corner - 1.0, 0.0, 1.0);
    gl_PointSize = 1.0; // (not drawn as points)
    return;
  }
  ivec2 tile = ivec2(gl_VertexID % fxTilesPerRow, gl_VertexID / fxTilesPerRow);
  vec2 centre = (vec2(tile) + 0.5) * float(fxTileSize);
  bool drawn = texelFetch(fxTileMask, tile, 0).r > 0.0;
  gl_PointSize = float(fxTileSize);
  gl_Position = drawn ? vec4(2.0 * centre / vec2(fxPaddedSize) - 1.0, 0.0, 1.0)
                      : vec4(-2.0, -2.0, 0.0, 1.0);
}
