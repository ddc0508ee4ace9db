using System;
using OpenTK.Mathematics;

namespace Rendering.Accel;

/// <summary>Axis-aligned box; the empty box has Min &gt; Max.</summary>
internal struct Aabb
{
  public Vector3d Min, Max;

  public static readonly Aabb Empty = new()
  {
    Min = new Vector3d(double.PositiveInfinity),
    Max = new Vector3d(double.NegativeInfinity),
  };

  public Aabb(Vector3d min, Vector3d max)
  {
    Min = min;
    Max = max;
  }

  public readonly bool IsEmpty => Min.X > Max.X || Min.Y > Max.Y || Min.Z > Max.Z;

  public readonly bool IsFinite =>
    double.IsFinite(Min.X) && double.IsFinite(Min.Y) && double.IsFinite(Min.Z) &&
    double.IsFinite(Max.X) && double.IsFinite(Max.Y) && double.IsFinite(Max.Z);

  public readonly Vector3d Center => 0.5 * (Min + Max);

  public readonly double HalfArea
  {
    get
    {
      if (IsEmpty)
        return 0.0;
      Vector3d d = Max - Min;
      return d.X * d.Y + d.Y * d.Z + d.Z * d.X;
    }
  }

  public void Add(Vector3d p)
  {
    Min = new Vector3d(Math.Min(Min.X, p.X), Math.Min(Min.Y, p.Y), Math.Min(Min.Z, p.Z));
    Max = new Vector3d(Math.Max(Max.X, p.X), Math.Max(Max.Y, p.Y), Math.Max(Max.Z, p.Z));
  }

  public void Add(in Aabb b)
  {
    Min = new Vector3d(Math.Min(Min.X, b.Min.X), Math.Min(Min.Y, b.Min.Y), Math.Min(Min.Z, b.Min.Z));
    Max = new Vector3d(Math.Max(Max.X, b.Max.X), Math.Max(Max.Y, b.Max.Y), Math.Max(Max.Z, b.Max.Z));
  }

  public static Aabb Intersect(in Aabb a, in Aabb b) => new(
    new Vector3d(Math.Max(a.Min.X, b.Min.X), Math.Max(a.Min.Y, b.Min.Y), Math.Max(a.Min.Z, b.Min.Z)),
    new Vector3d(Math.Min(a.Max.X, b.Max.X), Math.Min(a.Max.Y, b.Max.Y), Math.Min(a.Max.Z, b.Max.Z)));

  /// <summary>Box of the 8 transformed corners (row vectors); infinite boxes stay infinite.</summary>
  public readonly Aabb Transformed(in Matrix4d m)
  {
    if (IsEmpty)
      return Empty;
    if (!IsFinite)
      return new Aabb(new Vector3d(double.NegativeInfinity), new Vector3d(double.PositiveInfinity));
    Aabb r = Empty;
    for (int c = 0; c < 8; c++)
    {
      var p = new Vector3d((c & 1) != 0 ? Max.X : Min.X, (c & 2) != 0 ? Max.Y : Min.Y, (c & 4) != 0 ? Max.Z : Min.Z);
      r.Add(Vector3d.TransformPosition(p, m));
    }
    return r;
  }

  /// <summary>
  /// Grown by a relative margin: records are computed in local space through a chain of matrices,
  /// the box in world space, so both carry rounding; the margin keeps the box conservative.
  /// </summary>
  public readonly Aabb Padded()
  {
    double scale = Math.Max(Math.Max(Math.Abs(Min.X), Math.Abs(Max.X)), Math.Max(Math.Max(Math.Abs(Min.Y), Math.Abs(Max.Y)), Math.Max(Math.Abs(Min.Z), Math.Abs(Max.Z))));
    double pad = 1.0e-9 * scale + 1.0e-12;
    var d = new Vector3d(pad);
    return new Aabb(Min - d, Max + d);
  }
}
