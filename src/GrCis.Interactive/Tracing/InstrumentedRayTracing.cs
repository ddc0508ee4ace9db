using System;
using MathSupport;
using OpenTK.Mathematics;
using Rendering;

namespace GrCis.Interactive;

/// <summary>
/// <see cref="RayTracing"/> that reports each ray to a <see cref="RayObserver"/> and otherwise shades
/// exactly like its template (every override calls the base), so images are bit-identical.
/// Used only where rays are wanted (statistics, probe, extra views); plain renders pay nothing.
/// Not bound to a scene: it shades the thread's <see cref="MT.scene"/>, i.e. each worker's clone.
/// </summary>
internal sealed class InstrumentedRayTracing : RayTracing
{
  struct Frame
  {
    public Vector3d Direction;
    public Intersection? Hit;
    public bool HitSeen;
  }

  // Per-thread stack of the rays being shaded, to classify children by their parent hit.
  [ThreadStatic] static Frame[]? stack;
  [ThreadStatic] static int top;

  readonly RayObserver observer;

  public InstrumentedRayTracing(RayTracing template, RayObserver observer)
  {
    ArgumentNullException.ThrowIfNull(template);
    this.observer = observer ?? throw new ArgumentNullException(nameof(observer));
    CopySettingsFrom(template);
  }

  /// <summary>True when <paramref name="f"/> is a plain <see cref="RayTracing"/> whose behaviour this class reproduces.</summary>
  public static bool CanInstrument(IImageFunction? f) => f != null && f.GetType() == typeof(RayTracing);

  public override long GetSample(double x, double y, double[] color)
  {
    top = 0; // a previous sample may have thrown mid-stack
    return base.GetSample(x, y, color);
  }

  public override long shade(int depth, double importance, ref Vector3d p0, ref Vector3d p1, double[] color)
  {
    RayKind kind = Classify(depth, p1);
    Vector3d origin = p0, direction = p1;
    observer.BeginRay(kind, depth, origin, direction);

    Frame[] s = stack ??= new Frame[16];
    if (top == s.Length)
      Array.Resize(ref stack, 2 * s.Length);
    stack![top++] = new Frame { Direction = direction };

    long hash;
    try
    {
      hash = base.shade(depth, importance, ref p0, ref p1, color);
    }
    finally
    {
      top--;
    }
    observer.EndRay(kind, depth, origin, direction, stack[top].Hit);
    stack[top].Hit = null;
    return hash;
  }

  protected override Intersection? FirstHit(Vector3d p0, Vector3d p1)
  {
    Intersection? i = base.FirstHit(p0, p1);
    // The first query inside a shade() call is that ray's own hit.
    if (top > 0 && !stack![top - 1].HitSeen)
    {
      stack[top - 1].HitSeen = true;
      stack[top - 1].Hit = i;
    }
    return i;
  }

  protected override bool Occluded(Vector3d p0, Vector3d dir)
  {
    bool blocked = base.Occluded(p0, dir);
    observer.ShadowRay(p0, dir, blocked);
    return blocked;
  }

  RayKind Classify(int depth, in Vector3d p1)
  {
    if (top == 0)
      return RayKind.Primary;
    if (!observer.NeedsKinds)
      return depth == 0 ? RayKind.Primary : RayKind.Secondary;
    ref Frame parent = ref stack![top - 1];
    Intersection? i = parent.Hit;
    if (i == null)
      return RayKind.Secondary;
    // Recompute the parent's mirrored and refracted directions exactly as RayTracing does.
    Vector3d viewer = -parent.Direction.Normalized();
    if (Geometry.SpecularReflection(i.Normal, viewer) == p1)
      return RayKind.Reflected;
    if (i.Material != null && Geometry.SpecularRefraction(i.Normal, i.Material.n, viewer) == p1)
      return RayKind.Refracted;
    return RayKind.Secondary;
  }
}
