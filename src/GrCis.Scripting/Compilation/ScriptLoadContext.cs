using System.Collections.Generic;
using System.Reflection;
using System.Runtime.Loader;

namespace GrCis.Scripting.Compilation;

/// <summary>
/// A collectible load context for one compiled script or module. Module assemblies it references are
/// resolved from their own contexts; everything else (framework, GrCis.Rendering) from the default one,
/// so scripts share the host's types.
/// </summary>
internal sealed class ScriptLoadContext : AssemblyLoadContext
{
  readonly IReadOnlyDictionary<string, Assembly> modules;

  public ScriptLoadContext(string name, IReadOnlyDictionary<string, Assembly> modules)
    : base(name, isCollectible: true)
  {
    this.modules = modules;
  }

  protected override Assembly? Load(AssemblyName assemblyName) =>
    assemblyName.Name != null && modules.TryGetValue(assemblyName.Name, out Assembly? a) ? a : null;
}
