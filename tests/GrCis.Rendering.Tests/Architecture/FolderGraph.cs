using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;

namespace GrCis.Rendering.Tests.Architecture;

/// <summary>One use of a type (or of a member of it) declared in another folder of the library.</summary>
/// <param name="From">The folder of the file that names it.</param>
/// <param name="To">The folder of the file that declares it.</param>
/// <param name="File">The naming file, relative to the library's folder.</param>
/// <param name="Line">Its line (1-based).</param>
/// <param name="Name">The type or member named.</param>
public sealed record FolderDependency(string From, string To, string File, int Line, string Name)
{
  public override string ToString() => $"{File}:{Line} names {Name} ({From} -> {To})";
}

/// <summary>
/// The folders of src/GrCis.Rendering and their dependencies, from the library's sources compiled with Roslyn:
/// folder A depends on folder B when a file in A names a type declared in B, or a member declared in B (a method,
/// an extension method, a property …). Every identifier is bound with the semantic model; doc comments do not count.
/// A folder is the first folder under the library's root (Lights/Model is Lights).
/// </summary>
public sealed class FolderGraph
{
  public IReadOnlyList<string> Folders { get; }
  public IReadOnlyList<FolderDependency> Dependencies { get; }
  public IReadOnlyList<Diagnostic> Errors { get; }

  FolderGraph(IReadOnlyList<string> folders, IReadOnlyList<FolderDependency> dependencies, IReadOnlyList<Diagnostic> errors)
  {
    Folders = folders;
    Dependencies = dependencies;
    Errors = errors;
  }

  /// <summary>The distinct folder edges (From -> To, From != To).</summary>
  public IReadOnlyDictionary<string, SortedSet<string>> Edges()
  {
    var edges = Folders.ToDictionary(f => f, _ => new SortedSet<string>(StringComparer.Ordinal));
    foreach (FolderDependency d in Dependencies)
      edges[d.From].Add(d.To);
    return edges;
  }

  /// <summary>Strongly connected components (Tarjan), largest first.</summary>
  public List<List<string>> Components()
  {
    var edges = Edges();
    var index = new Dictionary<string, int>();
    var low = new Dictionary<string, int>();
    var onStack = new HashSet<string>();
    var stack = new Stack<string>();
    var result = new List<List<string>>();
    int next = 0;

    void Visit(string v)
    {
      index[v] = low[v] = next++;
      stack.Push(v);
      onStack.Add(v);
      foreach (string w in edges[v])
      {
        if (!index.ContainsKey(w))
        {
          Visit(w);
          low[v] = Math.Min(low[v], low[w]);
        }
        else if (onStack.Contains(w))
          low[v] = Math.Min(low[v], index[w]);
      }
      if (low[v] == index[v])
      {
        var component = new List<string>();
        string w;
        do
        {
          w = stack.Pop();
          onStack.Remove(w);
          component.Add(w);
        } while (w != v);
        component.Sort(StringComparer.Ordinal);
        result.Add(component);
      }
    }

    foreach (string f in Folders)
      if (!index.ContainsKey(f))
        Visit(f);
    return result.OrderByDescending(c => c.Count).ThenBy(c => c[0], StringComparer.Ordinal).ToList();
  }

  /// <summary>
  /// Compiles every .cs file under <paramref name="libraryRoot"/> (bin and obj left out) against
  /// <paramref name="references"/> and collects the dependencies between its folders.
  /// </summary>
  public static FolderGraph Build(string libraryRoot, IEnumerable<MetadataReference> references)
  {
    string root = Path.GetFullPath(libraryRoot);
    var parse = new CSharpParseOptions(LanguageVersion.Preview);
    var files = Directory.GetFiles(root, "*.cs", SearchOption.AllDirectories)
      .Where(p => !IsBuildOutput(Path.GetRelativePath(root, p)))
      .OrderBy(p => p, StringComparer.Ordinal)
      .ToList();
    var trees = files.Select(p => CSharpSyntaxTree.ParseText(File.ReadAllText(p), parse, p)).ToList();
    var options = new CSharpCompilationOptions(OutputKind.DynamicallyLinkedLibrary,
      allowUnsafe: true, nullableContextOptions: NullableContextOptions.Enable);
    var compilation = CSharpCompilation.Create("GrCis.Rendering", trees, references, options);
    var errors = compilation.GetDiagnostics().Where(d => d.Severity == DiagnosticSeverity.Error).ToList();

    string FolderOf(string path)
    {
      string rel = Path.GetRelativePath(root, path);
      int slash = rel.IndexOfAny(new[] { '/', '\\' });
      return slash < 0 ? "" : rel[..slash];
    }

    var folders = files.Select(FolderOf).Distinct().OrderBy(f => f, StringComparer.Ordinal).ToList();
    var dependencies = new List<FolderDependency>();
    var seen = new HashSet<(string, string, string)>();
    foreach (SyntaxTree tree in trees)
    {
      string from = FolderOf(tree.FilePath);
      string file = Path.GetRelativePath(root, tree.FilePath).Replace('\\', '/');
      SemanticModel model = compilation.GetSemanticModel(tree);
      foreach (SimpleNameSyntax name in tree.GetRoot().DescendantNodes().OfType<SimpleNameSyntax>())
      {
        SymbolInfo info = model.GetSymbolInfo(name);
        ISymbol? symbol = info.Symbol ?? (info.CandidateSymbols.Length == 1 ? info.CandidateSymbols[0] : null);
        if (symbol == null)
          continue;
        foreach ((ISymbol target, string display) in Targets(symbol))
          foreach (Location location in target.Locations)
          {
            if (!location.IsInSource || location.SourceTree == null)
              continue;
            string to = FolderOf(location.SourceTree.FilePath);
            if (to == from || !seen.Add((file, to, display)))
              continue;
            int line = name.GetLocation().GetLineSpan().StartLinePosition.Line + 1;
            dependencies.Add(new FolderDependency(from, to, file, line, display));
          }
      }
    }
    return new FolderGraph(folders, dependencies, errors);
  }

  /// <summary>What a bound name depends on: a type (its original definition), or a member (its own declaration).</summary>
  static IEnumerable<(ISymbol, string)> Targets(ISymbol symbol)
  {
    switch (symbol)
    {
      case IAliasSymbol alias:
        foreach (var t in Targets(alias.Target))
          yield return t;
        break;
      case INamedTypeSymbol type:
        yield return (type.OriginalDefinition, type.OriginalDefinition.ToDisplayString());
        break;
      case IMethodSymbol method:
      {
        IMethodSymbol m = method.ReducedFrom ?? method;
        m = m.OriginalDefinition;
        if (m.MethodKind == MethodKind.Constructor)
          yield return (m.ContainingType, m.ContainingType.ToDisplayString());
        else
          yield return (m, m.ContainingType.ToDisplayString() + "." + m.Name);
        break;
      }
      case IPropertySymbol or IFieldSymbol or IEventSymbol:
        if (symbol.ContainingType != null)
          yield return (symbol.OriginalDefinition, symbol.ContainingType.OriginalDefinition.ToDisplayString() + "." + symbol.Name);
        break;
    }
  }

  static bool IsBuildOutput(string relative)
  {
    string first = relative.Split('/', '\\')[0];
    return first is "bin" or "obj";
  }

  /// <summary>
  /// The references the library builds against: the framework's reference assemblies (those of the running
  /// runtime, same names and types) and the given assemblies (GrCis.Mathematics, StbImageSharp).
  /// </summary>
  public static List<MetadataReference> References(params string[] assemblies)
  {
    string framework = Path.GetDirectoryName(typeof(object).Assembly.Location)!;
    var list = Directory.GetFiles(framework, "*.dll")
      .Where(p =>
      {
        string n = Path.GetFileName(p);
        return n.StartsWith("System.", StringComparison.Ordinal) || n == "netstandard.dll" || n == "mscorlib.dll";
      })
      .Where(IsManaged)
      .Select(p => (MetadataReference)MetadataReference.CreateFromFile(p))
      .ToList();
    list.AddRange(assemblies.Select(a => MetadataReference.CreateFromFile(a)));
    return list;
  }

  static bool IsManaged(string path)
  {
    try
    {
      System.Reflection.AssemblyName.GetAssemblyName(path);
      return true;
    }
    catch (BadImageFormatException)
    {
      return false;
    }
  }
}
