using System;
using System.Collections.Generic;
using System.Linq;
using System.Reflection;
using Rendering;

namespace GrCis.Rendering.Tests.Compatibility;

/// <summary>
/// GrCis's public library (the course repository's <c>common/</c> folder), written down as data: one
/// line per public type and per public or protected member (<c>Data/grcis-common-api.tsv</c>: file,
/// kind, type, member). Each must exist here with GrCis's name, or be covered by a line of
/// <c>Data/grcis-api-exceptions.tsv</c> that gives the reason. Exceptions marked <c>pending</c> are gaps
/// still to fill: such an entry must still be missing, so the list shrinks as the port grows.
/// </summary>
public class ApiSurfaceTests
{
  static readonly Assembly[] assemblies = { typeof(RayTracing).Assembly };

  sealed record Entry(string File, string Kind, string Type, string Member)
  {
    public override string ToString() => $"{File}: {Type} {Kind} {Member}";
  }

  sealed record Exception(string Scope, string Reason)
  {
    public bool Covers(Entry e)
    {
      string[] parts = Scope.Split(':');
      return parts[0] == e.File && (parts.Length < 2 || parts[1] == e.Type) && (parts.Length < 3 || ApiLists.MemberMatches(parts[2], e.Member));
    }
  }

  static List<Entry> Entries() => ApiLists.Read("grcis-common-api.tsv").Select(f => new Entry(f[0], f[1], f[2], f[3])).ToList();

  static List<Exception> Exceptions() => ApiLists.Read("grcis-api-exceptions.tsv").Select(f => new Exception(f[0], f[1])).ToList();

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
  static bool Exists(Entry e)
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
        return t.GetEvent(member, all) != null;

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

  [Fact]
  public void Every_public_member_of_GrCis_common_library_exists_or_has_a_documented_reason()
  {
    List<Entry> entries = Entries();
    List<Exception> exceptions = Exceptions();
    Assert.True(entries.Count > 1000, "the API list looks truncated");

    (List<string> missing, List<string> stalePending) = ApiLists.Gaps(entries, Exists,
      e => exceptions.FirstOrDefault(x => x.Covers(e)) is { } x ? (x.Scope, x.Reason) : null);
    Assert.True(missing.Count == 0, $"{missing.Count} GrCis members are missing:\n" + string.Join("\n", missing));
    Assert.True(stalePending.Count == 0, "pending exceptions that are no longer gaps:\n" + string.Join("\n", stalePending));
  }

  [Fact]
  public void Every_exception_covers_something()
  {
    List<Entry> entries = Entries();
    string[] unused = Exceptions().Where(x => !entries.Any(x.Covers)).Select(x => x.Scope).ToArray();
    Assert.True(unused.Length == 0, "exceptions that match no GrCis member: " + string.Join(", ", unused));
  }
}
