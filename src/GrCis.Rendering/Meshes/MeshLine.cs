namespace Rendering;

/// <summary>A mesh query's line o + t·d with its inverse direction (1/d per axis, doubles), set up once per ray.</summary>
internal readonly struct MeshLine(double ox, double oy, double oz, double dx, double dy, double dz)
{
  public readonly double Ox = ox, Oy = oy, Oz = oz, Dx = dx, Dy = dy, Dz = dz;
  public readonly double Ix = 1.0 / dx, Iy = 1.0 / dy, Iz = 1.0 / dz;
}
