using System;
using System.Globalization;

namespace OpenTK.Mathematics;

/// <summary>
/// OpenTK 4's axis-aligned 2D box of floats, kept ordered: the constructor sorts each axis, and setting
/// <see cref="Min"/> above <see cref="Max"/> (or Max below Min) drags the other corner along.
/// </summary>
[Serializable]
public struct Box2 : IEquatable<Box2>, IFormattable
{
  Vector2 min, max;

  /// <summary>The box with corners <paramref name="min"/> and <paramref name="max"/>, sorted per axis so that Min ≤
  /// Max.</summary>
  public Box2(Vector2 min, Vector2 max)
  {
    this.min = Vector2.ComponentMin(min, max);
    this.max = Vector2.ComponentMax(min, max);
  }

  /// <summary>The box with corners (minX, minY) and (maxX, maxY), sorted per axis so that Min ≤ Max.</summary>
  public Box2(float minX, float minY, float maxX, float maxY)
    : this(new Vector2(minX, minY), new Vector2(maxX, maxY))
  {
  }

  /// <summary>The corner with the smallest coordinates; setting it above Max on an axis moves Max there too.</summary>
  public Vector2 Min
  {
    readonly get => min;
    set { if (value.X > max.X) max.X = value.X; if (value.Y > max.Y) max.Y = value.Y; min = value; }
  }

  /// <summary>The corner with the largest coordinates; setting it below Min on an axis moves Min there too.</summary>
  public Vector2 Max
  {
    readonly get => max;
    set { if (value.X < min.X) min.X = value.X; if (value.Y < min.Y) min.Y = value.Y; max = value; }
  }

  /// <summary>Max − Min; setting it keeps the centre.</summary>
  public Vector2 Size
  {
    readonly get => max - min;
    set { Vector2 c = Center; min = c - value * 0.5f; max = c + value * 0.5f; }
  }

  /// <summary>Half of <see cref="Size"/>; setting it keeps the centre.</summary>
  public Vector2 HalfSize { readonly get => Size / 2; set => Size = value * 2; }
  /// <summary>The centre, Min + HalfSize; setting it moves the box without resizing it.</summary>
  public Vector2 Center { readonly get => HalfSize + min; set => Translate(value - Center); }

  /// <summary>Strictly inside (boundary excluded), as OpenTK's obsolete one-argument form.</summary>
  public readonly bool Contains(Vector2 point) => ContainsExclusive(point);
  /// <summary>Whether <paramref name="point"/> is inside the box or on its boundary.</summary>
  public readonly bool ContainsInclusive(Vector2 point) => min.X <= point.X && point.X <= max.X && min.Y <= point.Y && point.Y <= max.Y;
  /// <summary>Whether <paramref name="point"/> is strictly inside the box (the boundary excluded).</summary>
  public readonly bool ContainsExclusive(Vector2 point) => min.X < point.X && point.X < max.X && min.Y < point.Y && point.Y < max.Y;
  /// <summary>Whether <paramref name="point"/> is inside the box, the boundary counting when
  /// <paramref name="boundaryInclusive"/> is true.</summary>
  public readonly bool Contains(Vector2 point, bool boundaryInclusive) => boundaryInclusive ? ContainsInclusive(point) : ContainsExclusive(point);
  /// <summary>Whether the boxes overlap (touching counts), despite the name.</summary>
  public readonly bool Contains(Box2 other) => max.X >= other.min.X && min.X <= other.max.X && max.Y >= other.min.Y && min.Y <= other.max.Y;

  /// <summary>The distance from <paramref name="point"/> to the box, 0 inside.</summary>
  public readonly float DistanceToNearestEdge(Vector2 point) =>
    new Vector2(Math.Max(0f, Math.Max(min.X - point.X, point.X - max.X)), Math.Max(0f, Math.Max(min.Y - point.Y, point.Y - max.Y))).Length;

  /// <summary>Moves both corners by <paramref name="distance"/>.</summary>
  public void Translate(Vector2 distance) { min += distance; max += distance; }
  /// <summary>A copy moved by <paramref name="distance"/>.</summary>
  public readonly Box2 Translated(Vector2 distance) { Box2 b = this; b.Translate(distance); return b; }
  /// <summary>Scales the corners' offsets from <paramref name="anchor"/> by <paramref name="scale"/>.</summary>
  public void Scale(Vector2 scale, Vector2 anchor) { min = anchor + (min - anchor) * scale; max = anchor + (max - anchor) * scale; }
  /// <summary>A copy scaled about <paramref name="anchor"/>, as <see cref="Scale(Vector2, Vector2)"/>.</summary>
  public readonly Box2 Scaled(Vector2 scale, Vector2 anchor) { Box2 b = this; b.Scale(scale, anchor); return b; }

  /// <summary>Grows each side by <paramref name="size"/>; a negative size shrinks, at most to the centre.</summary>
  public void Inflate(Vector2 size)
  {
    size = Vector2.ComponentMax(size, -HalfSize);
    Vector2 lo = min - size, hi = max + size;
    min = Vector2.ComponentMin(lo, hi);
    max = Vector2.ComponentMax(lo, hi);
  }

  /// <summary>A copy grown on each side by <paramref name="size"/>, as <see cref="Inflate(Vector2)"/>.</summary>
  public readonly Box2 Inflated(Vector2 size) { Box2 b = this; b.Inflate(size); return b; }
  /// <summary>Grows the box just enough to hold <paramref name="point"/>.</summary>
  public void Extend(Vector2 point) { min = Vector2.ComponentMin(min, point); max = Vector2.ComponentMax(max, point); }
  /// <summary>A copy grown just enough to hold <paramref name="point"/>.</summary>
  public readonly Box2 Extended(Vector2 point) { Box2 b = this; b.Extend(point); return b; }

  /// <summary>Whether the two are equal, as <see cref="Equals(Box2)"/> compares them.</summary>
  public static bool operator ==(Box2 left, Box2 right) => left.Equals(right);
  /// <summary>Whether the two differ, the negation of <see cref="Equals(Box2)"/>.</summary>
  public static bool operator !=(Box2 left, Box2 right) => !left.Equals(right);
  /// <summary>Whether both corners equal the other's exactly (no tolerance).</summary>
  public readonly bool Equals(Box2 other) => min.Equals(other.min) && max.Equals(other.max);
  /// <inheritdoc/>
  public override readonly bool Equals(object? obj) => obj is Box2 b && Equals(b);
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
