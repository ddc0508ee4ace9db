using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>
/// OpenTK 4's axis-aligned 2D box of doubles, kept ordered: the constructor sorts each axis, and setting
/// <see cref="Min"/> above <see cref="Max"/> (or Max below Min) drags the other corner along.
/// </summary>
[Serializable]
public struct Box2d : IEquatable<Box2d>, IFormattable
{
  Vector2d min, max;

  /// <summary>The box with corners <paramref name="min"/> and <paramref name="max"/>, sorted per axis so that Min ≤
  /// Max.</summary>
  public Box2d(Vector2d min, Vector2d max)
  {
    this.min = Vector2d.ComponentMin(min, max);
    this.max = Vector2d.ComponentMax(min, max);
  }

  /// <summary>The box with corners (minX, minY) and (maxX, maxY), sorted per axis so that Min ≤ Max.</summary>
  public Box2d(double minX, double minY, double maxX, double maxY)
    : this(new Vector2d(minX, minY), new Vector2d(maxX, maxY))
  {
  }

  /// <summary>The corner with the smallest coordinates; setting it above Max on an axis moves Max there too.</summary>
  public Vector2d Min
  {
    readonly get => min;
    set { if (value.X > max.X) max.X = value.X; if (value.Y > max.Y) max.Y = value.Y; min = value; }
  }

  /// <summary>The corner with the largest coordinates; setting it below Min on an axis moves Min there too.</summary>
  public Vector2d Max
  {
    readonly get => max;
    set { if (value.X < min.X) min.X = value.X; if (value.Y < min.Y) min.Y = value.Y; max = value; }
  }

  /// <summary>Max − Min; setting it keeps the centre.</summary>
  public Vector2d Size
  {
    readonly get => max - min;
    set { Vector2d c = Center; min = c - value * 0.5; max = c + value * 0.5; }
  }

  /// <summary>Half of <see cref="Size"/>; setting it keeps the centre.</summary>
  public Vector2d HalfSize { readonly get => Size / 2; set => Size = value * 2; }
  /// <summary>The centre, Min + HalfSize; setting it moves the box without resizing it.</summary>
  public Vector2d Center { readonly get => HalfSize + min; set => Translate(value - Center); }

  /// <summary>Strictly inside (boundary excluded), as OpenTK's obsolete one-argument form.</summary>
  public readonly bool Contains(Vector2d point) => ContainsExclusive(point);
  /// <summary>Whether <paramref name="point"/> is inside the box or on its boundary.</summary>
  public readonly bool ContainsInclusive(Vector2d point) => min.X <= point.X && point.X <= max.X && min.Y <= point.Y && point.Y <= max.Y;
  /// <summary>Whether <paramref name="point"/> is strictly inside the box (the boundary excluded).</summary>
  public readonly bool ContainsExclusive(Vector2d point) => min.X < point.X && point.X < max.X && min.Y < point.Y && point.Y < max.Y;
  /// <summary>Whether <paramref name="point"/> is inside the box, the boundary counting when
  /// <paramref name="boundaryInclusive"/> is true.</summary>
  public readonly bool Contains(Vector2d point, bool boundaryInclusive) => boundaryInclusive ? ContainsInclusive(point) : ContainsExclusive(point);
  /// <summary>Whether the boxes overlap (touching counts), despite the name.</summary>
  public readonly bool Contains(Box2d other) => max.X >= other.min.X && min.X <= other.max.X && max.Y >= other.min.Y && min.Y <= other.max.Y;

  /// <summary>The distance from <paramref name="point"/> to the box, 0 inside.</summary>
  public readonly double DistanceToNearestEdge(Vector2d point) =>
    new Vector2d(Math.Max(0.0, Math.Max(min.X - point.X, point.X - max.X)), Math.Max(0.0, Math.Max(min.Y - point.Y, point.Y - max.Y))).Length;

  /// <summary>Moves both corners by <paramref name="distance"/>.</summary>
  public void Translate(Vector2d distance) { min += distance; max += distance; }
  /// <summary>A copy moved by <paramref name="distance"/>.</summary>
  public readonly Box2d Translated(Vector2d distance) { Box2d b = this; b.Translate(distance); return b; }
  /// <summary>Scales the corners' offsets from <paramref name="anchor"/> by <paramref name="scale"/>.</summary>
  public void Scale(Vector2d scale, Vector2d anchor) { min = anchor + (min - anchor) * scale; max = anchor + (max - anchor) * scale; }
  /// <summary>A copy scaled about <paramref name="anchor"/>, as <see cref="Scale(Vector2d, Vector2d)"/>.</summary>
  public readonly Box2d Scaled(Vector2d scale, Vector2d anchor) { Box2d b = this; b.Scale(scale, anchor); return b; }

  /// <summary>Grows each side by <paramref name="size"/>; a negative size shrinks, at most to the centre.</summary>
  public void Inflate(Vector2d size)
  {
    size = Vector2d.ComponentMax(size, -HalfSize);
    Vector2d lo = min - size, hi = max + size;
    min = Vector2d.ComponentMin(lo, hi);
    max = Vector2d.ComponentMax(lo, hi);
  }

  /// <summary>A copy grown on each side by <paramref name="size"/>, as <see cref="Inflate(Vector2d)"/>.</summary>
  public readonly Box2d Inflated(Vector2d size) { Box2d b = this; b.Inflate(size); return b; }
  /// <summary>Grows the box just enough to hold <paramref name="point"/>.</summary>
  public void Extend(Vector2d point) { min = Vector2d.ComponentMin(min, point); max = Vector2d.ComponentMax(max, point); }
  /// <summary>A copy grown just enough to hold <paramref name="point"/>.</summary>
  public readonly Box2d Extended(Vector2d point) { Box2d b = this; b.Extend(point); return b; }

  /// <summary>Whether the two are equal, as <see cref="Equals(Box2d)"/> compares them.</summary>
  public static bool operator ==(Box2d left, Box2d right) => left.Equals(right);
  /// <summary>Whether the two differ, the negation of <see cref="Equals(Box2d)"/>.</summary>
  public static bool operator !=(Box2d left, Box2d right) => !left.Equals(right);
  /// <summary>Whether both corners equal the other's exactly (no tolerance).</summary>
  public readonly bool Equals(Box2d other) => min.Equals(other.min) && max.Equals(other.max);
  /// <inheritdoc/>
  public override readonly bool Equals(object? obj) => obj is Box2d b && Equals(b);
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
