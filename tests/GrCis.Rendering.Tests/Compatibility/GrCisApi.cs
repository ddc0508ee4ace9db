using System;
using System.Collections.Generic;
using System.Linq;
using System.Reflection;
using Rendering;

namespace GrCis.Rendering.Tests.Compatibility;

/// <summary>
/// One public type or member of GrCis's <c>common/</c> library as the API lists write it (file, kind, type,
/// member with parameter types), the reason lines that excuse a missing one, and the reflection check
/// shared by the API-surface tests.
/// </summary>
static class GrCisApi
{
  // GrCis's common/ lives in two houses: the core (GrCis.Rendering) and GrCis.Compatibility.
  static readonly Assembly[] assemblies = { typeof(RayTracing).Assembly, typeof(global::Utilities.Util).Assembly };

  public sealed record Entry(string File, string Kind, string Type, string Member)
  {
    public override string ToString() => $"{File}: {Type} {Kind} {Member}";
  }

  /// <summary>A reason line: scope = File.cs[:Type[:member]] (see <see cref="ApiLists.MemberMatches"/>).</summary>
  public sealed record Exception(string Scope, string Reason)
  {
    public bool Covers(Entry e)
    {
      string[] parts = Scope.Split(':');
      return parts[0] == e.File && (parts.Length < 2 || parts[1] == e.Type) && (parts.Length < 3 || ApiLists.MemberMatches(parts[2], e.Member));
    }
  }

  public static List<Exception> Exceptions(string fileName) => ApiLists.Read(fileName).Select(f => new Exception(f[0], f[1])).ToList();

  static Type? FindType(string name)
  {
    foreach (Assembly a in assemblies)
      if (a.GetType(name) is Type t)
        return t;
    return null;
  }

  static readonly Dictionary<string, string> operatorNames = new()
  {
    ["+"] = "op_Addition", ["-"] = "op_Subtraction", ["*"] = "op_Multiply", ["/"] = "op_Division",
    ["=="] = "op_Equality", ["!="] = "op_Inequality", ["<"] = "op_LessThan", [">"] = "op_GreaterThan",
    ["<="] = "op_LessThanOrEqual", [">="] = "op_GreaterThanOrEqual", ["%"] = "op_Modulus",
    ["++"] = "op_Increment", ["--"] = "op_Decrement", ["|"] = "op_BitwiseOr", ["&"] = "op_BitwiseAnd", ["^"] = "op_ExclusiveOr",
  };

  /// <summary>Whether <paramref name="e"/> exists: same name, same number of parameters, same ref/out places, reachable by subclasses.</summary>
  public static bool Exists(Entry e)
  {
    Type? t = FindType(e.Type);
    if (t == null)
      return false;
    if (e.Kind == "type")
      return true;
    const BindingFlags all = BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Instance | BindingFlags.Static | BindingFlags.FlattenHierarchy;
    string member = e.Member.StartsWith("protected ", StringComparison.Ordinal) ? e.Member["protected ".Length..] : e.Member;
    static bool Reachable(MethodBase m) => m.IsPublic || m.IsFamily || m.IsFamilyOrAssembly;

    switch (e.Kind)
    {
      case "field":
      case "property":
      case "event":
        if (t.IsEnum)
          return Enum.GetNames(t).Contains(member);
        FieldInfo? f = t.GetField(member, all);
        if (f != null && (f.IsPublic || f.IsFamily || f.IsFamilyOrAssembly))
          return true;
        PropertyInfo? p = member == "Item" ? t.GetProperties(all).FirstOrDefault(x => x.GetIndexParameters().Length > 0) : t.GetProperty(member, all);
        if (p != null && p.GetAccessors(nonPublic: true).Any(Reachable))
          return true;
        return t.GetEvent(member, all) != null || ExtensionProperty(t, member);

      case "conversion":
        // "implicit int(MutableInt)": a conversion operator of that direction taking one value (declared here or on a base class).
        string method = member.StartsWith("implicit ", StringComparison.Ordinal) ? "op_Implicit" : "op_Explicit";
        return t.GetMethods(all).Any(m => m.Name == method && m.IsPublic && m.GetParameters().Length == 1);

      default:
        int open = member.IndexOf('(');
        string name = member[..open];
        string[] parameters = ApiLists.SplitParameters(member[(open + 1)..^1]);
        IEnumerable<MethodBase> candidates = e.Kind == "ctor"
          ? t.GetConstructors(all)
          : t.GetMethods(all).Where(m => m.Name == (e.Kind == "operator" ? operatorNames.GetValueOrDefault(name, name) : name));
        return candidates.Any(m => Reachable(m) && Matches(m.GetParameters(), parameters));
    }
  }

  /// <summary>
  /// A C# extension property of <paramref name="t"/> named <paramref name="member"/> (static or instance), declared in a static
  /// class of its namespace and assembly: code that imports the type's namespace reads it as the type's own.
  /// </summary>
  static bool ExtensionProperty(Type t, string member) =>
    t.Assembly.GetExportedTypes().Any(c => c.IsAbstract && c.IsSealed && c.Namespace == t.Namespace && Extends(c, t) &&
      c.GetMethods(BindingFlags.Public | BindingFlags.Static | BindingFlags.DeclaredOnly).Any(m =>
        m.Name == "get_" + member && m.GetParameters() is var ps && (ps.Length == 0 || (ps.Length == 1 && ps[0].ParameterType == t))));

  /// <summary>Whether static class <paramref name="c"/> has an <c>extension(T)</c> block for <paramref name="t"/> (the compiler's marker method).</summary>
  static bool Extends(Type c, Type t)
  {
    const BindingFlags any = BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Static | BindingFlags.Instance | BindingFlags.DeclaredOnly;
    return c.GetNestedTypes(any).SelectMany(g => g.GetNestedTypes(any)).SelectMany(m => m.GetMethods(any))
      .Any(m => m.Name == "<Extension>$" && m.GetParameters() is [var p] && p.ParameterType == t);
  }

  /// <summary>Same count, and a by-reference parameter where GrCis has <c>ref</c> or <c>out</c> (an <c>in</c> or a value parameter both take a value).</summary>
  static bool Matches(ParameterInfo[] actual, string[] expected)
  {
    if (actual.Length != expected.Length)
    {
      // Optional trailing parameters may be added here.
      if (actual.Length < expected.Length || !actual.Skip(expected.Length).All(p => p.IsOptional))
        return false;
    }
    for (int i = 0; i < expected.Length; i++)
    {
      bool byRef = expected[i].StartsWith("ref ", StringComparison.Ordinal) || expected[i].StartsWith("out ", StringComparison.Ordinal);
      if (byRef != (actual[i].ParameterType.IsByRef && !actual[i].IsIn))
        return false;
    }
    return true;
  }
}
