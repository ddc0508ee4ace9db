using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Reflection.PortableExecutable;
using GrCis.Scripting;
using Microsoft.CodeAnalysis;
using Microsoft.CodeAnalysis.CSharp;
using Microsoft.CodeAnalysis.CSharp.Syntax;

namespace GrCis.Cli.Tests;

/// <summary>
/// The scene template's project compiles a script as top-level statements with Shim/ScriptGlobals.cs: the shim
/// declares what the script host gives (every global with its type, every import), and every script of the
/// repository, and the template's own, compiles that way without an error.
/// </summary>
public class IdeShimTests
{
  static readonly string ShimPath = Path.Combine(RepoPaths.Root, "templates", "grcis-scene", "Shim", "ScriptGlobals.cs");

  static readonly Lazy<IReadOnlyList<MetadataReference>> references = new(() =>
  {
    // What the template's project compiles against: the shared framework and the library packages (GrCis.Rendering
    // brings GrCis.Mathematics).
    string framework = Path.GetDirectoryName(typeof(object).Assembly.Location)!;
    var list = Directory.GetFiles(framework, "*.dll").Where(IsManaged).Select(f => (MetadataReference)MetadataReference.CreateFromFile(f)).ToList();
    list.Add(MetadataReference.CreateFromFile(typeof(OpenTK.Mathematics.Vector3d).Assembly.Location));
    list.Add(MetadataReference.CreateFromFile(typeof(Rendering.IRayScene).Assembly.Location));
    list.Add(MetadataReference.CreateFromFile(typeof(Utilities.Util).Assembly.Location));
    return list;
  });

  [Fact]
  public void Shim_declares_every_script_global_with_its_type()
  {
    var expected = typeof(ScriptGlobals).GetMembers(BindingFlags.Public | BindingFlags.Instance)
      .Where(m => m is FieldInfo or PropertyInfo)
      .Select(m => (m.Name, CSharpName(m is FieldInfo f ? f.FieldType : ((PropertyInfo)m).PropertyType)))
      .Order().ToArray();

    INamedTypeSymbol shim = Compile(ShimTree()).GetTypeByMetadataName("GrCisScript.ScriptGlobals")!;
    var declared = shim.GetMembers().Where(m => m.IsStatic && m.DeclaredAccessibility == Accessibility.Public && m is IFieldSymbol or IPropertySymbol)
      .Select(m => (m.Name, (m is IFieldSymbol f ? f.Type : ((IPropertySymbol)m).Type).ToDisplayString(SymbolDisplayFormat.FullyQualifiedFormat).Replace("global::", "", StringComparison.Ordinal)))
      .Order().ToArray();

    Assert.Equal(expected, declared);
  }

  [Fact]
  public void Shim_imports_the_namespaces_a_script_sees()
  {
    var imports = ((CompilationUnitSyntax)ShimTree().GetRoot()).Usings
      .Where(u => u.GlobalKeyword.IsKind(SyntaxKind.GlobalKeyword) && u.StaticKeyword.IsKind(SyntaxKind.None))
      .Select(u => u.Name!.ToString()).ToArray();

    // The host's list, and the homework solutions' namespace it adds unless a module declares such a type.
    Assert.Equal(ScriptHost.DefaultImports.Append("Rendering.Distributed").Order(StringComparer.Ordinal), imports.Order(StringComparer.Ordinal));
  }

  public static IEnumerable<object[]> Scripts() =>
    Directory.GetFiles(RepoPaths.Scripts, "*.cs").Select(f => new object[] { Path.GetFileName(f) })
      .Append(new object[] { Path.Combine("..", "templates", "grcis-scene", "Scene.cs") });

  [Theory]
  [MemberData(nameof(Scripts))]
  public void Script_compiles_as_the_template_project_compiles_it(string file)
  {
    string path = Path.Combine(RepoPaths.Scripts, file);
    SyntaxTree script = CSharpSyntaxTree.ParseText(File.ReadAllText(path), new CSharpParseOptions(LanguageVersion.Latest), path);

    Diagnostic[] errors = Compile(ShimTree(), script).GetDiagnostics().Where(d => d.Severity == DiagnosticSeverity.Error).ToArray();

    Assert.True(errors.Length == 0, string.Join("\n", errors.Select(e => e.ToString())));
  }

  static SyntaxTree ShimTree() =>
    CSharpSyntaxTree.ParseText(File.ReadAllText(ShimPath), new CSharpParseOptions(LanguageVersion.Latest), ShimPath);

  /// <summary>As the template's project builds: an executable (top-level statements), no nullable analysis, unsafe allowed, CS9191 quiet.</summary>
  static CSharpCompilation Compile(params SyntaxTree[] trees) =>
    CSharpCompilation.Create("IdeShimCheck", trees, references.Value,
      new CSharpCompilationOptions(OutputKind.ConsoleApplication, nullableContextOptions: NullableContextOptions.Disable, allowUnsafe: true,
        specificDiagnosticOptions: new Dictionary<string, ReportDiagnostic> { ["CS9191"] = ReportDiagnostic.Suppress }));

  /// <summary>The C# spelling Roslyn's fully qualified format gives (string, System.Collections.Generic.Dictionary&lt;string, object&gt;).</summary>
  static string CSharpName(Type t)
  {
    if (t == typeof(string)) return "string";
    if (t == typeof(object)) return "object";
    if (!t.IsGenericType) return t.FullName!;
    string name = t.GetGenericTypeDefinition().FullName!;
    return name[..name.IndexOf('`', StringComparison.Ordinal)] + "<" + string.Join(", ", t.GetGenericArguments().Select(CSharpName)) + ">";
  }

  static bool IsManaged(string file)
  {
    using var stream = File.OpenRead(file);
    using var pe = new PEReader(stream);
    return pe.HasMetadata;
  }
}
