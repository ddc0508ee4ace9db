using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Reflection.Metadata;
using System.Reflection.PortableExecutable;

namespace GrCis.Cli.Tests;

/// <summary>
/// GrCis.Compatibility (GrCis's classic helpers for students' code) sits on top of the core: the renderer
/// and its hosts never use it, and the script host only hands it to scripts and modules.
/// </summary>
public class CompatibilityLayerTests
{
  const string CompatibilityName = "GrCis.Compatibility";

  static readonly Assembly compatibility = typeof(Utilities.Util).Assembly;

  static readonly Assembly scripting = typeof(GrCis.Scripting.ScriptHost).Assembly;

  /// <summary>The core: the math, the renderer and every host except the script host (checked on its own below).</summary>
  static readonly Assembly[] core =
  {
    typeof(OpenTK.Mathematics.Vector3d).Assembly,
    typeof(Rendering.RayTracing).Assembly,
    typeof(GrCis.Hosting.RenderPlan).Assembly,
    typeof(GrCis.Interactive.DemoController).Assembly,
    typeof(GrCis.Studio.StudioServer).Assembly,
    typeof(ExitCodes).Assembly,
  };

  [Fact]
  public void Compatibility_assembly_builds_on_the_renderer()
  {
    Assert.Equal(CompatibilityName, compatibility.GetName().Name);
    Assert.Contains(compatibility.GetReferencedAssemblies(), a => a.Name == "GrCis.Rendering");
  }

  [Fact]
  public void The_math_assembly_stands_on_the_framework_alone_and_the_renderer_on_it()
  {
    Assembly math = typeof(OpenTK.Mathematics.Vector3d).Assembly;
    Assert.Equal("GrCis.Mathematics", math.GetName().Name);
    Assert.DoesNotContain(math.GetReferencedAssemblies(), r => r.Name!.StartsWith("GrCis", StringComparison.Ordinal));
    Assert.Contains(typeof(Rendering.RayTracing).Assembly.GetReferencedAssemblies(), r => r.Name == "GrCis.Mathematics");
    // Every type of OpenTK.Mathematics lives in GrCis.Mathematics; the renderer keeps GrCis's own math (MathSupport).
    Assert.DoesNotContain(typeof(Rendering.RayTracing).Assembly.GetExportedTypes(), t => t.Namespace == "OpenTK.Mathematics");
    Assert.Same(typeof(Rendering.RayTracing).Assembly, typeof(MathSupport.Geometry).Assembly);
  }

  [Fact]
  public void Renderer_and_hosts_reference_no_compatibility_assembly()
  {
    foreach (Assembly a in core)
      Assert.DoesNotContain(a.GetReferencedAssemblies(), r => r.Name == CompatibilityName);
  }

  [Fact]
  public void Script_host_names_one_compatibility_type_only_to_find_the_assembly_for_scripts()
  {
    // typeof(Util) in FrameworkReferences is a type reference with no member reference; a call such as
    // Util.TryParse(...) would add a member reference whose parent is Util.
    using var pe = new PEReader(File.OpenRead(scripting.Location));
    MetadataReader md = pe.GetMetadataReader();
    var compatTypes = new HashSet<TypeReferenceHandle>();
    foreach (TypeReferenceHandle h in md.TypeReferences)
    {
      TypeReference t = md.GetTypeReference(h);
      if (t.ResolutionScope.Kind == HandleKind.AssemblyReference &&
          md.GetString(md.GetAssemblyReference((AssemblyReferenceHandle)t.ResolutionScope).Name) == CompatibilityName)
        compatTypes.Add(h);
    }

    Assert.Equal(new[] { "Utilities.Util" }, compatTypes.Select(h => FullName(md, md.GetTypeReference(h))));
    foreach (MemberReferenceHandle h in md.MemberReferences)
    {
      EntityHandle parent = md.GetMemberReference(h).Parent;
      Assert.False(parent.Kind == HandleKind.TypeReference && compatTypes.Contains((TypeReferenceHandle)parent),
        $"GrCis.Scripting calls {md.GetString(md.GetMemberReference(h).Name)} of a compatibility type");
    }
  }

  [Fact]
  public void No_public_type_of_the_core_mentions_a_compatibility_type()
  {
    var offending = new List<string>();
    foreach (Assembly a in core.Append(scripting))
      foreach (Type t in a.GetExportedTypes())
        foreach ((string where, Type used) in Signature(t))
          if (Mentions(used))
            offending.Add($"{a.GetName().Name}: {t.FullName}.{where} uses {used}");
    Assert.Empty(offending);
  }

  [Fact]
  public void Moved_types_keep_their_GrCis_namespaces()
  {
    Assert.Equal("Utilities", typeof(Utilities.Util).Namespace);
    Assert.Equal("MathSupport", typeof(MathSupport.Arith).Namespace);
    Assert.Equal("MathSupport", typeof(MathSupport.Polynomial).Namespace);
    Assert.Equal("Rendering", typeof(Rendering.AdaptiveSupersampling).Namespace);
    Assert.Equal("Rendering", typeof(Rendering.PointCloud).Namespace);
    Assert.All(new[] { typeof(MathSupport.Arith), typeof(MathSupport.HeapMin<int>), typeof(Rendering.PointCloud), typeof(Utilities.Histogram<int>) },
      t => Assert.Same(compatibility, t.Assembly));
  }

  static bool Mentions(Type t)
  {
    if (t.HasElementType)
      return Mentions(t.GetElementType()!);
    if (t.IsGenericParameter)
      return false;
    if (t.Assembly == compatibility)
      return true;
    return t.IsGenericType && t.GetGenericArguments().Any(Mentions);
  }

  /// <summary>Every type the public or protected surface of <paramref name="t"/> names, with where.</summary>
  static IEnumerable<(string, Type)> Signature(Type t)
  {
    const BindingFlags all = BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Instance | BindingFlags.Static | BindingFlags.DeclaredOnly;
    if (t.BaseType != null)
      yield return ("base", t.BaseType);
    foreach (Type i in t.GetInterfaces())
      yield return ("interface", i);
    foreach (FieldInfo f in t.GetFields(all).Where(f => f.IsPublic || f.IsFamily || f.IsFamilyOrAssembly))
      yield return (f.Name, f.FieldType);
    foreach (MethodBase m in t.GetMethods(all).Cast<MethodBase>().Concat(t.GetConstructors(all)).Where(m => m.IsPublic || m.IsFamily || m.IsFamilyOrAssembly))
    {
      if (m is MethodInfo mi)
        yield return (m.Name, mi.ReturnType);
      foreach (ParameterInfo p in m.GetParameters())
        yield return ($"{m.Name}({p.Name})", p.ParameterType);
    }
  }

  static string FullName(MetadataReader md, TypeReference t) =>
    $"{md.GetString(t.Namespace)}.{md.GetString(t.Name)}";
}
