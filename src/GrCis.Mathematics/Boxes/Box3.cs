using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>
/// OpenTK 4's axis-aligned 3D box of floats, kept ordered: the constructor sorts each axis, and setting
/// <see cref="Min"/> above <see cref="Max"/> (or Max below Min) drags the other corner along.
/// </summary>
[Serializable]
public struct Box3 : IEquatable<Box3>, IFormattable
{
  Vector3 min, max;

  /// <summary>The box with corners <paramref name="min"/> and <paramref name="max"/>, sorted per axis so that Min ≤
  /// Max.</summary>
  public Box3(Vector3 min, Vector3 max)
  {
    this.min = Vector3.ComponentMin(min, max);
    this.max = Vector3.ComponentMax(min, max);
  }

  /// <summary>The box with corners (minX, minY, minZ) and (maxX, maxY, maxZ), sorted per axis so that Min ≤
  /// Max.</summary>
  public Box3(float minX, float minY, float minZ, float maxX, float maxY, float maxZ)
    : this(new Vector3(minX, minY, minZ), new Vector3(maxX, maxY, maxZ))
  {
  }

  /// <summary>The corner with the smallest coordinates; setting it above Max on an axis moves Max there too.</summary>
  public Vector3 Min
  {
    readonly get => min;
    set { if (value.X > max.X) max.X = value.X; if (value.Y > max.Y) max.Y = value.Y; if (value.Z > max.Z) max.Z = value.Z; min = value; }
  }

  /// <summary>The corner with the largest coordinates; setting it below Min on an axis moves Min there too.</summary>
  public Vector3 Max
  {
    readonly get => max;
    set { if (value.X < min.X) min.X = value.X; if (value.Y < min.Y) min.Y = value.Y; if (value.Z < min.Z) min.Z = value.Z; max = value; }
  }

  /// <summary>Max − Min; setting it keeps the centre.</summary>
  public Vector3 Size
  {
    readonly get => max - min;
    set { Vector3 c = Center; min = c - value * 0.5f; max = c + value * 0.5f; }
  }

  /// <summary>Half of <see cref="Size"/>; setting it keeps the centre.</summary>
  public Vector3 HalfSize { readonly get => Size / 2; set => Size = value * 2; }
  /// <summary>The centre, Min + HalfSize; setting it moves the box without resizing it.</summary>
  public Vector3 Center { readonly get => HalfSize + min; set => Translate(value - Center); }

  /// <summary>Strictly inside (boundary excluded), as OpenTK's obsolete one-argument form.</summary>
  public readonly bool Contains(Vector3 point) => ContainsExclusive(point);
  /// <summary>Whether <paramref name="point"/> is inside the box or on its boundary.</summary>
  public readonly bool ContainsInclusive(Vector3 point) => min.X <= point.X && point.X <= max.X && min.Y <= point.Y && point.Y <= max.Y && min.Z <= point.Z && point.Z <= max.Z;
  /// <summary>Whether <paramref name="point"/> is strictly inside the box (the boundary excluded).</summary>
  public readonly bool ContainsExclusive(Vector3 point) => min.X < point.X && point.X < max.X && min.Y < point.Y && point.Y < max.Y && min.Z < point.Z && point.Z < max.Z;
  /// <summary>Whether <paramref name="point"/> is inside the box, the boundary counting when
  /// <paramref name="boundaryInclusive"/> is true.</summary>
  public readonly bool Contains(Vector3 point, bool boundaryInclusive) => boundaryInclusive ? ContainsInclusive(point) : ContainsExclusive(point);
  /// <summary>Whether the boxes overlap (touching counts), despite the name.</summary>
  public readonly bool Contains(Box3 other) => max.X >= other.min.X && min.X <= other.max.X && max.Y >= other.min.Y && min.Y <= other.max.Y && max.Z >= other.min.Z && min.Z <= other.max.Z;

  /// <summary>The distance from <paramref name="point"/> to the box, 0 inside.</summary>
  public readonly float DistanceToNearestEdge(Vector3 point) =>
    new Vector3(Math.Max(0f, Math.Max(min.X - point.X, point.X - max.X)), Math.Max(0f, Math.Max(min.Y - point.Y, point.Y - max.Y)), Math.Max(0f, Math.Max(min.Z - point.Z, point.Z - max.Z))).Length;

  /// <summary>Moves both corners by <paramref name="distance"/>.</summary>
  public void Translate(Vector3 distance) { min += distance; max += distance; }
  /// <summary>A copy moved by <paramref name="distance"/>.</summary>
  public readonly Box3 Translated(Vector3 distance) { Box3 b = this; b.Translate(distance); return b; }
  /// <summary>Scales the corners' offsets from <paramref name="anchor"/> by <paramref name="scale"/>.</summary>
  public void Scale(Vector3 scale, Vector3 anchor) { min = anchor + (min - anchor) * scale; max = anchor + (max - anchor) * scale; }
  /// <summary>A copy scaled about <paramref name="anchor"/>, as <see cref="Scale(Vector3, Vector3)"/>.</summary>
  public readonly Box3 Scaled(Vector3 scale, Vector3 anchor) { Box3 b = this; b.Scale(scale, anchor); return b; }

  /// <summary>Grows each side by <paramref name="size"/>; a negative size shrinks, at most to the centre.</summary>
  public void Inflate(Vector3 size)
  {
    size = Vector3.ComponentMax(size, -HalfSize);
    Vector3 lo = min - size, hi = max + size;
    min = Vector3.ComponentMin(lo, hi);
    max = Vector3.ComponentMax(lo, hi);
  }

  /// <summary>A copy grown on each side by <paramref name="size"/>, as <see cref="Inflate(Vector3)"/>.</summary>
  public readonly Box3 Inflated(Vector3 size) { Box3 b = this; b.Inflate(size); return b; }
  /// <summary>Grows the box just enough to hold <paramref name="point"/>.</summary>
  public void Extend(Vector3 point) { min = Vector3.ComponentMin(min, point); max = Vector3.ComponentMax(max, point); }
  /// <summary>A copy grown just enough to hold <paramref name="point"/>.</summary>
  public readonly Box3 Extended(Vector3 point) { Box3 b = this; b.Extend(point); return b; }

  /// <summary>Whether the two are equal, as <see cref="Equals(Box3)"/> compares them.</summary>
  public static bool operator ==(Box3 left, Box3 right) => left.Equals(right);
  /// <summary>Whether the two differ, the negation of <see cref="Equals(Box3)"/>.</summary>
  public static bool operator !=(Box3 left, Box3 right) => !left.Equals(right);
  /// <summary>Whether both corners equal the other's exactly (no tolerance).</summary>
  public readonly bool Equals(Box3 other) => min.Equals(other.min) && max.Equals(other.max);
  /// <inheritdoc/>
  public override readonly bool Equals(object? obj) => obj is Box3 b && Equals(b);
  /// <inheritdoc/>
  public override readonly int GetHashCode() => HashCode.Combine(min, max);
  /// <inheritdoc/>
  public override readonly string ToString() => ToString(null, null);
  /// <summary>As <see cref="ToString(string, IFormatProvider)"/> with the current culture.</summary>
  public readonly string ToString(string? format) => ToString(format, null);
  /// <summary>As <see cref="ToString(string, IFormatProvider)"/> with no format.</summary>
  public readonly string ToString(IFormatProvider? formatProvider) => ToString(null, formatProvider);
  /// <summary>"min - max"; the corners are written as their vectors write themselves.</summary>
  public readonly string ToString(string? format, IFormatProvider? formatProvider) =>
    string.Format(formatProvider ?? CultureInfo.CurrentCulture, "{0} - {1}", min, max);
}
