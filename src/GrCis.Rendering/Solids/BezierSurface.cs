using System;
using System.Collections.Generic;
using OpenTK.Mathematics;
using Rendering.Accel;

namespace Rendering;

/// <summary>
/// K × L bicubic Bézier patches sharing a control net of (3K + 1) rows × (3L + 1) columns,
/// row-major xyz triples. Patch (k, l) uses rows 3k..3k+3 and columns 3l..3l+3; its parameter
/// u runs along the columns, v along the rows, and texture coordinates are (l + u, k + v).
/// Each patch is subdivided (de Casteljau) into a hierarchy of nearly flat pieces with boxes
/// from their control points; the ray is then solved on the exact surface by Newton iteration
/// started in every piece whose box it crosses. The surface is open: Enter = Front = the ray
/// runs against the normal ∂S/∂u × ∂S/∂v. Both APIs (the list and the fast path's first record) share one
/// search, <see cref="Collect"/>, so they give the same records.
/// </summary>
public partial class BezierSurface : DefaultSceneNode, ISolid, IRecordSolid
{
  /// <summary>Exact surface normals (otherwise the flat normal of the piece that was hit).</summary>
  public bool PreciseNormals { get; set; }

  /// <summary>
  /// Pieces are subdivided at least until their box's squared diagonal is below this or they are flat; one threshold
  /// for all surfaces built afterwards, as in GrCis. Code sets it as <c>BezierSurface.Epsilon</c> (GrCis until May 2020,
  /// static) or <c>surface.Epsilon</c> (since June 2020, an instance property setting the same threshold): a class cannot
  /// have a static and an instance property of one name, so both are extension properties
  /// (<see cref="BezierSurfaceStaticEpsilon"/>, <see cref="BezierSurfaceInstanceEpsilon"/>).
  /// </summary>
  internal static double SharedEpsilon { get; set; } = 1.0e-3;

  readonly int patchesK, patchesL;
  readonly Vector3d[][] control;   // per patch: 16 points, index 4·row + column
  readonly List<Piece> pieces = new();
  readonly List<int> roots = new();   // root piece of each patch
  Vector3d minV, maxV;

  sealed class Piece
  {
    public Vector3d Min, Max, FlatNormal;
    public double U0, U1, V0, V1;
    public int Patch;
    public int Left = -1, Right = -1;
  }

  /// <summary>A hit found by <see cref="Collect"/>: ray parameter, the piece whose Newton start found it, (u, v).</summary>
  struct Found
  {
    public double T;
    public int Piece;
    public double U, V;
  }

  /// <summary>The hit's patch and parameters, kept until completion.</summary>
  sealed class Hit
  {
    public int Patch;
    public double U, V;
    public Vector3d FlatNormal;
  }

  /// <summary>A surface of K × L bicubic Bézier patches (see <see cref="BezierSurface"/>); subdivides them into pieces at once.</summary>
  /// <param name="K">Patches along v: the net has 3K + 1 rows.</param>
  /// <param name="L">Patches along u: the net has 3L + 1 columns.</param>
  /// <param name="controlPoints">The control net, row by row, three numbers (x, y, z) per point: at least 3 (3K + 1)(3L + 1) numbers.</param>
  /// <exception cref="ArgumentOutOfRangeException"><paramref name="K"/> or <paramref name="L"/> is not positive.</exception>
  /// <exception cref="ArgumentException"><paramref name="controlPoints"/> is too short.</exception>
  public BezierSurface(int K, int L, double[] controlPoints)
  {
    if (K <= 0 || L <= 0)
      throw new ArgumentOutOfRangeException(K <= 0 ? nameof(K) : nameof(L), "The number of patches must be positive.");
    ArgumentNullException.ThrowIfNull(controlPoints);
    int columns = 3 * L + 1, rows = 3 * K + 1;
    if (controlPoints.Length < 3 * rows * columns)
      throw new ArgumentException($"{K}×{L} patches need {3 * rows * columns} numbers ({rows}×{columns} points), got {controlPoints.Length}.", nameof(controlPoints));

    PreciseNormals = true;
    patchesK = K;
    patchesL = L;
    control = new Vector3d[K * L][];
    minV = Vector3d.PositiveInfinity;
    maxV = Vector3d.NegativeInfinity;
    for (int k = 0; k < K; k++)
      for (int l = 0; l < L; l++)
      {
        var p = new Vector3d[16];
        for (int i = 0; i < 4; i++)
          for (int j = 0; j < 4; j++)
          {
            int o = 3 * ((3 * k + i) * columns + 3 * l + j);
            p[4 * i + j] = new Vector3d(controlPoints[o], controlPoints[o + 1], controlPoints[o + 2]);
            minV = Vector3d.ComponentMin(minV, p[4 * i + j]);
            maxV = Vector3d.ComponentMax(maxV, p[4 * i + j]);
          }
        int patch = k * L + l;
        control[patch] = p;
        roots.Add(Subdivide(patch, p, 0.0, 1.0, 0.0, 1.0, 0));
      }
  }

  int Subdivide(int patch, Vector3d[] p, double u0, double u1, double v0, double v1, int depth)
  {
    var piece = new Piece { Patch = patch, U0 = u0, U1 = u1, V0 = v0, V1 = v1 };
    piece.Min = piece.Max = p[0];
    for (int i = 1; i < 16; i++)
    {
      piece.Min = Vector3d.ComponentMin(piece.Min, p[i]);
      piece.Max = Vector3d.ComponentMax(piece.Max, p[i]);
    }
    Vector3d flat = Vector3d.Cross(p[15] - p[0], p[12] - p[3]);
    piece.FlatNormal = flat;
    int index = pieces.Count;
    pieces.Add(piece);

    double diag2 = (piece.Max - piece.Min).LengthSquared;
    if (depth >= 16 || (depth >= 2 && (diag2 < SharedEpsilon || Flatness(p) <= 0.02 * Math.Sqrt(diag2))))
      return index;

    // Halve along the longer parameter direction of the control net.
    double along = (p[3] - p[0]).Length + (p[15] - p[12]).Length;
    double across = (p[12] - p[0]).Length + (p[15] - p[3]).Length;
    var a = new Vector3d[16];
    var b = new Vector3d[16];
    if (along >= across)
    {
      SplitCurves(p, a, b, stride: 1, step: 4);
      double um = 0.5 * (u0 + u1);
      piece.Left = Subdivide(patch, a, u0, um, v0, v1, depth + 1);
      piece.Right = Subdivide(patch, b, um, u1, v0, v1, depth + 1);
    }
    else
    {
      SplitCurves(p, a, b, stride: 4, step: 1);
      double vm = 0.5 * (v0 + v1);
      piece.Left = Subdivide(patch, a, u0, u1, v0, vm, depth + 1);
      piece.Right = Subdivide(patch, b, u0, u1, vm, v1, depth + 1);
    }
    return index;
  }

  /// <summary>De Casteljau halving of the four cubic curves (points at offset + stride·i, curves at offset step·c).</summary>
  static void SplitCurves(Vector3d[] p, Vector3d[] left, Vector3d[] right, int stride, int step)
  {
    for (int c = 0; c < 4; c++)
    {
      int o = c * step;
      Vector3d p0 = p[o], p1 = p[o + stride], p2 = p[o + 2 * stride], p3 = p[o + 3 * stride];
      Vector3d p01 = 0.5 * (p0 + p1), p12 = 0.5 * (p1 + p2), p23 = 0.5 * (p2 + p3);
      Vector3d p012 = 0.5 * (p01 + p12), p123 = 0.5 * (p12 + p23), mid = 0.5 * (p012 + p123);
      left[o] = p0; left[o + stride] = p01; left[o + 2 * stride] = p012; left[o + 3 * stride] = mid;
      right[o] = mid; right[o + stride] = p123; right[o + 2 * stride] = p23; right[o + 3 * stride] = p3;
    }
  }

  /// <summary>Largest distance of a control point from the bilinear patch through the four corners.</summary>
  static double Flatness(Vector3d[] p)
  {
    double max = 0.0;
    for (int i = 0; i < 4; i++)
      for (int j = 0; j < 4; j++)
      {
        double s = j / 3.0, t = i / 3.0;
        Vector3d bilinear = (1 - t) * ((1 - s) * p[0] + s * p[3]) + t * ((1 - s) * p[12] + s * p[15]);
        max = Math.Max(max, (p[4 * i + j] - bilinear).Length);
      }
    return max;
  }

  /// <summary>Point and partial derivatives of patch <paramref name="patch"/> at (u, v) (also the tessellation's points).</summary>
  internal void Evaluate(int patch, double u, double v, out Vector3d s, out Vector3d su, out Vector3d sv)
  {
    Vector3d[] p = control[patch];
    Span<double> bu = stackalloc double[4];
    Span<double> du = stackalloc double[4];
    Span<double> bv = stackalloc double[4];
    Span<double> dv = stackalloc double[4];
    Bernstein(u, bu, du);
    Bernstein(v, bv, dv);
    s = su = sv = Vector3d.Zero;
    for (int i = 0; i < 4; i++)
      for (int j = 0; j < 4; j++)
      {
        Vector3d q = p[4 * i + j];
        s += (bv[i] * bu[j]) * q;
        su += (bv[i] * du[j]) * q;
        sv += (dv[i] * bu[j]) * q;
      }
  }

  static void Bernstein(double t, Span<double> b, Span<double> d)
  {
    double s = 1.0 - t;
    b[0] = s * s * s;
    b[1] = 3.0 * t * s * s;
    b[2] = 3.0 * t * t * s;
    b[3] = t * t * t;
    d[0] = -3.0 * s * s;
    d[1] = 3.0 * s * s - 6.0 * t * s;
    d[2] = 6.0 * t * s - 3.0 * t * t;
    d[3] = 3.0 * t * t;
  }

  /// <summary>
  /// All points where the line <c>p0 + t * p1</c> (local coordinates) crosses the surface, sorted by
  /// <see cref="Intersection.T"/>; null on a miss. Enter = Front = the ray runs against the normal ∂S/∂u × ∂S/∂v.
  /// </summary>
  public override LinkedList<Intersection>? Intersect(Vector3d p0, Vector3d p1)
  {
    Span<Found> found = CollectAll(p0, p1, stackalloc Found[StackHits]);
    int n = found.Length;
    if (n == 0)
      return null;

    var result = new LinkedList<Intersection>();
    for (int k = 0; k < n; k++)
    {
      Found f = found[k];
      bool front = Front(f, p1);
      result.AddLast(new Intersection(this) { T = f.T, Enter = front, Front = front, CoordLocal = p0 + f.T * p1, SolidData = NewHit(f.Piece, f.U, f.V) });
    }
    return result;
  }

  const int StackHits = 32;

  /// <summary>
  /// <see cref="Collect"/> into <paramref name="buffer"/>, or into an array big enough for any ray (every leaf
  /// piece yields at most one hit) when the buffer is too short; the hits found.
  /// </summary>
  Span<Found> CollectAll(in Vector3d p0, in Vector3d p1, Span<Found> buffer)
  {
    int n = Collect(p0, p1, buffer);
    if (n < 0)
    {
      buffer = new Found[pieces.Count];
      n = Collect(p0, p1, buffer);
    }
    return buffer[..n];
  }

  /// <summary>
  /// All hits of the line <c>p0 + t p1</c> sorted by t (stable), duplicates at patch seams dropped; the count,
  /// 0 for a degenerate direction, or -1 when <paramref name="found"/> is too short.
  /// </summary>
  int Collect(in Vector3d p0, in Vector3d p1, Span<Found> found)
  {
    double len2 = p1.LengthSquared;
    if (!(len2 > 0.0))
      return 0;

    // The ray as the intersection of two planes n1·x = c1, n2·x = c2.
    Vector3d dir = p1 / Math.Sqrt(len2);
    MathSupport.Geometry.GetTangents(dir, out Vector3d n1, out Vector3d n2);
    double c1 = Vector3d.Dot(n1, p0), c2 = Vector3d.Dot(n2, p0);
    double scale = Math.Max((maxV - minV).Length, 1e-300);
    double tTol = 1e-9 * scale / Math.Sqrt(len2);

    int n = 0;
    Span<int> stack = stackalloc int[64];
    foreach (int root in roots)
    {
      int sp = 0;
      stack[sp++] = root;
      while (sp > 0)
      {
        int index = stack[--sp];
        Piece piece = pieces[index];
        if (!LineCrossesBox(piece.Min, piece.Max, p0, p1, 1e-9 * scale))
          continue;
        if (piece.Left >= 0)
        {
          stack[sp++] = piece.Left;
          stack[sp++] = piece.Right;
          continue;
        }
        if (!Solve(piece, n1, n2, c1, c2, scale, out double u, out double v, out Vector3d point))
          continue;
        double t = Vector3d.Dot(point - p0, p1) / len2;
        if (Duplicate(found[..n], t, piece.Patch, u, v, tTol))
          continue;
        if (n == found.Length)
          return -1;
        found[n++] = new Found { T = t, Piece = index, U = u, V = v };
      }
    }

    // Insertion sort by t: stable, and these lists are short.
    for (int i = 1; i < n; i++)
    {
      Found f = found[i];
      int j = i - 1;
      while (j >= 0 && found[j].T > f.T)
      {
        found[j + 1] = found[j];
        j--;
      }
      found[j + 1] = f;
    }
    return n;
  }

  /// <summary>The same point found again: from another start on the same patch, or from the neighbour across a seam.</summary>
  bool Duplicate(ReadOnlySpan<Found> found, double t, int patch, double u, double v, double tTol)
  {
    foreach (Found f in found)
      if (pieces[f.Piece].Patch == patch && Math.Abs(f.T - t) <= tTol && Math.Abs(f.U - u) <= 1e-7 && Math.Abs(f.V - v) <= 1e-7)
        return true;
    foreach (Found f in found)
      if (pieces[f.Piece].Patch != patch && Math.Abs(f.T - t) <= tTol)
        return true;
    return false;
  }

  /// <summary>Whether the ray runs against the surface normal ∂S/∂u × ∂S/∂v at the hit.</summary>
  bool Front(in Found f, in Vector3d p1)
  {
    Evaluate(pieces[f.Piece].Patch, f.U, f.V, out _, out Vector3d su, out Vector3d sv);
    return Vector3d.Dot(Vector3d.Cross(su, sv), p1) < 0.0;
  }

  Hit NewHit(int piece, double u, double v) =>
    new() { Patch = pieces[piece].Patch, U = u, V = v, FlatNormal = pieces[piece].FlatNormal };

  /// <summary>Newton iteration for (u, v) on the plane pair, started in the middle of the piece.</summary>
  bool Solve(Piece piece, Vector3d n1, Vector3d n2, double c1, double c2, double scale, out double u, out double v, out Vector3d point)
  {
    u = 0.5 * (piece.U0 + piece.U1);
    v = 0.5 * (piece.V0 + piece.V1);
    point = Vector3d.Zero;
    double tol = 1e-12 * scale;
    for (int iter = 0; iter < 20; iter++)
    {
      Evaluate(piece.Patch, u, v, out point, out Vector3d su, out Vector3d sv);
      double f1 = Vector3d.Dot(n1, point) - c1, f2 = Vector3d.Dot(n2, point) - c2;
      if (Math.Abs(f1) <= tol && Math.Abs(f2) <= tol)
      {
        // Accept only parameters on the patch (pieces overlap only at their borders).
        const double slack = 1e-9;
        return u >= -slack && u <= 1 + slack && v >= -slack && v <= 1 + slack;
      }
      double a = Vector3d.Dot(n1, su), b = Vector3d.Dot(n1, sv);
      double c = Vector3d.Dot(n2, su), d = Vector3d.Dot(n2, sv);
      double det = a * d - b * c;
      if (det == 0.0 || !double.IsFinite(det))
        return false;
      double du = (d * f1 - b * f2) / det, dv = (a * f2 - c * f1) / det;
      u -= du;
      v -= dv;
      // Far outside the piece: this start does not lead to a hit here.
      double wu = piece.U1 - piece.U0, wv = piece.V1 - piece.V0;
      if (u < piece.U0 - 2 * wu || u > piece.U1 + 2 * wu || v < piece.V0 - 2 * wv || v > piece.V1 + 2 * wv)
        return false;
    }
    return false;
  }

  static bool LineCrossesBox(Vector3d min, Vector3d max, Vector3d o, Vector3d d, double pad)
  {
    double tMin = double.NegativeInfinity, tMax = double.PositiveInfinity;
    for (int axis = 0; axis < 3; axis++)
    {
      double lo = min[axis] - pad, hi = max[axis] + pad, oa = o[axis], da = d[axis];
      if (da == 0.0)
      {
        if (oa < lo || oa > hi)
          return false;
        continue;
      }
      double t0 = (lo - oa) / da, t1 = (hi - oa) / da;
      if (t0 > t1)
        (t0, t1) = (t1, t0);
      tMin = Math.Max(tMin, t0);
      tMax = Math.Min(tMax, t1);
      if (tMin > tMax)
        return false;
    }
    return true;
  }

  /// <summary>
  /// Sets the texture coordinates (l + u, k + v), the normal (exact with <see cref="PreciseNormals"/>, else
  /// the flat normal of the piece that was hit) and the tangents ∂S/∂u, ∂S/∂v.
  /// </summary>
  public override void CompleteIntersection(Intersection inter)
  {
    if (inter.SolidData is not Hit hit)
    {
      SolidSupport.SetWorldFrame(inter, Vector3d.UnitZ);
      return;
    }
    Evaluate(hit.Patch, hit.U, hit.V, out _, out Vector3d su, out Vector3d sv);
    Vector3d normal = PreciseNormals ? Vector3d.Cross(su, sv) : hit.FlatNormal;
    if (normal.LengthSquared == 0.0)
      normal = hit.FlatNormal;
    int k = hit.Patch / patchesL, l = hit.Patch % patchesL;
    inter.TextureCoord = new Vector2d(l + hit.U, k + hit.V);
    SolidSupport.SetWorldFrame(inter, normal, su, sv);
  }

  /// <summary>The box of all control points (the surface lies inside it).</summary>
  /// <param name="corner1">The minimal corner.</param>
  /// <param name="corner2">The maximal corner.</param>
  public virtual void GetBoundingBox(out Vector3d corner1, out Vector3d corner2)
  {
    corner1 = minV;
    corner2 = maxV;
  }

  /// <summary>Number of patches (K·L).</summary>
  public int Patches => patchesK * patchesL;
}
