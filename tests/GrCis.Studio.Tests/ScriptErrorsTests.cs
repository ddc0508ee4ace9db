using System.IO;
using GrCis.Scripting;

namespace GrCis.Studio.Tests;

public sealed class ScriptErrorsTests
{
  [Fact]
  public void Only_the_shown_scripts_diagnostics_are_marked_a_modules_stay_in_the_message()
  {
    string script = Path.GetFullPath(Path.Combine("scripts", "Scene.cs"));
    string module = Path.GetFullPath(Path.Combine("modules", "Helper.cs"));
    ScriptDiagnostic[] found =
    [
      new(module, 4, 9, "error", "CS0103", "The name 'x' does not exist in the current context"),
      new(script, 2, 13, "error", "CS0029", "Cannot implicitly convert type 'string' to 'int'"),
    ];

    ScriptError marked = Assert.Single(ScriptErrors.In(found, Path.Combine("scripts", "Scene.cs")));

    Assert.Equal(new ScriptError(2, 13, "error", "CS0029", "Cannot implicitly convert type 'string' to 'int'"), marked);
    Assert.Empty(ScriptErrors.In(found, null));
  }
}
