using System.Collections.Generic;

namespace GrCis.Scripting.Compilation;

/// <summary>
/// What compiling module folders yields, before it is loaded (see <see cref="ScriptImage"/>): the assembly, its
/// PDB and its XML documentation (the editor's hover shows the module's doc comments), which files were compiled and which left out as scene scripts, the warnings, the way back to the
/// user's lines in each file, and the types renamed because the library has them too.
/// </summary>
internal sealed record ModuleImage(
  string AssemblyName,
  byte[] Assembly,
  byte[] Pdb,
  byte[] Documentation,
  IReadOnlyList<string> Files,
  IReadOnlyList<string> SkippedScripts,
  IReadOnlyList<ScriptDiagnostic> Warnings,
  IReadOnlyDictionary<string, SourceMap> Maps,
  IReadOnlyList<ShadowedLibraryTypes.Renamed> Renamed);
