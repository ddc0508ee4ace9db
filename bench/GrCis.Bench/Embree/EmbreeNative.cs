using System;
using System.Runtime.InteropServices;

namespace GrCis.Bench.Embree;

/// <summary>
/// The few entry points of Intel Embree 3 (Debian's libembree3-3) the comparison needs, with the structure
/// layouts of its headers (embree3/rtcore_ray.h, rtcore_common.h; RTC_MAX_INSTANCE_LEVEL_COUNT = 1,
/// RTC_MIN_WIDTH = 0 in Debian's build). The benchmark's only native dependency: the library never loads it.
/// </summary>
internal static unsafe partial class EmbreeNative
{
  const string Library = "embree3";

  /// <summary>The Debian package that ships the library.</summary>
  public const string DebianPackage = "libembree3-3";

  // The runtime package ships only the versioned name (libembree3.so.3); libembree3.so comes with -dev.
  static readonly string[] Candidates = { "libembree3.so.3", "libembree3.so", "embree3", "libembree3.dylib" };
  static IntPtr handle;

  static EmbreeNative() =>
    NativeLibrary.SetDllImportResolver(typeof(EmbreeNative).Assembly, (name, _, _) => name == Library ? Load() : IntPtr.Zero);

  /// <summary>True when the library can be loaded on this machine.</summary>
  public static bool IsAvailable => Load() != IntPtr.Zero;

  /// <summary>Loads the library or throws with the package to install.</summary>
  public static void Require()
  {
    if (!IsAvailable)
      throw new EmbreeMissingException($"Intel Embree 3 (libembree3.so.3) is not installed: install the Debian package '{DebianPackage}' (apt-get install -y {DebianPackage})");
  }

  static IntPtr Load()
  {
    if (handle != IntPtr.Zero)
      return handle;
    foreach (string name in Candidates)
      if (NativeLibrary.TryLoad(name, out IntPtr h))
        return handle = h;
    return IntPtr.Zero;
  }

  public const int GeometryTypeTriangle = 0;
  public const int BufferTypeIndex = 0, BufferTypeVertex = 1;
  public const int FormatUInt3 = 0x5003, FormatFloat3 = 0x9003;
  public const int BuildQualityLow = 0, BuildQualityMedium = 1, BuildQualityHigh = 2;
  public const int ContextFlagIncoherent = 0, ContextFlagCoherent = 1;
  public const uint InvalidGeometryId = uint.MaxValue;

  [StructLayout(LayoutKind.Sequential)]
  public struct IntersectContext
  {
    public int Flags;
    public IntPtr Filter;
    public uint InstId;

    /// <summary>rtcInitIntersectContext (an inline function of the header).</summary>
    public static IntersectContext Create(bool coherent) =>
      new() { Flags = coherent ? ContextFlagCoherent : ContextFlagIncoherent, Filter = IntPtr.Zero, InstId = InvalidGeometryId };
  }

  /// <summary>RTCRay: 48 bytes, 16-byte aligned.</summary>
  [StructLayout(LayoutKind.Sequential, Size = 48)]
  public struct Ray
  {
    public float OrgX, OrgY, OrgZ, TNear;
    public float DirX, DirY, DirZ, Time;
    public float TFar;
    public uint Mask, Id, Flags;
  }

  /// <summary>RTCHit: 32 bytes.</summary>
  [StructLayout(LayoutKind.Sequential, Size = 32)]
  public struct Hit
  {
    public float NgX, NgY, NgZ, U, V;
    public uint PrimId, GeomId, InstId;
  }

  /// <summary>RTCRayHit: the ray, then the hit (80 bytes).</summary>
  [StructLayout(LayoutKind.Sequential, Size = 80)]
  public struct RayHit
  {
    public Ray Ray;
    public Hit Hit;
  }

  /// <summary>RTCRayHit16: sixteen rays in SoA layout (12 arrays of the ray, 8 of the hit), 64-byte aligned.</summary>
  [StructLayout(LayoutKind.Sequential, Size = 20 * 64)]
  public struct RayHit16
  {
    public fixed float OrgX[16];
    public fixed float OrgY[16];
    public fixed float OrgZ[16];
    public fixed float TNear[16];
    public fixed float DirX[16];
    public fixed float DirY[16];
    public fixed float DirZ[16];
    public fixed float Time[16];
    public fixed float TFar[16];
    public fixed uint Mask[16];
    public fixed uint Id[16];
    public fixed uint Flags[16];
    public fixed float NgX[16];
    public fixed float NgY[16];
    public fixed float NgZ[16];
    public fixed float U[16];
    public fixed float V[16];
    public fixed uint PrimId[16];
    public fixed uint GeomId[16];
    public fixed uint InstId[16];
  }

  [LibraryImport(Library, EntryPoint = "rtcNewDevice", StringMarshalling = StringMarshalling.Utf8)]
  public static partial IntPtr NewDevice(string? config);

  [LibraryImport(Library, EntryPoint = "rtcReleaseDevice")]
  public static partial void ReleaseDevice(IntPtr device);

  [LibraryImport(Library, EntryPoint = "rtcGetDeviceError")]
  public static partial int GetDeviceError(IntPtr device);

  [LibraryImport(Library, EntryPoint = "rtcNewScene")]
  public static partial IntPtr NewScene(IntPtr device);

  [LibraryImport(Library, EntryPoint = "rtcReleaseScene")]
  public static partial void ReleaseScene(IntPtr scene);

  [LibraryImport(Library, EntryPoint = "rtcSetSceneBuildQuality")]
  public static partial void SetSceneBuildQuality(IntPtr scene, int quality);

  [LibraryImport(Library, EntryPoint = "rtcNewGeometry")]
  public static partial IntPtr NewGeometry(IntPtr device, int type);

  [LibraryImport(Library, EntryPoint = "rtcSetGeometryBuildQuality")]
  public static partial void SetGeometryBuildQuality(IntPtr geometry, int quality);

  [LibraryImport(Library, EntryPoint = "rtcSetSharedGeometryBuffer")]
  public static partial void SetSharedGeometryBuffer(IntPtr geometry, int type, uint slot, int format, void* ptr, nuint byteOffset, nuint byteStride, nuint itemCount);

  [LibraryImport(Library, EntryPoint = "rtcCommitGeometry")]
  public static partial void CommitGeometry(IntPtr geometry);

  [LibraryImport(Library, EntryPoint = "rtcAttachGeometry")]
  public static partial uint AttachGeometry(IntPtr scene, IntPtr geometry);

  [LibraryImport(Library, EntryPoint = "rtcReleaseGeometry")]
  public static partial void ReleaseGeometry(IntPtr geometry);

  [LibraryImport(Library, EntryPoint = "rtcCommitScene")]
  public static partial void CommitScene(IntPtr scene);

  [LibraryImport(Library, EntryPoint = "rtcIntersect1")]
  public static partial void Intersect1(IntPtr scene, IntersectContext* context, RayHit* rayhit);

  [LibraryImport(Library, EntryPoint = "rtcOccluded1")]
  public static partial void Occluded1(IntPtr scene, IntersectContext* context, Ray* ray);

  [LibraryImport(Library, EntryPoint = "rtcIntersect16")]
  public static partial void Intersect16(int* valid, IntPtr scene, IntersectContext* context, RayHit16* rayhit);
}
