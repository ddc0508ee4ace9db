using System;
using System.Collections.Generic;
using System.Runtime.CompilerServices;
using OpenTK.Mathematics;

namespace Rendering.Accel;

/// <summary>
/// The library solids the prepared scene knows by name (<see cref="Sphere"/>, <see cref="Plane"/>, <see cref="Cube"/>,
/// and the mesh's any-hit walk): which members qualify, decided once when a member is bound; the direct calls to their
/// kernels and hit set-ups; their surface-only completions; the world-space culls a sphere or a plane member gets.
/// A library solid's fast path is its own class (the kernel, the set-up, the completion) and this file, nowhere else.
/// </summary>
internal static partial class LibraryTypes
{
  // ---------------------------------------------------------------- decided when a member is bound

  /// <summary>
  /// The library solid the prepared scene may call directly: exactly <see cref="Sphere"/> or <see cref="Plane"/> (a
  /// subclass may change the kernel or the hit set-up, so it is called through its interface); or a solid whose shadow
  /// queries may take its any-hit walk (<see cref="IAnyHitSolid"/>: the library's mesh, or a subclass that changes
  /// nothing of it; one that changes anything might change its records, so it is asked for them).
  /// </summary>
  public static DirectSolid DirectKernel(IRecordSolid solid) =>
    solid.GetType() == typeof(Sphere) ? DirectSolid.Sphere : solid.GetType() == typeof(Plane) ? DirectSolid.Plane :
    solid is IAnyHitSolid && SubclassCheck.OverridesNothing(solid, ImplementingClass(solid, typeof(IAnyHitSolid))) ? DirectSolid.AnyHit :
    DirectSolid.None;

  // The class whose methods implement the interface for this object (the library class, unless a subclass re-implements it).
  static Type ImplementingClass(object o, Type contract) => o.GetType().GetInterfaceMap(contract).TargetMethods[0].DeclaringType!;

  /// <summary>
  /// The surface-only completion of a solid's hit: <see cref="HitCompletion.Sphere"/> (or
  /// <see cref="HitCompletion.SphereTextured"/>), <see cref="HitCompletion.Plane"/>, <see cref="HitCompletion.Cube"/> or
  /// <see cref="HitCompletion.OwnSurface"/> for the library's own solids and subclasses that override nothing; <see cref="HitCompletion.Full"/> otherwise.
  /// </summary>
  public static HitCompletion SurfaceShape(IRecordSolid solid, bool textured)
  {
    if (SubclassCheck.OverridesNothing(solid, typeof(Sphere)))
      return textured ? HitCompletion.SphereTextured : HitCompletion.Sphere;
    if (SubclassCheck.OverridesNothing(solid, typeof(Plane)))
      return HitCompletion.Plane;
    if (SubclassCheck.OverridesNothing(solid, typeof(Cube)))
      return HitCompletion.Cube;
    if (solid is ISurfaceSolid && SubclassCheck.OverridesNothing(solid, ImplementingClass(solid, typeof(ISurfaceSolid))))
      return HitCompletion.OwnSurface;
    return HitCompletion.Full;
  }

  /// <summary>A plane whose records are the library plane's (an emitter the light model may sample as a rectangle).</summary>
  public static bool HasPlaneGeometry(Plane plane) => SubclassCheck.KeepsGeometry(plane, typeof(Plane));

  /// <summary>
  /// The world-space culls of a sphere or plane member (its records through <paramref name="solid"/>): a sphere under a
  /// similarity gets its world ball, a plane the row of its local z and, when finite, its world box.
  /// </summary>
  public static void BindShapeCulls(ref PreparedMember m, IRecordSolid solid, List<Matrix4d> path)
  {
    if (solid is Sphere && PreparedScene.TrySimilarity(path, out Vector3d center, out double radius))
    {
      // 1e-6 relative slack covers the rounding of the chain and of this estimate by a wide margin.
      double r = radius * (1.0 + 1.0e-6) + 1.0e-12;
      m.CullCenter = center;
      m.CullRadius2 = r * r;
    }
    else if (solid is Plane plane)
    {
      PlaneCull.Build(ref m, path);
      if (BoundedPlaneBox(plane, out Aabb flat))
      {
        Aabb world = flat.Transformed(PreparedScene.LocalToWorldOf(path));
        if (!world.IsEmpty && world.IsFinite)
        {
          m.LineBox = world.Padded();
          m.HasLineBox = true;
        }
      }
    }
  }

  /// <summary>Local box of a finite rectangle or triangle of the z = 0 plane (where <see cref="Plane"/> can have its record).</summary>
  static bool BoundedPlaneBox(Plane plane, out Aabb box)
  {
    box = Aabb.Empty;
    double x0 = plane.XMin, x1 = plane.XMax, y0 = plane.YMin, y1 = plane.YMax;
    if (plane.Triangle)
    {
      // x ≥ XMin, y ≥ YMin, x·XMax + y·YMax ≤ 1: bounded only for positive XMax and YMax.
      if (!(plane.XMax > 0.0 && plane.YMax > 0.0))
        return false;
      x1 = (1.0 - y0 * plane.YMax) / plane.XMax;
      y1 = (1.0 - x0 * plane.XMax) / plane.YMax;
    }
    if (!double.IsFinite(x0) || !double.IsFinite(x1) || !double.IsFinite(y0) || !double.IsFinite(y1))
      return false;
    box = new Aabb(new Vector3d(x0, y0, 0.0), new Vector3d(x1, y1, 0.0));
    return true;
  }

  // ---------------------------------------------------------------- per ray: the calls by name

  /// <summary>
  /// The first record of a member's solid, called by name for <paramref name="kind"/> (no interface call in code compiled
  /// without a profile: ReadyToRun, a render's first moments). A shadow query (<paramref name="any"/>) asks an any-hit
  /// solid for any blocker up to <paramref name="bound"/> instead of the first record.
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static bool First(DirectSolid kind, IRecordSolid solid, in Vector3d p0, in Vector3d p1, double len2, bool any, double bound,
                           out SolidRecord hit, out bool inside) =>
    kind switch
    {
      DirectSolid.Sphere => Unsafe.As<Sphere>(solid).First(p0, p1, len2, out hit, out inside),
      DirectSolid.Plane => Unsafe.As<Plane>(solid).First(p0, p1, len2, out hit, out inside),
      DirectSolid.AnyHit when any => Unsafe.As<IAnyHitSolid>(solid).IntersectAny(p0, p1, len2, bound, out hit, out inside),
      _ => solid.IntersectFirst(p0, p1, len2, out hit, out inside),
    };

  /// <summary>
  /// The first record of a member's solid when the state before it is not needed (a scene of this one member): an any-hit
  /// solid's <see cref="IAnyHitSolid.FirstRecord"/>, which may return none when the record lies beyond <paramref name="tMax"/>;
  /// any other solid's <see cref="IRecordSolid.IntersectFirst"/>.
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static bool FirstRecord(DirectSolid kind, IRecordSolid solid, in Vector3d p0, in Vector3d p1, double len2, double tMax, out SolidRecord hit) =>
    kind == DirectSolid.AnyHit
      ? Unsafe.As<IAnyHitSolid>(solid).FirstRecord(p0, p1, len2, tMax, out hit)
      : solid.IntersectFirst(p0, p1, len2, out hit, out _);

  /// <summary>
  /// A scene of one member's shadow answer: its first record exists and is not far (<see cref="PreparedScene.NotFar"/>;
  /// none beyond <paramref name="tMax"/> is). An any-hit solid's <see cref="IAnyHitSolid.Occluded"/> may stop at the first
  /// blocker it proves; any other solid's <see cref="IRecordSolid.IntersectFirst"/> gives the record.
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static bool Occluded(DirectSolid kind, IRecordSolid solid, in Vector3d p0, in Vector3d p1, double len2, double tMax) =>
    kind == DirectSolid.AnyHit
      ? Unsafe.As<IAnyHitSolid>(solid).Occluded(p0, p1, len2, tMax)
      : solid.IntersectFirst(p0, p1, len2, out SolidRecord hit, out _) && PreparedScene.NotFar(hit.T, len2);

  /// <summary>The hit set-up of a member's solid (<see cref="IRecordSolid.InitIntersection"/>), by name for <paramref name="kind"/>.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static void Init(DirectSolid kind, IRecordSolid solid, in SolidRecord hit, Intersection target)
  {
    switch (kind)
    {
      case DirectSolid.Sphere: Sphere.Init(hit, target); break;
      case DirectSolid.Plane: Plane.Init(hit, target); break;
      default: solid.InitIntersection(hit, target); break;
    }
  }

  /// <summary>
  /// The solid's part of a surface-only completion (<paramref name="completion"/> is not <see cref="HitCompletion.Full"/>);
  /// false when this hit needs the full completion after all (<see cref="ISurfaceSolid"/>).
  /// </summary>
  public static bool CompleteSurface(HitCompletion completion, Intersection inter, in Matrix4d worldToLocal)
  {
    if (completion == HitCompletion.OwnSurface)
      return Unsafe.As<ISurfaceSolid>(inter.Solid!).CompleteSurface(inter, worldToLocal);
    if (completion == HitCompletion.Plane)
      ((Plane)inter.Solid!).CompleteSurface(inter, worldToLocal);
    else if (completion == HitCompletion.Cube)
      Cube.CompleteSurface(inter, worldToLocal);
    else
      Sphere.CompleteSurface(inter, worldToLocal, completion == HitCompletion.SphereTextured);
    return true;
  }
}
