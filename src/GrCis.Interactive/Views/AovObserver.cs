using System;
using OpenTK.Mathematics;
using Rendering;
using Rendering.Observation;

namespace GrCis.Interactive;

/// <summary>Accumulates per-pixel maps; a pixel belongs to one thread at a time, so no locking.</summary>
internal sealed class AovObserver : RayObserver
{
  readonly int width;
  public readonly int[] Primary, All, Hits;
  public readonly double[] DepthSum, AngleSum;
  public readonly Vector3d[] NormalSum, PointSum;

  public AovObserver(int width, int height)
  {
    this.width = width;
    int n = width * height;
    Primary = new int[n];
    All = new int[n];
    Hits = new int[n];
    DepthSum = new double[n];
    AngleSum = new double[n];
    NormalSum = new Vector3d[n];
    PointSum = new Vector3d[n];
  }

  int Pixel => MT.y * width + MT.x;

  public override void BeginRay(RayKind kind, int depth, in Vector3d origin, in Vector3d direction)
  {
    int p = Pixel;
    All[p]++;
    if (kind == RayKind.Primary)
      Primary[p]++;
  }

  public override void EndRay(RayKind kind, int depth, in Vector3d origin, in Vector3d direction, Intersection? hit)
  {
    if (kind != RayKind.Primary || hit == null)
      return;
    int p = Pixel;
    Hits[p]++;
    Vector3d toViewer = origin - hit.CoordWorld;
    DepthSum[p] += toViewer.Length;
    NormalSum[p] += hit.Normal;
    PointSum[p] += hit.CoordWorld;
    double cos = Vector3d.Dot(hit.Normal, toViewer) / (hit.Normal.Length * toViewer.Length);
    AngleSum[p] += Math.Acos(Math.Clamp(cos, -1.0, 1.0)) * (180.0 / Math.PI);
  }

  public override void ShadowRay(in Vector3d origin, in Vector3d direction, bool blocked) => All[Pixel]++;
}
