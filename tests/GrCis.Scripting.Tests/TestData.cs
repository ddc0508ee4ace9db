using System.IO;

namespace GrCis.Scripting.Tests;

/// <summary>Paths of the scripts and modules copied beside the test assembly.</summary>
internal static class TestData
{
  public static string Root => Path.Combine(System.AppContext.BaseDirectory, "TestData");

  public static string Script(string name) => Path.Combine(Root, "scripts", name);

  public static string Error(string name) => Path.Combine(Root, "errors", name);

  public static string Module(string name) => Path.Combine(Root, "modules", name);
}
