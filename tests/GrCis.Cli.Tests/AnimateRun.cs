using System;
using System.IO;
using System.Linq;
using System.Threading;

namespace GrCis.Cli.Tests;

/// <summary>Runs <c>grcis animate</c> in-process with the test scenes of <see cref="TestAnimations"/> registered.</summary>
internal static class AnimateRun
{
  public static CliRun Of(string workingDirectory, params string[] args) => Of(workingDirectory, CancellationToken.None, args);

  public static CliRun Of(string workingDirectory, CancellationToken cancel, params string[] args)
  {
    var output = new StringWriter();
    var error = new StringWriter();
    var env = new CliEnvironment(output, error) { WorkingDirectory = workingDirectory, Cancel = cancel, ExtraScenes = TestAnimations.Find };
    int code = Program.Run(args, env);
    return new CliRun(code, output.ToString(), error.ToString());
  }

  /// <summary>File name → bytes of every file in <paramref name="dir"/> (sorted by name).</summary>
  public static (string Name, byte[] Bytes)[] Snapshot(string dir) =>
    Directory.GetFiles(dir).Order(System.StringComparer.Ordinal)
      .Select(f => (Path.GetFileName(f), File.ReadAllBytes(f))).ToArray();

  public static void AssertSameFiles((string Name, byte[] Bytes)[] expected, (string Name, byte[] Bytes)[] actual)
  {
    Assert.Equal(expected.Select(e => e.Name), actual.Select(a => a.Name));
    for (int i = 0; i < expected.Length; i++)
      Assert.True(expected[i].Bytes.AsSpan().SequenceEqual(actual[i].Bytes), $"{expected[i].Name} differs");
  }
}
