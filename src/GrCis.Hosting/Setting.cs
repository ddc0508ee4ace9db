namespace GrCis.Hosting;

/// <summary>A render setting, as a front end names it to its user (an option, a control).</summary>
public enum Setting
{
  Size,
  SamplesPerPixel,
  Jitter,
  Shadows,
  Reflections,
  Refractions,
  Accel,
  Gamma,
  Threads,
  TileSize,
  Time,
  Algorithm,
}
