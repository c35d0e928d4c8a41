// vtkFXToonBands: composite code of vtkFXToonPass ('@' is its prefix).
// Each light's diffuse factor is raised to the band above it, as in the
// deferred toon shader of seed 004 (0-0.05 -> 0, 0.05-0.25 -> 0.25, ...,
// 0.75-1 -> 1): with thresholds t[0] < ... < t[k-1], df < t[0] gives 0,
// t[i] <= df < t[i+1] gives t[i+1], df >= t[k-1] gives 1. The thresholds
// are compiled in, as a sum of steps, each adding the rise from the level
// below it (step(t[i], df) * (t[i+1] - t[i]), with t[k] = 1, and t[1] for
// the first step, whose level below is 0): a few instructions per light,
// no loop and no uniforms; changing them rebuilds the composite.
float @band(float df)
{
  float level = 0.0;
  //VTK::FXToonBands::Steps
  // NaN factors (degenerate normals) stay dark rather than lit.
  return df > 0.0 ? level : 0.0;
}
