using System.Collections.Generic;
using System.Reflection;

namespace GrCis.Scripting.Compilation;

/// <summary>
/// The GrCis assemblies scripts and modules compile against, beside the shared framework: GrCis.Rendering
/// (with OpenTK's math types), GrCis.Compatibility (GrCis's classic helpers: Util, Arith, histograms ...) and
/// GrCis.Scripting itself (the globals). Their identity is part of every compiled-script cache key.
/// </summary>
internal static class LibraryAssemblies
{
  public static IReadOnlyList<Assembly> All { get; } =
    new[] { typeof(Rendering.IRayScene).Assembly, typeof(Utilities.Util).Assembly, typeof(ScriptGlobals).Assembly };
}
