using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// The shading point a light is sampled from: its position <see cref="P"/>, the normal <see cref="N"/> on the side
/// light is gathered from (the facing normal of the vertex) and the hit itself (for a student's light, which reads it).
/// The side travels here, so no light needs the hit's normal overwritten.
/// </summary>
internal readonly struct LightContext
{
  public readonly Vector3d P, N;
  public readonly Intersection? Hit;

  public LightContext(in Vector3d p, in Vector3d n, Intersection? hit)
  {
    P = p;
    N = n;
    Hit = hit;
  }
}
