using System;
using System.Collections.Generic;
using System.Runtime.CompilerServices;
using MathSupport;
using OpenTK.Mathematics;
using Rendering.Observation;

namespace Rendering.Accel;

/// <summary>
/// The prepared form of <see cref="RayTracing"/>: the same algorithm as <see cref="RayTracing.shade"/>, value for
/// value and in the same order (the image hashes and <c>WhittedKernelTests</c> hold the two equal), written for
/// speed. <see cref="For"/> decides once per frame whether a function may be sampled through it: the library's
/// <see cref="RayTracing"/> and any subclass that keeps its shading (<see cref="LibraryTypes.ShadesAsWhitted"/>;
/// <see cref="Distributed.DistributedRayTracing"/> changes only the reflected and refracted directions, which the
/// kernel asks the function for). Everything else is sampled through <see cref="IImageFunction.GetSample"/>.
/// <para>
/// What makes it fast, all decided here rather than in the classes students read: the library's own scene's camera,
/// background and lights are read once per frame and worker (<see cref="BoundScene"/>), each tagged with the library
/// class called without an interface call (code compiled without a profile, such as ReadyToRun images and a render's
/// first moments, would otherwise pay one per sample); the Phong model writes into stack buffers instead of a new
/// array per light; the thread's shading scratch is fetched once per sample.
/// </para>
/// </summary>
internal sealed partial class WhittedKernel
{
  readonly RayTracing function;

  WhittedKernel(RayTracing function)
  {
    this.function = function;
    plainFunction = !function.firstHitOverridden && LibraryTypes.KeepsWhittedDirections(function);
  }

  /// <summary>
  /// The kernel of <paramref name="function"/>, or null when it must be sampled through its own <c>GetSample</c>:
  /// a function that changes the shading, or one on GrCis's faithful path (<see cref="AccelMode.None"/>).
  /// </summary>
  public static WhittedKernel? For(IImageFunction function) =>
    function is RayTracing rt && rt.Accel != AccelMode.None && LibraryTypes.ShadesAsWhitted(rt) ? new WhittedKernel(rt) : null;

  /// <summary><see cref="RayTracing.GetSample"/> of the function.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]   // into the sample loop
  public long Sample(double x, double y, double[] color)
  {
    Execution.WorkerContext context = Execution.WorkerContext.Current;
    context.DoubleX = x;
    context.DoubleY = y;
    Zero(color);
    ShadingScratch scratch = ShadingScratch.Of(context);
    BoundScene bound = Bind(scratch, function.Scene);
    Vector3d p0, p1;
    if (bound.StaticCamera != null)
      bound.StaticCamera.Ray(x, y, out p0, out p1);
    else
    {
      ICamera? camera = bound.Library ? bound.Camera : bound.Scene.Camera;
      if (camera == null || !camera.GetRay(x, y, out p0, out p1))
        return 11L;
    }
    if (bound.Plain != null && scratch.Observer == null)
      return ShadePlain(scratch, bound, 0, 1.0, p0, p1, color);
    return Shade(scratch, bound, 0, 1.0, ref p0, ref p1, color);
  }

  /// <summary>The scene as this thread reads it during this frame: taken on the thread's first sample of the frame.</summary>
  BoundScene Bind(ShadingScratch scratch, IRayScene scene)
  {
    BoundScene? bound = scratch.Bound;
    if (bound != null && bound.Kernel == this && bound.Scene == scene)
      return bound;
    scratch.Bound = bound = new BoundScene(this, scene);
    bound.Plain = PlainSceneOf(scratch, bound);   // after the binding is the thread's: the prepared scene is looked up through it
    return bound;
  }

  /// <summary><see cref="RayTracing.shade"/> of the function.</summary>
  [SkipLocalsInit]   // the stack buffers are written before they are read
  long Shade(ShadingScratch scratch, BoundScene bound, int depth, double importance, ref Vector3d p0, ref Vector3d p1, double[] color)
  {
    RayTracing f = function;
    RayObserver? observer = scratch.Observer;
    int rayDepth = depth;
    RayKind kind = RayKind.Primary;
    if (observer != null)
    {
      kind = depth == 0 ? RayKind.Primary : scratch.NextKind;
      scratch.NextKind = RayKind.Secondary;
      observer.BeginRay(kind, depth, p0, p1);
    }

    IRayScene sc = bound.Scene;
    Vector3d direction = p1;
    Intersection? i = FirstHit(scratch, depth, p0, direction);
    long hash;
    bool library = bound.Library;
    if (i == null)
    {
      f.rayRegisterer?.RegisterRay(AbstractRayRegisterer.RayType.rayVisualizerNormal, depth, p0, direction * 100000.0);
      hash = Background(bound, p1, color);
      goto done;
    }

    scratch.Hits++;
    hash = RayCasting.CompleteAndTexture(i);
    f.rayRegisterer?.RegisterRay(AbstractRayRegisterer.RayType.unknown, depth, p0, i);
    int bands = color.Length;
    Zero(color);

    if (f.DoRecursion && i.RecursionAttribute is RecursionFunction recursion)
    {
      hash += RayTracing.HASH_RECURSION * recursion(i, direction, importance, out RayRecursion rr);
      if (rr != null)
        hash = rr.Recursion(f, i, hash, depth, color);
      goto done;
    }

    Vector3d viewer = -p1.Normalized();
    double[] surface = i.SurfaceColor!;

    BoundLight[]? lights = bound.Lights;
    ICollection<ILightSource>? sources = library ? null : sc.Sources;
    if (library ? lights == null : sources == null || sources.Count == 0)
      AddScaled(color, surface, 1.0);
    else
    {
      i.Material = scratch.Material(i.Material!, surface, depth);
      // The library's Phong model writes into a stack buffer instead of a new array per light.
      bool phong = LibraryTypes.IsLibraryPhongModel(i.ReflectanceModel) && IsPhongMaterial(i.Material) && surface.Length <= 16;
      Unsafe.SkipInit(out Bands16 lit);
      Span<double> buffer = lit;

      if (lights != null)
        foreach (BoundLight light in lights)
          hash = AddLight(scratch, light.Source, light.Kind, light.Hash, i, viewer, phong, surface, buffer, color, hash);
      // A script's own scene class: its lights as it gives them now, a LinkedList (GrCis's type) walked by nodes.
      else if (sources is LinkedList<ILightSource> linked)
      {
        for (LinkedListNode<ILightSource>? n = linked.First; n != null; n = n.Next)
          hash = AddLight(scratch, n.Value, DirectLight.None, 0, i, viewer, phong, surface, buffer, color, hash);
      }
      else
        foreach (ILightSource source in sources!)
          hash = AddLight(scratch, source, DirectLight.None, 0, i, viewer, phong, surface, buffer, color, hash);
    }

    if (depth++ >= f.MaxLevel || (!f.DoReflections && !f.DoRefractions))
      goto done;

    double[] comp = scratch.Buffer(depth, bands);
    Vector3d origin = i.CoordWorld;
    Vector3d viewerUnit = default;
    bool haveUnit = false;

    if (f.DoReflections)
    {
      Vector3d r = Geometry.SpecularReflection(i.Normal, viewer);
      Unsafe.SkipInit(out Bands16 ksStore);
      Span<double> ksBuffer = ksStore;
      scoped ReadOnlySpan<double> ks = default;
      bool have;
      if (LibraryTypes.IsLibraryPhongModel(i.ReflectanceModel) && IsPhongMaterial(i.Material) && Unsafe.As<PhongMaterial>(i.Material!) is { Color.Length: > 0 and <= 16 } pm)
      {
        Span<double> k = ksBuffer[..pm.Color.Length];
        if (viewer.X == 0.0 && viewer.Y == 0.0 && viewer.Z == 0.0)
          PhongModel.ColorReflection(pm, i.Normal, viewer, r, ReflectionComponent.SPECULAR_REFLECTION, k);
        else
        {
          // The model's normalized input, kept for the refracted direction (which normalizes the same vector).
          viewerUnit = viewer.Normalized();
          haveUnit = true;
          PhongModel.Directional(pm, i.Normal, viewerUnit, r, ReflectionComponent.SPECULAR_REFLECTION, k);
        }
        ks = k;
        have = true;
      }
      else
      {
        double[]? arr = i.ReflectanceModel!.ColorReflection(i, viewer, r, ReflectionComponent.SPECULAR_REFLECTION);
        have = arr != null;
        if (have)
          ks = arr;
      }
      if (have)
      {
        double newImportance = importance * MaxBand(ks);
        if (newImportance >= f.MinImportance)
        {
          if (f.ReflectionDirection(i, r, depth, out Vector3d reflected))
          {
            if (observer != null)
              scratch.NextKind = RayKind.Reflected;
            hash += RayTracing.HASH_REFLECT * Shade(scratch, bound, depth, newImportance, ref origin, ref reflected, comp);
            AddWeighted(color, ks, comp);
          }
        }
      }
    }

    if (f.DoRefractions)
    {
      IMaterial material = i.Material!;
      double kt = material.Kt;
      if (f.FresnelRefraction && kt > 0.0)
        kt *= 1.0 - RayTracing.SchlickReflectance(Math.Abs(Vector3d.Dot(i.Normal, viewer)), material.n);
      double newImportance = importance * kt;
      if (newImportance < f.MinImportance)
        goto done;
      Vector3d r = haveUnit
        ? Geometry.SpecularRefractionUnit(i.Normal, material.n, viewerUnit)
        : Geometry.SpecularRefraction(i.Normal, material.n, viewer);
      if (r.X == 0.0 && r.Y == 0.0 && r.Z == 0.0 || !f.RefractionDirection(i, r, depth, out r))
        goto done;
      if (observer != null)
        scratch.NextKind = RayKind.Refracted;
      hash += RayTracing.HASH_REFRACT * Shade(scratch, bound, depth, newImportance, ref origin, ref r, comp);
      AddScaled(color, comp, kt);
    }

  done:
    // Every way out passes here, so an observer sees the end of each ray it saw begin.
    observer?.EndRay(kind, rayDepth, p0, p1, i);
    return hash;
  }

  /// <summary>The background's colour of a ray that hits nothing, into <paramref name="color"/>; returns the hash.</summary>
  static long Background(BoundScene bound, in Vector3d p1, double[] color)
  {
    IBackground? background = bound.Library ? bound.Background : bound.Scene.Background;
    if (bound.DefaultBackground != null)
      return bound.DefaultBackground.Fill(color);
    if (background != null)
      return background.GetColor(p1, color);
    return RayTracing.FillBackground(bound.Scene, color);
  }

  /// <summary>
  /// One light's direct contribution (shadow ray included) added to <paramref name="color"/>; returns the hash.
  /// <paramref name="sourceHash"/> is the source's hash code when <paramref name="kind"/> names a library class.
  /// </summary>
  long AddLight(ShadingScratch scratch, ILightSource source, DirectLight kind, int sourceHash, Intersection i, Vector3d viewer, bool phong, double[] surface, Span<double> buffer, double[] color, long hash)
  {
    RayTracing f = function;
    double[]? intensity;
    Vector3d dir;
    switch (kind)
    {
      case DirectLight.Point: intensity = Unsafe.As<PointLightSource>(source).Intensity(i, out dir); break;
      case DirectLight.Ambient: intensity = Unsafe.As<AmbientLightSource>(source).Intensity(out dir); break;
      default: intensity = source.GetIntensity(i, out dir); break;
    }
    if (f.rayRegisterer != null && MT.singleRayTracing && source.position is Vector3d lightPosition)
      f.rayRegisterer.RegisterRay(AbstractRayRegisterer.RayType.rayVisualizerShadow, i.CoordWorld, lightPosition);
    if (intensity == null)
      return hash;
    double transmit = 1.0;
    if (f.DoShadows && (dir.X != 0.0 || dir.Y != 0.0 || dir.Z != 0.0))
    {
      transmit = Transmittance(scratch, i.CoordWorld, dir);
      scratch.Observer?.ShadowRay(i.CoordWorld, dir, transmit <= 0.0);
      if (transmit <= 0.0)
      {
        scratch.Hits++;   // a blocked shadow ray
        return hash;
      }
    }
    if (phong)
    {
      Span<double> r = buffer[..surface.Length];
      PhongModel.ColorReflection(Unsafe.As<PhongMaterial>(i.Material!), i.Normal, dir, viewer, ReflectionComponent.ALL, r);
      AddLit(color, transmit, intensity, r);
    }
    else
    {
      double[]? arr = i.ReflectanceModel!.ColorReflection(i, dir, viewer, ReflectionComponent.ALL);
      if (arr == null)
        return hash;
      AddLit(color, transmit, intensity, arr);
    }
    return hash * RayCasting.HASH_LIGHT + (kind != DirectLight.None ? sourceHash : source.GetHashCode());
  }

  /// <summary><see cref="RayCasting.FirstHitAt(int, Vector3d, Vector3d)"/> of the function, the library's scene read directly.</summary>
  Intersection? FirstHit(ShadingScratch scratch, int depth, Vector3d p0, Vector3d p1)
  {
    RayTracing f = function;
    PreparedScene? ps;
    if (f.firstHitOverridden || !f.ReuseIntersections || (ps = Prepared(scratch)) == null)
      return f.FirstHitAt(scratch, depth, p0, p1);
    scratch.Rays++;
    return ps.FirstHit(p0, p1, scratch.Intersection(depth), ReferenceEquals(ps, f.surfaceOnly));
  }

  /// <summary>
  /// The share of a light that reaches <paramref name="p0"/> along <paramref name="dir"/>, counting the shadow ray: the
  /// function's <see cref="RayTracing.ShadowTransmittance"/> with <c>TransparentShadows</c>, else 0 or 1 by
  /// <see cref="RayTracing"/>'s shadow query (the kernel serves only functions that keep it).
  /// </summary>
  double Transmittance(ShadingScratch scratch, in Vector3d p0, in Vector3d dir)
  {
    scratch.Rays++;
    if (function.TransparentShadows)
      return function.ShadowTransmittance(p0, dir);
    PreparedScene? ps = Prepared(scratch);
    return (ps != null ? ps.AnyHit(p0, dir) : function.Lists.AnyHit(p0, dir)) ? 0.0 : 1.0;
  }

  /// <summary>
  /// <c>material is PhongMaterial</c>, the exact class (the scratch copy's) answered inline: <see cref="Shade"/> is
  /// compiled without a profile, and the type test otherwise calls the runtime's cast helper per hit.
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  static bool IsPhongMaterial(IMaterial? material) =>
    material != null && (material.GetType() == typeof(PhongMaterial) || material is PhongMaterial);

  /// <summary>
  /// <see cref="RayCasting.PreparedFor"/> of the function, the library's scene read directly: the snapshot this thread
  /// used last when it is still the scene's, else the render's.
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]   // a few loads, once per ray
  PreparedScene? Prepared(ShadingScratch scratch)
  {
    RayTracing f = function;
    BoundScene bound = scratch.Bound!;
    IIntersectable? source = bound.Library ? bound.Intersectable : bound.Scene.Intersectable;
    PreparedScene? ps = scratch.LastPrepared;
    return ps != null && ps.Source == source ? ps : f.PreparedFor(scratch);
  }

  /// <summary>
  /// The largest band, as folding <see cref="Math.Max(double, double)"/> from band 0 gives it; its NaN and signed-zero
  /// rules are applied only where they can matter (a Phong reflectance has all bands equal).
  /// </summary>
  internal static double MaxBand(ReadOnlySpan<double> bands)
  {
    double max = bands[0];
    for (int b = 1; b < bands.Length; b++)
    {
      double k = bands[b];
      if (k > max)
        max = k;
      else if (!(k < max) && (k != max || k == 0.0))
        max = Math.Max(max, k);
    }
    return max;
  }

  /// <summary>color += transmit · light · reflected, band by band; a light or reflectance with fewer bands repeats its last one.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  static void AddLit(double[] color, double transmit, double[] light, ReadOnlySpan<double> reflected)
  {
    int bands = color.Length;
    if (light.Length >= bands && reflected.Length >= bands)
    {
      // Every band has its own values (the common case): no index clamps.
      ReadOnlySpan<double> l = light.AsSpan(0, bands), k = reflected[..bands];
      for (int b = 0; b < bands; b++)
        color[b] += transmit * l[b] * k[b];
    }
    else
      for (int b = 0; b < bands; b++)
        color[b] += transmit * light[Math.Min(b, light.Length - 1)] * reflected[Math.Min(b, reflected.Length - 1)];
  }

  /// <summary>color += weights · src, band by band; weights with fewer bands repeat their last one.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]   // once per reflected ray, a short loop
  static void AddWeighted(double[] color, ReadOnlySpan<double> weights, double[] src)
  {
    int bands = color.Length;
    if (weights.Length >= bands)
      for (int b = 0; b < bands; b++)
        color[b] += weights[b] * src[b];
    else
      for (int b = 0; b < bands; b++)
        color[b] += weights[Math.Min(b, weights.Length - 1)] * src[b];
  }

  /// <summary>color += k · src; a one-element src adds the same value to every band.</summary>
  static void AddScaled(double[] color, ReadOnlySpan<double> src, double k)
  {
    for (int b = 0; b < color.Length; b++)
      color[b] += k * src[Math.Min(b, src.Length - 1)];
  }

  /// <summary>Zeroes a colour of a few bands inline (Array.Clear's call costs more than three stores).</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  internal static void Zero(double[] color)
  {
    for (int b = 0; b < color.Length; b++)
      color[b] = 0.0;
  }

  /// <summary>Sixteen bands in the frame (a local, not a stack allocation: no stack-guard cookie per call).</summary>
  [InlineArray(16)]
  struct Bands16
  {
    double first;
  }
}
