using System;
using System.Runtime.CompilerServices;
using MathSupport;
using OpenTK.Mathematics;

namespace Rendering.Accel;

/// <summary>
/// The kernel's plain-surface path: <see cref="Shade"/> for a scene of library balls, planes and cubes shaded by the Phong
/// model (checkers at most) and lit by point and ambient lights, with the hit kept as a record on the stack. Where the
/// general path fills a pooled <see cref="Intersection"/> (reset field by field, completed, textured) and copies the
/// material with the surface colour per hit, this one computes the same world point, normal, surface colour and hash
/// from the member's cached matrices and attributes, and gives the Phong model the material's coefficients with the
/// surface colour beside them. The same values in the same order: <c>WhittedKernelTests</c> and the image hashes hold
/// the two paths to the same bits. Chosen once per frame and worker (<see cref="PlainSceneOf"/>).
/// </summary>
internal sealed partial class WhittedKernel
{
  // The function's class keeps everything the plain path does itself (decided once per kernel).
  readonly bool plainFunction;

  /// <summary>
  /// The prepared scene when this binding's rays may take the plain path: the function keeps Whitted's first-hit query
  /// and directions, no ray registerer, the library's scene with only point and ambient lights, and a surface-only
  /// snapshot of plain surfaces (<see cref="PreparedScene.PlainSurfaces"/>). Else null.
  /// </summary>
  PreparedScene? PlainSceneOf(ShadingScratch scratch, BoundScene bound)
  {
    RayTracing f = function;
    if (!plainFunction || !f.ReuseIntersections || f.rayRegisterer != null || !bound.Library)
      return null;
    if (bound.Lights != null)
      foreach (BoundLight light in bound.Lights)
        if (light.Kind == DirectLight.None)
          return null;
    PreparedScene? ps = Prepared(scratch);
    return ps != null && ReferenceEquals(ps, f.surfaceOnly) && ps.PlainSurfaces ? ps : null;
  }

  /// <summary><see cref="Shade"/> of a ray in a plain scene (<see cref="BoundScene.Plain"/>, no observer).</summary>
  [SkipLocalsInit]   // the stack buffers are written before they are read
  long ShadePlain(ShadingScratch scratch, BoundScene bound, int depth, double importance, in Vector3d p0, in Vector3d p1, double[] color)
  {
    RayTracing f = function;
    PreparedScene ps = bound.Plain!;
    int found = ps.FirstRecord(p0, p1, out int index, out SolidRecord hit);
    if (found < 0)
    {
      // Not a member's own record (the faithful path answers): the general path asks again and completes its answer.
      Vector3d a = p0, b = p1;
      return Shade(scratch, bound, depth, importance, ref a, ref b, color);
    }
    scratch.Rays++;
    if (found == 0)
      return Background(bound, p1, color);

    scratch.Hits++;
    ref readonly PreparedMember m = ref ps.Member(index);
    Unsafe.SkipInit(out Bands16 surfaceStore);
    long hash = Surface(m, hit, out Vector3d point, out Vector3d normal, surfaceStore, out int surfaceBands);
    ReadOnlySpan<double> surface = ((ReadOnlySpan<double>)surfaceStore)[..surfaceBands];
    int bands = color.Length;
    Zero(color);

    Vector3d viewer = -p1.Normalized();
    PhongMaterial material = Unsafe.As<PhongMaterial>(m.Material!);
    BoundLight[]? lights = bound.Lights;
    if (lights == null)
      AddScaled(color, surface, 1.0);
    else
    {
      Unsafe.SkipInit(out Bands16 lit);
      Span<double> reflected = ((Span<double>)lit)[..surfaceBands];
      foreach (BoundLight light in lights)
      {
        double[]? intensity;
        Vector3d dir;
        if (light.Kind == DirectLight.Point)
          intensity = Unsafe.As<PointLightSource>(light.Source).Intensity(point, normal, out dir);
        else
          intensity = Unsafe.As<AmbientLightSource>(light.Source).Intensity(out dir);
        if (intensity == null)
          continue;
        double transmit = 1.0;
        if (f.DoShadows && (dir.X != 0.0 || dir.Y != 0.0 || dir.Z != 0.0))
        {
          transmit = Transmittance(scratch, point, dir);
          if (transmit <= 0.0)
          {
            scratch.Hits++;   // a blocked shadow ray
            continue;
          }
        }
        PhongModel.ColorReflection(material, surface, normal, dir, viewer, ReflectionComponent.ALL, reflected);
        AddLit(color, transmit, intensity, reflected);
        hash = hash * RayCasting.HASH_LIGHT + light.Hash;
      }
    }

    if (depth++ >= f.MaxLevel || (!f.DoReflections && !f.DoRefractions))
      return hash;

    double[] comp = scratch.Buffer(depth, bands);
    Vector3d viewerUnit = default;
    bool haveUnit = false;
    if (f.DoReflections)
    {
      // The general path reads the hit's material: the scratch copy with the surface colour when the scene has lights,
      // the member's own material (and colour) when it has none.
      ReadOnlySpan<double> materialColor = lights != null ? surface : material.Color;
      Vector3d r = Geometry.SpecularReflection(normal, viewer);
      Unsafe.SkipInit(out Bands16 ksStore);
      Span<double> ks = ((Span<double>)ksStore)[..materialColor.Length];
      if (viewer.X == 0.0 && viewer.Y == 0.0 && viewer.Z == 0.0)
        PhongModel.ColorReflection(material, materialColor, normal, viewer, r, ReflectionComponent.SPECULAR_REFLECTION, ks);
      else
      {
        viewerUnit = viewer.Normalized();
        haveUnit = true;
        PhongModel.Directional(material, materialColor, normal, viewerUnit, r, ReflectionComponent.SPECULAR_REFLECTION, ks);
      }
      double newImportance = importance * MaxBand(ks);
      if (newImportance >= f.MinImportance)
      {
        hash += RayTracing.HASH_REFLECT * ShadePlain(scratch, bound, depth, newImportance, point, r, comp);
        AddWeighted(color, ks, comp);
      }
    }

    if (f.DoRefractions)
    {
      double kt = material.Kt;
      if (f.FresnelRefraction && kt > 0.0)
        kt *= 1.0 - RayTracing.SchlickReflectance(Math.Abs(Vector3d.Dot(normal, viewer)), material.n);
      double newImportance = importance * kt;
      if (newImportance < f.MinImportance)
        return hash;
      Vector3d r = haveUnit
        ? Geometry.SpecularRefractionUnit(normal, material.n, viewerUnit)
        : Geometry.SpecularRefraction(normal, material.n, viewer);
      if (r.X == 0.0 && r.Y == 0.0 && r.Z == 0.0)
        return hash;
      hash += RayTracing.HASH_REFRACT * ShadePlain(scratch, bound, depth, newImportance, point, r, comp);
      AddScaled(color, comp, kt);
    }
    return hash;
  }

  /// <summary>
  /// A plain member's hit as the surface-only completion and the textures leave it: the world point, the unit normal facing
  /// the ray, the surface colour (<paramref name="bands"/> values in <paramref name="color"/>). Returns the hash
  /// <see cref="RayCasting.CompleteAndTexture"/> gives (the solid's, then each texture's).
  /// </summary>
  static long Surface(in PreparedMember m, in SolidRecord hit, out Vector3d point, out Vector3d normal, Span<double> color, out int bands)
  {
    HitCompletion shape = m.Completion;
    point = Vector3d.TransformPosition(hit.CoordLocal, m.LocalToWorld);
    // The local normal the solid's hit set-up gives: the point itself on the unit ball, +z on the plane, the face's axis on the cube.
    Vector3d local = shape switch
    {
      HitCompletion.Plane => Vector3d.UnitZ,
      HitCompletion.Cube => Cube.FaceNormal(hit.Data),
      _ => hit.CoordLocal,
    };
    normal = Vector3d.TransformNormalInverse(local, m.WorldToLocal);
    normal.Normalize();
    if (hit.Enter != hit.Front)
      normal = -normal;

    // The member's colour (a hit's own copy in the general path), black when it has none.
    double[]? own = m.Color;
    if (own != null)
    {
      bands = own.Length;
      for (int b = 0; b < bands; b++)
        color[b] = own[b];
    }
    else
    {
      bands = 3;
      color[..3].Clear();
    }

    long hash = m.RecordSolid!.GetHashCode();
    if (m.Textures is { First: not null } textures)
    {
      Vector3d p = hit.CoordLocal;
      Vector2d uv = shape switch
      {
        HitCompletion.Plane => Unsafe.As<Plane>(m.RecordSolid).TextureCoordAt(p),
        HitCompletion.Cube => Cube.TextureCoordAt(p, local),
        _ => Sphere.TextureCoordAt(p, Math.Sqrt(p.X * p.X + p.Y * p.Y)),
      };
      foreach (ITexture texture in textures)
      {
        CheckerTexture checker = Unsafe.As<CheckerTexture>(texture);
        if (checker.IsOdd(uv, out long cell))
        {
          double[] second = checker.Color2;
          bands = second.Length;
          for (int b = 0; b < bands; b++)
            color[b] = second[b];
        }
        hash = hash * RayCasting.HASH_TEXTURE + cell;
      }
    }
    return hash;
  }
}
