namespace Rendering;

/// <summary>One ray–triangle hit of a mesh query (<see cref="MeshBvh"/>, <see cref="MeshTriangles"/>).</summary>
internal struct MeshHit
{
  public double T;
  public int Triangle;
  public double U, V;   // barycentrics: p = (1 − u − v)·a + u·b + v·c
  public bool Front;    // the ray runs against the geometric normal (b − a) × (c − a)
}
