using System.Collections.Generic;

namespace GrCis.Scripting.Compilation;

/// <summary>
/// What compiling a scene script yields, before it is loaded: the assembly and its PDB, the entry point,
/// the warnings and the way back to the user's lines. A fresh compilation and the compiled-script cache
/// both hand one to <see cref="ScriptLoader"/>, so a cached script runs exactly as a fresh one.
/// </summary>
internal sealed record ScriptImage(
  string AssemblyName,
  byte[] Assembly,
  byte[] Pdb,
  string EntryType,
  string EntryMethod,
  IReadOnlyList<ScriptDiagnostic> Warnings,
  SourceMap Map);
