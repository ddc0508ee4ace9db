using System;
using System.IO;
using System.Linq;

namespace GrCis.Scripting.Tests;

/// <summary>
/// A <c>using</c> of a namespace .NET 10 does not have (GrCis-era WinForms, OpenGL, Remoting) is dropped
/// with a warning when nothing needs it, and explained when something does.
/// </summary>
public sealed class MissingNamespaceTests : IDisposable
{
  readonly ScriptHost host = new();
  readonly ScratchFolder scratch = new("grcis-usings-");

  public void Dispose()
  {
    host.Dispose();
    scratch.Dispose();
  }

  string Write(string relative, string text) => scratch.Write(relative, text);

  [Fact]
  public void An_unused_using_of_a_missing_namespace_is_ignored_with_a_warning_at_its_line()
  {
    string path = Write("scene.cs", """
      using System.Windows.Forms;
      using System.Runtime.Remoting.Messaging;
      context["ok"] = 1;
      """);
    CompiledScript script = host.Compile(path);
    Assert.Equal(1, host.Run(script).Context["ok"]);
    ScriptDiagnostic[] warnings = script.Warnings.Where(w => w.Id == ScriptDiagnostic.MissingNamespaceId).ToArray();
    Assert.Equal(2, warnings.Length);
    Assert.Equal((1, 1), (warnings[0].Line, warnings[0].Column));
    Assert.Contains("'using System.Windows.Forms;' was ignored", warnings[0].Message);
    Assert.Contains("WinForms", warnings[0].Message);
    Assert.Equal(2, warnings[1].Line);
    Assert.Contains("Remoting", warnings[1].Message);
  }

  [Fact]
  public void A_used_missing_namespace_is_explained_before_the_errors_it_causes()
  {
    string path = Write("scene.cs", """
      using System.Windows.Forms;
      for (int i = 0; i < 1; i++) { }
      MessageBox.Show("hello");
      """);
    var ex = Assert.Throws<ScriptCompilationException>(() => host.Compile(path));
    ScriptDiagnostic[] errors = ex.Errors.ToArray();
    Assert.Equal(ScriptDiagnostic.MissingNamespaceId, errors[0].Id);
    Assert.Equal(1, errors[0].Line);
    Assert.Contains("namespace 'System.Windows.Forms' does not exist here", errors[0].Message);
    ScriptDiagnostic messageBox = errors.Single(e => e.Id == "CS0103");
    Assert.Equal((3, 1), (messageBox.Line, messageBox.Column));
  }

  [Fact]
  public void A_module_file_with_OpenGL_usings_compiles_when_it_only_uses_math()
  {
    Write("mod/Shapes.cs", """
      using System;
      using OpenTK;
      using OpenTK.Graphics.OpenGL;

      namespace Shapes
      {
        public static class Size
        {
          public static double Of (Vector3d v) => v.Length;
        }
      }
      """);
    ScriptModule module = host.AddModule(Path.Combine(scratch.Path, "mod"));
    ScriptDiagnostic warning = Assert.Single(module.Warnings, w => w.Id == ScriptDiagnostic.MissingNamespaceId);
    Assert.Equal(3, warning.Line);
    Assert.EndsWith("Shapes.cs", warning.Path);
    Assert.Contains("OpenTK.Mathematics", warning.Message);
    string script = Write("use.cs", "context[\"len\"] = Shapes.Size.Of(new Vector3d(3, 4, 0));\n");
    Assert.Equal(5.0, host.Load(script).Context["len"]);
  }

  [Fact]
  public void A_missing_namespace_of_the_users_own_stays_the_compilers_error()
  {
    // Usually a forgotten --module: the compiler's "could not be found" says that best.
    string path = Write("scene.cs", "using MyLibrary;\ncontext[\"x\"] = 1;\n");
    var ex = Assert.Throws<ScriptCompilationException>(() => host.Compile(path));
    ScriptDiagnostic error = Assert.Single(ex.Errors);
    Assert.Equal("CS0246", error.Id);
    Assert.Equal(1, error.Line);
  }
}
