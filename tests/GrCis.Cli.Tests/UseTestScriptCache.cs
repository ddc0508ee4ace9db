using System.Runtime.CompilerServices;

namespace GrCis.Cli.Tests;

/// <summary>Before any test: compiled scripts go to a folder of the test process, not the user's cache (see TestScriptCache).</summary>
internal static class UseTestScriptCache
{
#pragma warning disable CA2255 // a module initializer in a test assembly is what sets the environment up before any test
  [ModuleInitializer]
  internal static void Run() => GrCis.TestSupport.TestScriptCache.Use();
#pragma warning restore CA2255
}
