using System;
using System.IO;
using System.Linq;

namespace GrCis.Scripting.Tests;

/// <summary>Errors a student can cause are messages naming the file and line.</summary>
public class ErrorTests
{
  readonly ScriptHost host = new();

  [Fact]
  public void Compile_errors_list_every_diagnostic_with_the_users_line_and_column()
  {
    string path = Path.GetFullPath(TestData.Error("CompileErrors.cs"));
    var ex = Assert.Throws<ScriptCompilationException>(() => host.Compile(path));

    ScriptDiagnostic[] errors = ex.Errors.ToArray();
    Assert.Equal(2, errors.Length);
    Assert.Equal($"{path}(5,20): error CS1002: ; expected", errors[0].ToString());
    Assert.StartsWith($"{path}(6,20): error CS0246: The type or namespace name 'NoSuchCamera' could not be found", errors[1].ToString());

    // The exception message carries all of them, one per line.
    string[] lines = ex.Message.Split(Environment.NewLine);
    Assert.Equal(3, lines.Length);
    Assert.Equal($"{path}: 2 compilation errors", lines[0]);
    Assert.Equal(errors[0].ToString(), lines[1]);
    Assert.Equal(errors[1].ToString(), lines[2]);
    Assert.Equal(path, ex.Path);
  }

  [Fact]
  public void Failed_compilation_is_not_cached_and_the_host_stays_usable()
  {
    string path = TestData.Error("CompileErrors.cs");
    Assert.Throws<ScriptCompilationException>(() => host.Compile(path));
    Assert.Throws<ScriptCompilationException>(() => host.Compile(path));
    Assert.Equal(0, host.CachedScriptCount);
    Assert.NotNull(host.Load(TestData.Script("TimeDependent.cs")).Scene);
  }

  [Fact]
  public void Exception_in_a_script_method_reports_the_script_line()
  {
    string path = Path.GetFullPath(TestData.Error("ThrowsInMethod.cs"));
    var ex = Assert.Throws<ScriptRuntimeException>(() => host.Load(path));

    Assert.Equal(path, ex.Path);
    Assert.Equal(7, ex.Line);
    Assert.IsType<IndexOutOfRangeException>(ex.InnerException);
    Assert.StartsWith($"{path}(7,", ex.Message);
    Assert.Contains("runtime error: IndexOutOfRangeException", ex.Message);
  }

  [Fact]
  public void Exception_at_top_level_reports_the_script_line_and_message()
  {
    string path = Path.GetFullPath(TestData.Error("ThrowsTopLevel.cs"));
    var ex = Assert.Throws<ScriptRuntimeException>(() => host.Load(path, ""));

    Assert.Equal(4, ex.Line);
    Assert.Equal(3, ex.Column);
    Assert.Equal($"{path}(4,3): runtime error: ArgumentException: this scene needs a parameter", ex.Message);

    // The same compiled script runs fine with a parameter.
    Assert.NotNull(host.Load(path, "x=1").Scene);
    Assert.Equal(1, host.CompilationCount);
  }

  [Fact]
  public void Missing_script_file_is_a_FileNotFoundException_naming_the_path()
  {
    string path = Path.Combine(TestData.Root, "no-such-scene.cs");
    var ex = Assert.Throws<FileNotFoundException>(() => host.Load(path));
    Assert.Equal(Path.GetFullPath(path), ex.FileName);
    Assert.Equal($"Scene script not found: '{Path.GetFullPath(path)}'", ex.Message);
  }

  [Fact]
  public void Strict_parameters_report_which_value_is_wrong_at_the_script_line()
  {
    string path = Path.GetFullPath(TestData.Script("StrictParams.cs"));
    var ex = Assert.Throws<ScriptRuntimeException>(() => host.Load(path, "n=abc"));

    var inner = Assert.IsType<ScriptParameterException>(ex.InnerException);
    Assert.Equal("n", inner.Key);
    Assert.Equal("abc", inner.Value);
    Assert.Equal(3, ex.Line);
    Assert.Equal($"{path}(3,12): runtime error: ScriptParameterException: parameter 'n' has the value 'abc', expected a number (e.g. 1.5)", ex.Message);

    Assert.Equal(2.5, host.Load(path, "n=2.5").Context["n"]);
    Assert.Equal(1.6, host.Load(path, "").Context["n"]);
  }

  [Fact]
  public void Optimized_scripts_still_report_the_script_path_of_a_runtime_error()
  {
    using var fast = new ScriptHost(optimizeScripts: true);
    string path = Path.GetFullPath(TestData.Error("ThrowsInMethod.cs"));
    var ex = Assert.Throws<ScriptRuntimeException>(() => fast.Load(path));
    Assert.Equal(path, ex.Path);
    Assert.StartsWith(path, ex.Message);
    Assert.IsType<IndexOutOfRangeException>(ex.InnerException);
  }
}
