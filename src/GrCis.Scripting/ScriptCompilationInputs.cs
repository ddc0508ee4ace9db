using System;
using System.Collections.Generic;
using System.Collections.Immutable;
using GrCis.Scripting.Compilation;
using Microsoft.CodeAnalysis;

namespace GrCis.Scripting;

/// <summary>
/// What a scene script is compiled with, for tools that must see a script exactly as the compiler does (the
/// editor's completion, hover and diagnostics): the namespaces it imports and the assemblies it references.
/// </summary>
public static class ScriptCompilationInputs
{
  /// <summary>The namespaces every script imports: GrCis's defaults and each module's own.</summary>
  public static ImmutableArray<string> Imports(IReadOnlyList<ScriptModule> modules) => ScriptCompiler.ScriptImports(modules);

  /// <summary>The framework and GrCis assemblies every script references (shared objects, created once per process).</summary>
  public static IReadOnlyList<MetadataReference> FrameworkReferences => Compilation.FrameworkReferences.All;

  /// <summary>A compiled module as a reference, with a provider of its doc comments (see <see cref="ModuleDocumentation"/>) or none.</summary>
  public static MetadataReference ModuleReference(ScriptModule module, DocumentationProvider? documentation = null) =>
    MetadataReference.CreateFromImage(module.Image, documentation: documentation);

  /// <summary>The module's XML doc comments as its compilation wrote them; empty when it has none.</summary>
  public static byte[] ModuleDocumentation(ScriptModule module) => (byte[])module.Documentation.Clone();
}
