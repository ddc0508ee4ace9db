using System.Runtime.InteropServices;

namespace Rendering.Accel;

/// <summary>
/// One node of a flattened BVH. Leaf: <see cref="Count"/> &gt; 0 items from <see cref="Index"/> on.
/// Inner: <see cref="Count"/> == 0, left child is the next node, right child is <see cref="Index"/>.
/// </summary>
[StructLayout(LayoutKind.Sequential)]
internal struct BvhNode
{
  public double MinX, MinY, MinZ, MaxX, MaxY, MaxZ;
  public int Index;
  public int Count;
  public int Axis;
}
