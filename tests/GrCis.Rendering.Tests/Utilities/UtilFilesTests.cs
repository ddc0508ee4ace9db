using System;
using System.IO;
using Utilities;

namespace GrCis.Rendering.Tests.Utilities;

// These tests move the process's current folder: nothing may run beside them.
[CollectionDefinition(nameof(CurrentDirectoryCollection), DisableParallelization = true)]
public class CurrentDirectoryCollection { }

/// <summary>GrCis's file helpers, which work relative to the current folder.</summary>
[Collection(nameof(CurrentDirectoryCollection))]
public class UtilFilesTests
{
  [Fact]
  public void Files_are_found_upwards_read_whole_and_made_relative()
  {
    string root = Path.Combine(Path.GetTempPath(), "grcis-util-" + Guid.NewGuid().ToString("N"));
    string deep = Path.Combine(root, "a", "b");
    Directory.CreateDirectory(deep);
    Directory.CreateDirectory(Path.Combine(root, "a", "data"));
    string old = Directory.GetCurrentDirectory();
    string missing = "missing-" + Guid.NewGuid().ToString("N") + ".txt";
    try
    {
      File.WriteAllText(Path.Combine(root, "top.txt"), "héllo\nworld");
      File.WriteAllText(Path.Combine(root, "a", "data", "hinted.txt"), "x");
      Directory.SetCurrentDirectory(deep);
      Assert.Equal("../../top.txt", Util.FindSourceFile("top.txt"));
      Assert.Equal("../data/hinted.txt", Util.FindSourceFile("hinted.txt", "data"));
      Assert.Null(Util.FindSourceFile("hinted.txt"));
      Assert.Null(Util.FindSourceFile(missing, "data"));

      Assert.True(Util.ReadTextFile("../../top.txt", out string text));
      Assert.Equal("héllo\nworld", text);
      Assert.False(Util.ReadTextFile(missing, out text));
      Assert.Equal("", text);

      Assert.Equal("../data/hinted.txt", Util.MakeRelativePath(deep, Path.Combine(root, "a", "data", "hinted.txt")));
      Assert.Equal("b", Util.MakeRelativePath("..", "."));
      Assert.Throws<ArgumentNullException>(() => Util.MakeRelativePath("", "x"));
    }
    finally
    {
      Directory.SetCurrentDirectory(old);
      Directory.Delete(root, recursive: true);
    }
  }
}
