// vtkFXToonBands: composite code of vtkFXToonPass ('@' is its prefix).
// Each light's diffuse factor is raised to the band above it, as in the
// deferred toon shader of seed 004 (0-0.05 -> 0, 0.05-0.25 -> 0.25, ...,
// 0.75-1 -> 1): with thresholds t[0] < ... < t[k-1], df < t[0] gives 0,
// t[i] <= df < t[i+1] gives t[i+1], df >= t[k-1] gives 1.
uniform float @thresholds[16];
uniform int @count;

float @band(float df)
{
  float level = @count > 0 ? 0.0 : 1.0;
  for (int i = 0; i < @count; ++i)
  {
    if (df >= @thresholds[i])
    {
      level = i + 1 < @count ? @thresholds[i + 1] : 1.0;
    }
  }
  // NaN factors (degenerate normals) stay dark rather than lit.
  return df > 0.0 ? level : 0.0;
}
