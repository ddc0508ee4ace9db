using System;
using System.IO;
using System.Text;

namespace GrCis.Interactive;

/// <summary>Writes a text file through a temporary sibling and a rename: never a half-written export.</summary>
internal static class AtomicText
{
  public static void Write(string path, Action<TextWriter> write)
  {
    ArgumentException.ThrowIfNullOrEmpty(path);
    string full = Path.GetFullPath(path);
    string temp = full + ".tmp-" + Guid.NewGuid().ToString("N")[..12];
    try
    {
      // Created new: a file or link of that name (planted, however unlikely the name) is never written through.
      using (var w = new StreamWriter(new FileStream(temp, FileMode.CreateNew, FileAccess.Write, FileShare.None), new UTF8Encoding(false)))
      {
        w.NewLine = "\n";
        write(w);
      }
      File.Move(temp, full, overwrite: true);
    }
    catch
    {
      try { File.Delete(temp); } catch (IOException) { } catch (UnauthorizedAccessException) { }
      throw;
    }
  }
}
