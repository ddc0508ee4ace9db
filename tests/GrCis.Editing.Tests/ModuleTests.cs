using System.IO;
using System.Linq;
using System.Threading.Tasks;
using GrCis.Scripting;

namespace GrCis.Editing.Tests;

public sealed class ModuleTests
{
  [Fact]
  public async Task A_modules_types_and_their_doc_comments_are_known_to_the_script()
  {
    string dir = Directory.CreateTempSubdirectory("grcis-editing-module-").FullName;
    try
    {
      File.WriteAllText(Path.Combine(dir, "Checker.cs"), """
        namespace Homework;

        /// <summary>A two-colour checkerboard texture.</summary>
        public class CheckerTexture
        {
          /// <summary>Squares per unit.</summary>
          public double Frequency { get; set; } = 4;
        }
        """);
      using var host = new ScriptHost();
      host.AddModule(dir);
      using var assistant = new ScriptAssistant(host.Modules);

      const string source = "var t = new Homework.CheckerTexture(); t.";
      CompletionResult result = await assistant.CompleteAsync(source, source.Length);
      Assert.Contains(result.Items, i => i.Label == "Frequency");
      CompletionEntry? frequency = await assistant.DescribeAsync(source, source.Length, "Frequency");
      Assert.Equal("Squares per unit.", frequency?.Documentation);

      const string declared = "Homework.CheckerTexture t = null;";
      HoverInfo? hover = await assistant.HoverAsync(declared, declared.IndexOf("Checker", System.StringComparison.Ordinal) + 1);
      Assert.NotNull(hover);
      Assert.Contains("CheckerTexture", hover.Text);
      Assert.Equal("A two-colour checkerboard texture.", hover.Documentation);
    }
    finally
    {
      Directory.Delete(dir, recursive: true);
    }
  }
}
