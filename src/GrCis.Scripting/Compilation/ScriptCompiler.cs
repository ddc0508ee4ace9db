using System;
using System.Collections.Generic;
using System.Collections.Immutable;
using System.IO;
using System.Linq;
using System.Runtime.CompilerServices;
using System.Text;
using System.Threading;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.Emit;
using Microsoft.CodeAnalysis.Text;

namespace GrCis.Scripting.Compilation;

/// <summary>
/// Compiles scene scripts (Roslyn's script dialect, as a script compilation with a globals type) and
/// modules (regular compilations) to in-memory assemblies with portable PDBs, loaded into collectible
/// contexts. This is what Roslyn's CSharpScript does internally, minus its non-collectible loader.
/// </summary>
internal static class ScriptCompiler
{
  /// <summary>Namespaces a script sees without a <c>using</c>: GrCis's list (OpenTK's vector types live in OpenTK.Mathematics), plus Scene3D, where GrCis keeps SceneBrep and WavefrontObj, so scripts written before they moved there still compile.</summary>
  public static readonly ImmutableArray<string> DefaultImports = ImmutableArray.Create(
    "System", "System.Diagnostics", "System.Collections.Generic", "OpenTK.Mathematics",
    "MathSupport", "Rendering", "Utilities", "Scene3D");

  /// <summary>
  /// Imported for scripts unless a module declares a public type of the same simple name: the library's
  /// solutions of homework skeletons (<c>DistributedRayTracing</c> of 049), which a student's own module
  /// declares too, often in namespace <c>Rendering</c> as GrCis's skeleton does. The student's class wins.
  /// </summary>
  public const string YieldingImport = "Rendering.Distributed";

  const string ModuleImports = "global using OpenTK.Mathematics;\n";

  static readonly CSharpParseOptions scriptParseOptions =
    new(LanguageVersion.Latest, DocumentationMode.None, SourceCodeKind.Script);

  /// <summary>
  /// How module files are parsed: regular C# (not the script dialect) with <c>DEBUG</c> and <c>TRACE</c>
  /// defined, as the Debug build of a student's GrCis project defined them (<c>#if DEBUG</c> blocks and
  /// <c>Debug.Assert</c> calls are compiled, see <see cref="Assertions"/>). Doc comments are parsed (not checked), so a
  /// module's XML documentation is emitted for the editor's hover and completion.
  /// </summary>
  public static readonly CSharpParseOptions ModuleParseOptions =
    new CSharpParseOptions(LanguageVersion.Latest, DocumentationMode.Parse, SourceCodeKind.Regular).WithPreprocessorSymbols("DEBUG", "TRACE");

  // Roslyn keys its metadata cache by reference object: one reference per module, made when a script first needs it.
  static readonly ConditionalWeakTable<ScriptModule, MetadataReference> moduleReferences = new();

  static readonly EmitOptions emitOptions = new(debugInformationFormat: DebugInformationFormat.PortablePdb);

  static int serial;

  /// <summary>
  /// Warnings about code that is right for its GrCis year: CS9191, a <c>ref</c> argument (OpenTK 3's
  /// <c>Vector3d.Add(ref a, ref b, out c)</c>) for an <c>in</c> parameter (OpenTK 4's signature, which ours is).
  /// </summary>
  static readonly ImmutableDictionary<string, ReportDiagnostic> QuietWarnings =
    ImmutableDictionary<string, ReportDiagnostic>.Empty.Add("CS9191", ReportDiagnostic.Suppress);

  /// <summary>Compiles a scene script to an image (not loaded yet: see <see cref="ScriptLoader"/>).</summary>
  /// <param name="key">Its key in the host's memory cache (part of the assembly name).</param>
  public static ScriptImage CompileScript(string path, string source, string key, IReadOnlyList<ScriptModule> modules, bool optimize)
  {
    int nul = source.IndexOf('\0', StringComparison.Ordinal);
    if (nul >= 0)
      throw new ScriptCompilationException(path, new[] { new ScriptDiagnostic(path, 1, 1, "error", ScriptDiagnostic.BinaryScriptId,
        $"the file is not a C# scene script: it holds binary data (a NUL character at offset {nul})") });
    SyntaxTree tree = CSharpSyntaxTree.ParseText(SourceText.From(source, Encoding.UTF8), scriptParseOptions, path);
    // Nothing but whitespace and comments: say so instead of an empty list of errors.
    if (!tree.GetRoot().ChildNodes().Any())
      throw new ScriptCompilationException(path, new[] { new ScriptDiagnostic(path, 1, 1, "error", ScriptDiagnostic.EmptyScriptId,
        "the scene script is empty (only whitespace or comments); it must build the scene: set scene.Intersectable, scene.Camera, scene.Sources") });
    (tree, InstrumentedSource instrumented) = Instrument(tree, scriptParseOptions);
    // A module type that shadows a library type of the same name is the one the script means.
    InstrumentedSource aliased = ShadowedLibraryTypes.WithAliases(instrumented, modules);
    if (!ReferenceEquals(aliased, instrumented))
    {
      instrumented = aliased;
      tree = CSharpSyntaxTree.ParseText(instrumented.Instrumented, scriptParseOptions, path);
    }
    var options = new CSharpCompilationOptions(
      OutputKind.DynamicallyLinkedLibrary,
      usings: ScriptImports(modules),
      // Debug code keeps every frame (no JIT inlining), so a runtime error always maps to its script line.
      optimizationLevel: optimize ? OptimizationLevel.Release : OptimizationLevel.Debug,
      allowUnsafe: true,
      nullableContextOptions: NullableContextOptions.Disable,
      specificDiagnosticOptions: QuietWarnings,
      concurrentBuild: false);

    string assemblyName = $"GrCisScript{Interlocked.Increment(ref serial)}_{key[..12]}";
    CSharpCompilation compilation = CSharpCompilation.CreateScriptCompilation(
      assemblyName, tree, References(modules), options,
      previousScriptCompilation: null, returnType: typeof(object), globalsType: typeof(ScriptGlobals));

    var sources = new Dictionary<SyntaxTree, InstrumentedSource> { [tree] = instrumented };
    var removed = new List<MissingNamespaces.Removed>();
    compilation = DropMissingNamespaces(compilation, sources, scriptParseOptions, removed);
    var overrides = new List<OverrideAccess.Changed>();
    compilation = OverrideAccess.Normalize(compilation, sources, scriptParseOptions, overrides);
    compilation = DataFileCalls.Rewrite(compilation, sources, scriptParseOptions);
    compilation = RecursionGuards.GuardLambdas(compilation, sources, scriptParseOptions);
    instrumented = sources.Values.Single();
    (MemoryStream pe, MemoryStream pdb, List<ScriptDiagnostic> warnings) = Emit(compilation, path, sources, removed, overrides);

    IMethodSymbol entry = compilation.GetEntryPoint(CancellationToken.None)
      ?? throw new InvalidOperationException($"{path}: the script compilation has no entry point.");
    string typeName = entry.ContainingType.MetadataName;
    if (entry.ContainingNamespace is { IsGlobalNamespace: false } ns)
      typeName = ns.ToDisplayString() + "." + typeName;
    return new ScriptImage(assemblyName, pe.ToArray(), pdb.ToArray(), typeName, entry.MetadataName, warnings, instrumented.ToMap());
  }

  /// <summary>
  /// Compiles module folders to one image (not loaded yet: see <see cref="ScriptLoader"/>). Scene scripts kept among
  /// the files are left out; a folder with nothing else is an error (GRCIS001).
  /// </summary>
  /// <param name="directories">The module folders compiled together (one assembly, so they may use each other).</param>
  /// <param name="candidates">Every <c>*.cs</c> file of each folder (<see cref="ModuleFiles.Candidates"/>) with its text.</param>
  /// <param name="cacheKey">The module's key in the compiled-script cache; its assembly is named after it.</param>
  public static ModuleImage CompileModule(IReadOnlyList<string> directories, IReadOnlyList<ModuleFiles.Candidate> candidates,
                                          string cacheKey, IReadOnlyList<ScriptModule> earlier, bool optimize)
  {
    string directory = directories[0];
    // Scene scripts kept beside the classes are not module code.
    var files = new List<string>();
    var parsed = new List<SyntaxTree>();
    var scripts = new List<string>();
    foreach (string dir in directories)
    {
      int before = files.Count, scriptsBefore = scripts.Count;
      foreach (ModuleFiles.Candidate c in candidates)
      {
        if (c.Directory != dir || files.Contains(c.File) || scripts.Contains(c.File))
          continue; // another folder's file, or one of a folder inside another one given too
        SyntaxTree tree = ModuleFiles.Parse(c.File, c.Text);
        if (ModuleFiles.IsSceneScript(tree))
          scripts.Add(c.File);
        else
        {
          files.Add(c.File);
          parsed.Add(tree);
        }
      }
      if (files.Count == before)
        throw new ScriptCompilationException(dir, new[] { new ScriptDiagnostic(dir, 1, 1, "error", "GRCIS001",
          scripts.Count == scriptsBefore ? "the module folder holds no *.cs file"
                             : $"the module folder holds only scene scripts ({scripts.Count - scriptsBefore}), no classes; give a script as the scene, not as --module") });
    }
    var trees = new List<SyntaxTree>(files.Count);
    var instrumented = new Dictionary<SyntaxTree, InstrumentedSource>();
    for (int i = 0; i < files.Count; i++)
    {
      (SyntaxTree tree, InstrumentedSource source) = Instrument(parsed[i], ModuleParseOptions);
      trees.Add(tree);
      instrumented[tree] = source;
    }

    // Debug code as a student's Debug build (and as scripts): no inlining, so an error or a failed assertion names its line.
    var options = new CSharpCompilationOptions(
      OutputKind.DynamicallyLinkedLibrary,
      optimizationLevel: optimize ? OptimizationLevel.Release : OptimizationLevel.Debug,
      allowUnsafe: true,
      nullableContextOptions: NullableContextOptions.Disable,
      specificDiagnosticOptions: QuietWarnings,
      concurrentBuild: false);

    // GrCis was written against OpenTK 3, whose math types live in namespace OpenTK: students write
    // `using OpenTK;`. Here they live in OpenTK.Mathematics (OpenTK 4), imported for every module file
    // as scripts import it; a file's own types still win over imported ones.
    // Types an earlier module compiled under a suffixed name (see ShadowedLibraryTypes) keep their plain name here too.
    string imports = ModuleImports + string.Concat(earlier.SelectMany(m => m.Renamed).Select(r => "global " + r.Alias + "\n"));
    trees.Add(CSharpSyntaxTree.ParseText(SourceText.From(imports, Encoding.UTF8), ModuleParseOptions, "GrCisModuleImports.g.cs"));

    string dirName = new string(Path.GetFileName(directory.TrimEnd(Path.DirectorySeparatorChar, Path.AltDirectorySeparatorChar))
      .Select(c => char.IsLetterOrDigit(c) ? c : '_').ToArray());
    string assemblyName = $"GrCisModule_{dirName}_{cacheKey[..16]}";
    CSharpCompilation compilation = CSharpCompilation.Create(assemblyName, trees, References(earlier), options);

    var removed = new List<MissingNamespaces.Removed>();
    compilation = DropMissingNamespaces(compilation, instrumented, ModuleParseOptions, removed);
    var overrides = new List<OverrideAccess.Changed>();
    compilation = OverrideAccess.Normalize(compilation, instrumented, ModuleParseOptions, overrides);
    compilation = DataFileCalls.Rewrite(compilation, instrumented, ModuleParseOptions);
    var shadowed = new List<ShadowedLibraryTypes.Renamed>();
    var partials = new List<ScriptDiagnostic>();
    compilation = ShadowedLibraryTypes.Rename(compilation, instrumented, ModuleParseOptions, shadowed, partials);
    // After the renames, so a lambda binds to the types the module means.
    compilation = RecursionGuards.GuardLambdas(compilation, instrumented, ModuleParseOptions);
    var xml = new MemoryStream();
    (MemoryStream pe, MemoryStream pdb, List<ScriptDiagnostic> warnings) = Emit(compilation, directory, instrumented, removed, overrides, partials, xml);
    warnings.AddRange(ShadowedLibraryTypes.Report(shadowed));
    return new ModuleImage(assemblyName, pe.ToArray(), pdb.ToArray(), xml.ToArray(), files, scripts, warnings,
      instrumented.ToDictionary(kv => kv.Key.FilePath, kv => kv.Value.ToMap(), StringComparer.Ordinal), shadowed);
  }

  /// <summary>
  /// The user's tree with interruption points (see <see cref="InterruptionPoints"/>) and recursion guards of declared
  /// bodies (<see cref="RecursionGuards"/>) inserted, parsed again, and the way back to the original.
  /// </summary>
  static (SyntaxTree Tree, InstrumentedSource Source) Instrument(SyntaxTree parsed, CSharpParseOptions parseOptions)
  {
    InstrumentedSource source = InterruptionPoints.Instrument(parsed);
    SyntaxTree polled = CSharpSyntaxTree.ParseText(source.Instrumented, parseOptions, parsed.FilePath);
    source = RecursionGuards.Instrument(polled, source);
    return (CSharpSyntaxTree.ParseText(source.Instrumented, parseOptions, parsed.FilePath), source);
  }

  /// <summary>
  /// Blanks out the usings of namespaces that do not exist here (GrCis-era APIs, see
  /// <see cref="MissingNamespaces"/>) in every user tree; records them in <paramref name="removed"/>.
  /// </summary>
  static CSharpCompilation DropMissingNamespaces(CSharpCompilation compilation, Dictionary<SyntaxTree, InstrumentedSource> sources,
                                                 CSharpParseOptions parseOptions, List<MissingNamespaces.Removed> removed)
  {
    foreach ((SyntaxTree tree, InstrumentedSource source) in sources.ToArray())
    {
      List<MissingNamespaces.Missing> missing = MissingNamespaces.Find(compilation, tree);
      if (missing.Count == 0)
        continue;
      SourceText blanked = MissingNamespaces.Blank(tree.GetText(), missing);
      compilation = source.WithInstrumented(blanked).Replace(tree, compilation, sources, parseOptions);
      foreach (MissingNamespaces.Missing m in missing)
        removed.Add(new MissingNamespaces.Removed(tree.FilePath,
          source.Original.Lines.GetLinePosition(source.ToOriginal(m.Span.Start)), m.Namespace));
    }
    return compilation;
  }

  static (MemoryStream pe, MemoryStream pdb, List<ScriptDiagnostic> warnings) Emit(
    CSharpCompilation compilation, string path, IReadOnlyDictionary<SyntaxTree, InstrumentedSource> sources,
    IReadOnlyList<MissingNamespaces.Removed> removed, IReadOnlyList<OverrideAccess.Changed> overrides,
    IReadOnlyList<ScriptDiagnostic>? causes = null, MemoryStream? documentation = null)
  {
    var pe = new MemoryStream();
    var pdb = new MemoryStream();
    EmitResult result = compilation.Emit(pe, pdb, xmlDocumentationStream: documentation, options: emitOptions);
    List<ScriptDiagnostic> diagnostics = DiagnosticFormatter.Convert(result.Diagnostics, path, sources);
    if (!result.Success)
    {
      // First what is gone, then the errors it causes.
      diagnostics.InsertRange(0, MissingNamespaces.Report(removed, compiled: false));
      // What the compiler's own errors follow from comes first.
      if (causes != null)
        diagnostics.InsertRange(0, causes);
      diagnostics.AddRange(OverrideAccess.Report(overrides));
      throw new ScriptCompilationException(path, diagnostics);
    }
    diagnostics.AddRange(MissingNamespaces.Report(removed, compiled: true));
    diagnostics.AddRange(OverrideAccess.Report(overrides));
    pe.Position = 0;
    pdb.Position = 0;
    return (pe, pdb, diagnostics);
  }

  /// <summary><see cref="DefaultImports"/>, and <see cref="YieldingImport"/> unless a module declares a type it holds.</summary>
  internal static ImmutableArray<string> ScriptImports(IReadOnlyList<ScriptModule> modules)
  {
    foreach (ScriptModule m in modules)
      foreach (Type t in m.Assembly.GetExportedTypes())
        if (YieldingNames.Contains(t.Name))
          return DefaultImports;
    return ImportsWithYielding;
  }

  static readonly ImmutableArray<string> ImportsWithYielding = DefaultImports.Add(YieldingImport);

  // The simple names of the library's types in YieldingImport, read once.
  static readonly HashSet<string> YieldingNames = new(typeof(Rendering.RayTracing).Assembly.GetExportedTypes()
    .Where(t => t.Namespace == YieldingImport).Select(t => t.Name), StringComparer.Ordinal);

  internal static IEnumerable<MetadataReference> References(IReadOnlyList<ScriptModule> modules) =>
    modules.Count == 0 ? FrameworkReferences.All : FrameworkReferences.All.Concat(modules.Select(Reference));

  static MetadataReference Reference(ScriptModule module) =>
    moduleReferences.GetValue(module, static m => MetadataReference.CreateFromImage(m.Image));
}
