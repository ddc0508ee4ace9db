using System;

namespace GrCis.Scripting.Caching;

/// <summary>
/// Whether the compiled-script cache's folder and its secret can be trusted: what the folder holds is code grcis
/// runs, so nobody but the user may be able to put anything there. On Unix the folder must belong to the user and not
/// be writable by group or others (a shared <c>/tmp</c> folder, a mode 777 one, another user's), and the secret must
/// be a regular file of the user's that nobody else may read or write. Windows keeps the cache in the user's own
/// profile, whose access list is the user's; nothing is checked there.
/// </summary>
internal static class CacheFolderTrust
{
  const int GroupWrite = 0x10, OtherWrite = 0x2, GroupOrOther = 0x3F;

  /// <summary>Why <paramref name="directory"/> is not to be used, or null when it is the user's alone to write.</summary>
  public static string? Untrusted(string directory)
  {
    if (OperatingSystem.IsWindows())
      return null;
    if (UnixFileStatus.Of(directory) is not UnixFileStatus folder)
      return "it cannot be examined";
    if (!folder.IsDirectory)
      return "it is not a folder";
    uint me = UnixFileStatus.CurrentUser;
    if (folder.Uid != me)
      return $"it belongs to another user (uid {folder.Uid}, not {me})";
    int writable = folder.Permissions & (GroupWrite | OtherWrite);
    if (writable != 0)
      return $"other users may write it (mode {Octal(folder.Permissions)}, writable by {(writable == OtherWrite ? "others" : writable == GroupWrite ? "its group" : "its group and others")}); " +
             "make it yours alone (chmod 700) or set GRCIS_CACHE_DIR to another folder";
    return null;
  }

  /// <summary>Why the secret at <paramref name="path"/> is not to be used, or null when it is a private regular file of the user's.</summary>
  public static string? UntrustedSecret(string path)
  {
    if (OperatingSystem.IsWindows())
      return null;
    if (UnixFileStatus.OfLink(path) is not UnixFileStatus key)
      return $"its secret '{ScriptCache.KeyFileName}' cannot be examined";
    if (!key.IsRegularFile)
      return $"its secret '{ScriptCache.KeyFileName}' is not a regular file";
    if (key.Uid != UnixFileStatus.CurrentUser)
      return $"its secret '{ScriptCache.KeyFileName}' belongs to another user (uid {key.Uid})";
    if ((key.Permissions & GroupOrOther) != 0)
      return $"its secret '{ScriptCache.KeyFileName}' may be read or written by others (mode {Octal(key.Permissions)}); delete it, and a new one is made";
    return null;
  }

  static string Octal(int mode) => System.Convert.ToString(mode, 8).PadLeft(3, '0');
}
