using System;
using System.IO;
using GrCis.TestSupport;

namespace GrCis.Cli.Tests;

/// <summary>
/// A recursion without end in a student's code, while the scene is built, in a class of the script that rendering
/// calls on a worker thread, or in a module, ends <c>grcis</c> with one error line naming the recursive call's file and
/// line (exit 1), not a stack overflow that kills the process without a word (exit 134). Run as a process: a stack
/// overflow would take the test host down with it.
/// </summary>
public class RecursionProcessTests
{
  const string Scene = """
    var root = new CSGInnerNode(SetOperation.Union);
    var s = new Sphere();
    s.SetAttribute(PropertyName.TEXTURE, new Deep());
    root.InsertChild(s, Matrix4d.Identity);
    scene.Intersectable = root;
    """;

  static void AssertRecursionError(TempDirectory dir, string file, int line, params string[] args)
  {
    (int code, string output, string error) = GrcisProcess.Run(dir.Path, args);
    Assert.True(code == ExitCodes.Failure, $"exit {code}\n{output}\n{error}");
    string last = error.TrimEnd().Split('\n')[^1];
    Assert.StartsWith($"grcis: error: {file}({line},", last);
    Assert.Contains("runtime error: RecursionTooDeepException: recursion deeper than", last);
    Assert.DoesNotContain(dir.AllFiles(), f => f.EndsWith(".png", StringComparison.Ordinal));
  }

  [Fact]
  public void A_recursion_at_the_top_level_is_an_error_at_its_line()
  {
    using var dir = new TempDirectory();
    string path = dir.File("deep.cs");
    File.WriteAllText(path, StuckScripts.Camera + "\nint F(int n) => n < 0 ? 0 : F(n + 1) + 1;\nF(0);\n");
    AssertRecursionError(dir, path, 4, "render", "deep.cs", "-o", "out.png", "--size", "16x12", "-q");
  }

  [Fact]
  public void A_recursion_in_a_texture_on_the_render_threads_is_an_error_at_its_line()
  {
    using var dir = new TempDirectory();
    string path = dir.File("texture.cs");
    File.WriteAllText(path, StuckScripts.Camera + "\n" + Scene + """

      class Deep : ITexture
      {
        int Down(int n) => n < 0 ? 0 : Down(n + 1) + 1;
        public long Apply(Intersection inter) => Down(0);
      }
      """);
    AssertRecursionError(dir, path, 11, "render", "texture.cs", "-o", "out.png", "--size", "64x48", "--threads", "2", "-q");
  }

  [Fact]
  public void A_recursion_in_a_module_is_an_error_at_the_module_line()
  {
    using var dir = new TempDirectory();
    Directory.CreateDirectory(dir.File("mod"));
    string module = dir.File(Path.Combine("mod", "Deep.cs"));
    File.WriteAllText(module, """
      using Rendering;

      public class Deep : ITexture
      {
        public long Apply(Intersection inter)
        {
          return Apply(inter) + 1;
        }
      }
      """);
    File.WriteAllText(dir.File("uses.cs"), StuckScripts.Camera + "\n" + Scene + "\n");
    AssertRecursionError(dir, module, 7, "render", "uses.cs", "--module", "mod", "-o", "out.png", "--size", "16x12", "-q");
  }
}
