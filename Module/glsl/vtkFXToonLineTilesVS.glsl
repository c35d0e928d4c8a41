//VTK::System::Dec
// vtkFXToonLineTilesVS: the feature lines are drawn only over the screen
// tiles that some marked pixel side can reach.
//
// A software rasteriser runs the fragment shader for every pixel a
// primitive covers, whatever the shader's branches, and lines cover a few
// percent of an image: drawn over the whole screen they cost as much as
// the rest of the frame's post-processing (1280x720 on llvmpipe). So the
// edges pass flags (fxTileMask) every tile (fxTileSize pixels square)
// whose pixels can see one of its marks, and the lines are drawn as one
// point per tile, fxTileSize pixels wide (a square centred on the tile
// covers exactly its pixels), flagged tiles only: an unflagged tile's
// point lies outside the view and is clipped. One draw of points: as
// many instances of a quad cost llvmpipe about as much again as the lines
// themselves (2.5 ms for 14400 tiles at 1280x720). The viewport is padded
// to whole tiles, so that a partial tile's centre is inside it; the
// scissor box keeps its pixels in the image. Where there are no flags
// (no image stores, or points too small for a tile), or the target is
// multisampled (a point's square has no rule for samples on its sides),
// fxEveryTile draws one quad over the image (a strip of four vertices);
// tests compare both.

uniform sampler2D fxTileMask;
uniform int fxTileSize;
uniform int fxTilesPerRow;
uniform ivec2 fxPaddedSize; // the viewport: whole tiles
uniform bool fxEveryTile;

void main()
{
  if (fxEveryTile)
  {
    ivec2 corner = ivec2(gl_VertexID & 1, gl_VertexID >> 1); // a strip's four corners
    gl_Position = vec4(2.0 * vec2(corner) - 1.0, 0.0, 1.0);
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
