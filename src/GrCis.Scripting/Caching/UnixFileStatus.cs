using System;
using System.Runtime.InteropServices;

namespace GrCis.Scripting.Caching;

/// <summary>
/// A file's type, owner and permissions on Unix, as <c>stat</c>/<c>lstat</c> give them: .NET has no API for a file's
/// owner, so this asks the runtime's own native shim (<c>libSystem.Native</c>, shipped with every .NET on Unix), whose
/// status record starts with flags, mode, uid and gid on every platform.
/// </summary>
internal readonly record struct UnixFileStatus(int Mode, uint Uid, long Size)
{
  const int TypeMask = 0xF000, Directory = 0x4000, Regular = 0x8000;

  public bool IsDirectory => (Mode & TypeMask) == Directory;

  public bool IsRegularFile => (Mode & TypeMask) == Regular;

  /// <summary>The permission bits (rwxrwxrwx and set-id, sticky).</summary>
  public int Permissions => Mode & 0xFFF;

  /// <summary>The effective user id of this process.</summary>
  public static uint CurrentUser => GetEUid();

  /// <summary>The status of <paramref name="path"/> itself (a link is not followed), or null when there is none.</summary>
  public static UnixFileStatus? OfLink(string path) => Convert(LStat(path, out NativeStatus s), s);

  /// <summary>The status of what <paramref name="path"/> leads to (links followed), or null when there is none.</summary>
  public static UnixFileStatus? Of(string path) => Convert(Stat(path, out NativeStatus s), s);

  static UnixFileStatus? Convert(int result, NativeStatus s) => result == 0 ? new UnixFileStatus(s.Mode, s.Uid, s.Size) : null;

  // The shim's FileStatus begins with these fields; the size leaves room for the rest, whatever the runtime version adds.
  [StructLayout(LayoutKind.Sequential, Size = 512)]
  struct NativeStatus
  {
    public int Flags;
    public int Mode;
    public uint Uid;
    public uint Gid;
    public long Size;
  }

  [DllImport("libSystem.Native", EntryPoint = "SystemNative_LStat")]
  static extern int LStat([MarshalAs(UnmanagedType.LPUTF8Str)] string path, out NativeStatus status);

  [DllImport("libSystem.Native", EntryPoint = "SystemNative_Stat")]
  static extern int Stat([MarshalAs(UnmanagedType.LPUTF8Str)] string path, out NativeStatus status);

  [DllImport("libSystem.Native", EntryPoint = "SystemNative_GetEUid")]
  static extern uint GetEUid();
}
