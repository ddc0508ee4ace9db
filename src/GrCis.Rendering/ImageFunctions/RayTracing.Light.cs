using System;
using System.Collections.Generic;
using System.Runtime.CompilerServices;
using MathSupport;
using OpenTK.Mathematics;
using Rendering.Accel;

namespace Rendering;

// RayTracing's lights: one light's direct contribution, the shadow transmittance, and the bands of the mirror's reflectance.
public partial class RayTracing
{
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

  // A material's Kt and index: the shading's scratch copy (exactly a PhongMaterial) without an interface call.
  [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
  static double Kt(IMaterial m) =>
    m.GetType() == typeof(PhongMaterial) ? System.Runtime.CompilerServices.Unsafe.As<PhongMaterial>(m).Kt : m.Kt;

  [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
  static double Index(IMaterial m) =>
    m.GetType() == typeof(PhongMaterial) ? System.Runtime.CompilerServices.Unsafe.As<PhongMaterial>(m).n : m.n;

  /// <summary>
  /// Fraction of light passing from <paramref name="p0"/> to the light at <c>p0 + dir</c>: the product
  /// of the Kt of every surface entered on the way (0 = blocked). Uses the faithful all-hits query.
  /// </summary>
  protected virtual double ShadowTransmittance(Vector3d p0, Vector3d dir)
  {
    LinkedList<Intersection>? list = IntersectScene(p0, dir);
    if (list == null)
      return 1.0;
    double transmit = 1.0;
    double len2 = dir.LengthSquared;
    bool first = true;
    foreach (Intersection hit in list)
    {
      if (hit.T <= 0.0 || hit.T * hit.T * len2 <= Intersection.RAY_EPSILON2)
        continue;
      if (hit.Far(1.0, ref dir))
        break;
      if (hit.Solid != null && hit.Solid.GetLocalAttribute(PropertyName.NO_SHADOW) != null)
        continue;
      // Count each solid once: where the ray enters it, or at its exit when the ray starts inside.
      if (hit.Enter || first)
      {
        double kt = (hit.Solid?.GetAttribute(PropertyName.MATERIAL) as IMaterial)?.Kt ?? 0.0;
        transmit *= kt;
        if (transmit <= 0.0)
          return 0.0;
      }
      first = false;
    }
    return transmit;
  }

  /// <summary>Adds one light's direct contribution (shadow ray included) to <paramref name="color"/>; returns the hash.</summary>
  long AddLight(ShadingScratch scratch, ILightSource source, Intersection i, Vector3d viewer, bool phong, double[] surface, Span<double> buffer, double[] color, long hash)
  {
    // The library's point and ambient lights directly: no interface call, with or without a profile (see LibraryScene).
    double[]? intensity;
    Vector3d dir;
    if (source.GetType() == typeof(PointLightSource))
      intensity = Unsafe.As<PointLightSource>(source).Intensity(i, out dir);
    else if (source.GetType() == typeof(AmbientLightSource))
      intensity = Unsafe.As<AmbientLightSource>(source).Intensity(out dir);
    else
      intensity = source.GetIntensity(i, out dir);
    if (rayRegisterer != null && MT.singleRayTracing && source.position is Vector3d lightPosition)
      rayRegisterer.RegisterRay(AbstractRayRegisterer.RayType.rayVisualizerShadow, i.CoordWorld, lightPosition);
    if (intensity == null)
      return hash;
    double transmit = 1.0;
    if (DoShadows && (dir.X != 0.0 || dir.Y != 0.0 || dir.Z != 0.0))
    {
      if (TransparentShadows)
      {
        scratch.Rays++;
        transmit = ShadowTransmittance(i.CoordWorld, dir);
      }
      else
        transmit = Blocked(scratch, i.CoordWorld, dir) ? 0.0 : 1.0;
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
      PhongModel.ColorReflection((PhongMaterial)i.Material!, i.Normal, dir, viewer, ReflectionComponent.ALL, r);
      AddLit(color, transmit, intensity, r);
    }
    else
    {
      double[]? arr = i.ReflectanceModel!.ColorReflection(i, dir, viewer, ReflectionComponent.ALL);
      if (arr == null)
        return hash;
      AddLit(color, transmit, intensity, arr);
    }
    return hash * HASH_LIGHT + source.GetHashCode();
  }

  /// <summary>
  /// color += transmit · light · reflected, band by band; a light or reflectance with fewer bands repeats its last one.
  /// </summary>
  [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
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
}
