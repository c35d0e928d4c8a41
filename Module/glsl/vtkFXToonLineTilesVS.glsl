//VTK::System::Dec
// vtkFXToonLineTilesVS: the feature lines are drawn only over the screen
// tiles that some marked pixel side can reach.
//
// A software rasteriser runs the fragment shader for every pixel a
// primitive covers, whatever the shader's branches, and lines cover a few
// percent of an image: drawn over the whole screen they cost as much as
// the rest of the frame's post-processing (1280x720 on llvmpipe). So the
// edges pass flags (fxTileMask) every tile (fxTileSize pixels) whose pixels
// can see one of its marks, and the lines are drawn as one instance of a
// quad per tile, flagged tiles only: an unflagged tile's quad collapses to
// a point and covers no pixel. Where GL lacks image stores there are no
// flags: fxEveryTile draws the tiles (then one, the size of the image);
// tests compare both.

uniform sampler2D fxTileMask;
uniform ivec2 fxTileSize;
uniform int fxTilesPerRow;
uniform ivec2 fxEdgeSize;
uniform bool fxEveryTile;

void main()
{
  ivec2 tile = ivec2(gl_InstanceID % fxTilesPerRow, gl_InstanceID / fxTilesPerRow);
  ivec2 corner = ivec2(gl_VertexID & 1, gl_VertexID >> 1); // a strip's four corners
  vec2 pixel = vec2(min((tile + corner) * fxTileSize, fxEdgeSize));
  bool drawn = fxEveryTile || texelFetch(fxTileMask, tile, 0).r > 0.0;
  gl_Position = drawn ? vec4(2.0 * pixel / vec2(fxEdgeSize) - 1.0, 0.0, 1.0)
                      : vec4(-2.0, -2.0, 0.0, 1.0);
}
