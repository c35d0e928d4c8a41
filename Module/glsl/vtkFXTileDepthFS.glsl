//VTK::System::Dec
// vtkFXTileDepthFS: each screen tile's range of linear depth, the nearest
// and the farthest surface among its FX_TILE x FX_TILE G-buffer pixels
// (0 = no surface; NaN counts as none), for vtkFXLightTiles: a light then
// counts for a tile only where its sphere's depth extent meets that range
// (the depth bounds of tiled deferred shading: Andersson, "DirectX 11
// Rendering in Battlefield 3", GDC 2011). A tile without a surface writes
// an empty range (nearest above farthest). One fragment per tile.

in vec2 texCoord;

uniform sampler2D fxLinearDepth;
uniform ivec2 fxSize; // G-buffer pixels

//VTK::Output::Dec

void main()
{
  if (texCoord.x < -1.0)
  {
    discard; // never: texCoord is read so that the quad's attribute stays bound
  }
  ivec2 first = ivec2(gl_FragCoord.xy) * FX_TILE;
  float nearest = 3.0e38;
  float farthest = 0.0;
  for (int y = 0; y < FX_TILE; ++y)
  {
    for (int x = 0; x < FX_TILE; ++x)
    {
      // (past the image's edge, its last texels again)
      float d = texelFetch(fxLinearDepth, min(first + ivec2(x, y), fxSize - 1), 0).r;
      bool covered = d > 0.0 && d < 3.0e38;
      nearest = covered ? min(nearest, d) : nearest;
      farthest = covered ? max(farthest, d) : farthest;
    }
  }
  gl_FragData[0] = vec4(nearest, farthest, 0.0, 1.0);
}
