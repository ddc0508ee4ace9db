using System;
using System.Runtime.InteropServices;

namespace GrCis.Bench.Embree;

/// <summary>
/// One triangle mesh in an Embree device and scene (vertex and index buffers shared from native memory
/// this object owns), built at a given quality; single-ray closest-hit and occlusion queries, and
/// 16-ray packets. Thread-safe for queries once built.
/// </summary>
internal sealed unsafe class EmbreeScene : IDisposable
{
  IntPtr device, scene;
  float* vertices;
  uint* indices;

  /// <summary>Seconds the scene's commit (the BVH build) took.</summary>
  public double BuildSeconds { get; }

  /// <param name="positions">x, y, z per vertex.</param>
  /// <param name="triangles">Three vertex indices per triangle.</param>
  /// <param name="quality">EmbreeNative.BuildQuality*.</param>
  /// <param name="config">rtcNewDevice's configuration ("threads=1"), or null.</param>
  public EmbreeScene(ReadOnlySpan<float> positions, ReadOnlySpan<int> triangles, int quality, string? config)
  {
    EmbreeNative.Require();
    device = EmbreeNative.NewDevice(config);
    if (device == IntPtr.Zero)
      throw new InvalidOperationException("rtcNewDevice failed (error " + EmbreeNative.GetDeviceError(IntPtr.Zero) + ")");
    // Embree reads vertex buffers 16 bytes at a time: one float of padding after the last vertex.
    vertices = (float*)NativeMemory.AlignedAlloc((nuint)(positions.Length + 4) * sizeof(float), 16);
    positions.CopyTo(new Span<float>(vertices, positions.Length));
    indices = (uint*)NativeMemory.AlignedAlloc((nuint)Math.Max(triangles.Length, 3) * sizeof(uint), 16);
    MemoryMarshal.Cast<int, uint>(triangles).CopyTo(new Span<uint>(indices, triangles.Length));

    var clock = System.Diagnostics.Stopwatch.StartNew();
    scene = EmbreeNative.NewScene(device);
    EmbreeNative.SetSceneBuildQuality(scene, quality);
    IntPtr geometry = EmbreeNative.NewGeometry(device, EmbreeNative.GeometryTypeTriangle);
    EmbreeNative.SetGeometryBuildQuality(geometry, quality);
    EmbreeNative.SetSharedGeometryBuffer(geometry, EmbreeNative.BufferTypeVertex, 0, EmbreeNative.FormatFloat3, vertices, 0, 3 * sizeof(float), (nuint)(positions.Length / 3));
    EmbreeNative.SetSharedGeometryBuffer(geometry, EmbreeNative.BufferTypeIndex, 0, EmbreeNative.FormatUInt3, indices, 0, 3 * sizeof(uint), (nuint)(triangles.Length / 3));
    EmbreeNative.CommitGeometry(geometry);
    EmbreeNative.AttachGeometry(scene, geometry);
    EmbreeNative.ReleaseGeometry(geometry);
    EmbreeNative.CommitScene(scene);
    BuildSeconds = clock.Elapsed.TotalSeconds;
    int error = EmbreeNative.GetDeviceError(device);
    if (error != 0)
      throw new InvalidOperationException("Embree reported error " + error + " while building the scene");
  }

  /// <summary>Closest hit of <paramref name="rh"/> (16-byte aligned; its TFar becomes the hit's t): true on a hit.</summary>
  public bool Intersect(EmbreeNative.RayHit* rh)
  {
    EmbreeNative.IntersectContext context = EmbreeNative.IntersectContext.Create(false);
    rh->Hit.GeomId = EmbreeNative.InvalidGeometryId;
    EmbreeNative.Intersect1(scene, &context, rh);
    return rh->Hit.GeomId != EmbreeNative.InvalidGeometryId;
  }

  /// <summary>True when some triangle lies on <paramref name="ray"/>'s segment [TNear, TFar] (16-byte aligned).</summary>
  public bool Occluded(EmbreeNative.Ray* ray)
  {
    EmbreeNative.IntersectContext context = EmbreeNative.IntersectContext.Create(false);
    EmbreeNative.Occluded1(scene, &context, ray);
    // Embree marks an occluded ray by setting tfar to −∞.
    return ray->TFar < 0.0f;
  }

  /// <summary>Closest hits of the first <paramref name="count"/> rays of a packet, with the coherent context; the packet and the 16 ints of <paramref name="valid"/> 64-byte aligned.</summary>
  public void Intersect16(EmbreeNative.RayHit16* packet, int* valid, int count)
  {
    EmbreeNative.IntersectContext context = EmbreeNative.IntersectContext.Create(true);
    for (int k = 0; k < 16; k++)
    {
      valid[k] = k < count ? -1 : 0;
      packet->GeomId[k] = EmbreeNative.InvalidGeometryId;
    }
    EmbreeNative.Intersect16(valid, scene, &context, packet);
  }

  public void Dispose()
  {
    if (scene != IntPtr.Zero)
      EmbreeNative.ReleaseScene(scene);
    if (device != IntPtr.Zero)
      EmbreeNative.ReleaseDevice(device);
    scene = device = IntPtr.Zero;
    NativeMemory.AlignedFree(vertices);
    NativeMemory.AlignedFree(indices);
    vertices = null;
    indices = null;
  }
}
