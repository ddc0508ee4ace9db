using System.Collections.Generic;
using System.Reflection;

namespace GrCis.Scripting.Compilation;

/// <summary>
/// The GrCis assemblies scripts and modules compile against, beside the shared framework: GrCis.Mathematics
/// (OpenTK's math types, namespace OpenTK.Mathematics), GrCis.Rendering, GrCis.Compatibility (GrCis's classic
/// helpers: Util, Arith, histograms ...) and GrCis.Scripting itself (the globals). Their identity is part of every
/// compiled-script cache key.
/// </summary>
internal static class LibraryAssemblies
{
  public static IReadOnlyList<Assembly> All { get; } =
    new[]
    {
      typeof(OpenTK.Mathematics.Vector3d).Assembly, typeof(Rendering.IRayScene).Assembly, typeof(Utilities.Util).Assembly,
      typeof(ScriptGlobals).Assembly,
    };
}
