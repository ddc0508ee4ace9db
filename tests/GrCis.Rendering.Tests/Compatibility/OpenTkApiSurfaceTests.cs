using System;
using System.Collections.Generic;
using System.Linq;
using System.Reflection;
using OpenTK.Mathematics;

namespace GrCis.Rendering.Tests.Compatibility;

/// <summary>
/// OpenTK 3.3.3's public API of the math types GrCis code uses, as data (<c>Data/opentk3-api.tsv</c>: type,
/// kind, member with its parameter types). Each member must exist in <c>OpenTK.Mathematics</c> here and accept
/// OpenTK's arguments, or be covered by a line of <c>Data/opentk3-api-exceptions.tsv</c> with its reason. A
/// <c>pending</c> line whose member exists fails, so the list of gaps only shrinks.
/// </summary>
public class OpenTkApiSurfaceTests
{
  const string Namespace = "OpenTK.Mathematics";
  static readonly Assembly assembly = typeof(Vector3d).Assembly;

  sealed record Member(string Type, string Kind, string Signature)
  {
    public override string ToString() => $"{Type} {Kind} {Signature}";
  }

  sealed record Reason(string Scope, string Why)
  {
    public bool Covers(Member m)
    {
      int colon = Scope.IndexOf(':');
      return colon < 0 ? Scope == m.Type : Scope[..colon] == m.Type && ApiLists.MemberMatches(Scope[(colon + 1)..], m.Signature);
    }
  }

  static List<Member> Members() => ApiLists.Read("opentk3-api.tsv").Select(f => new Member(f[0], f[1], f[2])).ToList();

  static List<Reason> Reasons() => ApiLists.Read("opentk3-api-exceptions.tsv").Select(f => new Reason(f[0], f[1])).ToList();

  static readonly Dictionary<string, Type> keywords = new()
  {
    ["double"] = typeof(double), ["float"] = typeof(float), ["int"] = typeof(int), ["long"] = typeof(long),
    ["bool"] = typeof(bool), ["string"] = typeof(string), ["object"] = typeof(object), ["byte"] = typeof(byte),
  };

  /// <summary>An OpenTK parameter type here: a keyword, an array of one, or a type of our OpenTK.Mathematics (null: not here).</summary>
  static Type? Resolve(string name)
  {
    if (name.EndsWith("[]"))
      return Resolve(name[..^2])?.MakeArrayType();
    return keywords.TryGetValue(name, out Type? k) ? k : assembly.GetType($"{Namespace}.{name}");
  }

  // C#'s implicit numeric conversions among the types OpenTK's signatures use.
  static readonly Dictionary<Type, Type[]> widening = new()
  {
    [typeof(int)] = new[] { typeof(long), typeof(float), typeof(double) },
    [typeof(long)] = new[] { typeof(float), typeof(double) },
    [typeof(float)] = new[] { typeof(double) },
  };

  /// <summary>Whether an argument of OpenTK's type <paramref name="from"/> can be passed by value where we take <paramref name="to"/>.</summary>
  static bool Accepts(Type to, Type from) =>
    to == from || (widening.TryGetValue(from, out Type[]? wider) && wider.Contains(to))
    || to.GetMethods(BindingFlags.Public | BindingFlags.Static).Any(m => m.Name == "op_Implicit" && m.ReturnType == to && m.GetParameters()[0].ParameterType == from);

  static bool ParametersAccept(ParameterInfo[] actual, string[] expected)
  {
    if (actual.Length < expected.Length || !actual.Skip(expected.Length).All(p => p.IsOptional))
      return false;
    for (int i = 0; i < expected.Length; i++)
    {
      string[] words = expected[i].Split(' ');
      bool byRef = words[0] is "ref" or "out";
      // OpenTK 3's `ref` inputs are OpenTK 4's `in`: C# binds a `ref` argument to an `in` parameter (a warning, not an error).
      bool sameMode = words[0] == "out" ? actual[i].IsOut : !actual[i].IsOut;
      Type? want = Resolve(words[^1]);
      Type got = actual[i].ParameterType;
      if (want == null)
        return false;
      if (byRef ? !(got.IsByRef && sameMode && got.GetElementType() == want) : !Accepts(got.IsByRef ? got.GetElementType()! : got, want) || (got.IsByRef && !actual[i].IsIn))
        return false;
    }
    return true;
  }

  static string OperatorName(string symbol, int arity) => (symbol, arity) switch
  {
    ("-", 1) => "op_UnaryNegation", ("+", 1) => "op_UnaryPlus",
    ("+", _) => "op_Addition", ("-", _) => "op_Subtraction", ("*", _) => "op_Multiply", ("/", _) => "op_Division",
    ("==", _) => "op_Equality", ("!=", _) => "op_Inequality",
    _ => "op_" + symbol,
  };

  /// <summary>Whether <paramref name="m"/> exists here: same name, static or not as in OpenTK, and OpenTK's arguments fit.</summary>
  static bool Exists(Member m)
  {
    Type? t = assembly.GetType($"{Namespace}.{m.Type}");
    if (t == null)
      return false;
    bool isStatic = m.Kind.StartsWith("static ", StringComparison.Ordinal);
    BindingFlags flags = BindingFlags.Public | (isStatic ? BindingFlags.Static : BindingFlags.Instance);
    string kind = isStatic ? m.Kind["static ".Length..] : m.Kind;
    int open = m.Signature.IndexOf('(');
    string[] parameters = open < 0 ? Array.Empty<string>() : ApiLists.SplitParameters(m.Signature[(open + 1)..^1]);

    switch (kind)
    {
      case "field":
      case "const":
      case "property":
        // A field may stand for a property and the other way round: reading and assigning compile the same.
        return t.GetField(m.Signature, flags) != null || t.GetProperty(m.Signature, flags) != null;
      case "indexer":
        string[] indices = ApiLists.SplitParameters(m.Signature["this[".Length..^1]);
        return t.GetProperties(flags).Any(p => p.GetIndexParameters() is { Length: > 0 } ip && ParametersAccept(ip, indices));
      case "ctor":
        return t.GetConstructors().Any(c => ParametersAccept(c.GetParameters(), parameters));
      case "conversion":
        // An implicit conversion also serves where OpenTK's is explicit.
        bool explicitOk = m.Signature.StartsWith("explicit ", StringComparison.Ordinal);
        string target = m.Signature[(m.Signature.IndexOf(' ') + 1)..open];
        Type? to = Resolve(target), from = Resolve(parameters[0]);
        return to != null && from != null && new[] { to, from }.SelectMany(x => x.GetMethods(BindingFlags.Public | BindingFlags.Static))
          .Any(c => (c.Name == "op_Implicit" || (explicitOk && c.Name == "op_Explicit")) && c.ReturnType == to && c.GetParameters()[0].ParameterType == from);
      case "operator":
        string op = OperatorName(m.Signature[..open], parameters.Length);
        return t.GetMethods(BindingFlags.Public | BindingFlags.Static).Any(x => x.Name == op && ParametersAccept(x.GetParameters(), parameters));
      default:
        string name = m.Signature[..open];
        return t.GetMethods(flags).Any(x => x.Name == name && ParametersAccept(x.GetParameters(), parameters));
    }
  }

  [Fact]
  public void Every_listed_OpenTK_3_member_exists_or_has_a_reason()
  {
    List<Member> members = Members();
    List<Reason> reasons = Reasons();
    Assert.True(members.Count > 1000, "the OpenTK 3 list looks truncated");

    (List<string> missing, List<string> stale) = ApiLists.Gaps(members, Exists,
      m => reasons.FirstOrDefault(r => r.Covers(m)) is { } r ? (r.Scope, r.Why) : null);
    Assert.True(missing.Count == 0, $"{missing.Count} OpenTK 3 members are missing:\n" + string.Join("\n", missing));
    Assert.True(stale.Count == 0, "pending lines that are no longer gaps:\n" + string.Join("\n", stale));
  }

  [Fact]
  public void Every_reason_covers_a_listed_member()
  {
    List<Member> members = Members();
    string[] unused = Reasons().Where(r => !members.Any(r.Covers)).Select(r => r.Scope).ToArray();
    Assert.True(unused.Length == 0, "exception lines that match no OpenTK 3 member: " + string.Join(", ", unused));
  }

  [Theory]
  [InlineData("Vector3d", "static method", "Transform(Vector3d, Matrix4d)", true)]
  [InlineData("Vector3d", "static method", "Transform(ref Vector3d, ref Matrix4d, out Vector3d)", true)]
  [InlineData("Vector3d", "static method", "Transform(Vector3d, Vector3d)", false)]
  [InlineData("Vector3d", "static method", "Dot(Vector3d, Vector3d, Vector3d)", false)]
  [InlineData("Vector3d", "method", "Dot(Vector3d, Vector3d)", false)]
  [InlineData("Vector3d", "field", "X", true)]
  [InlineData("Vector3d", "operator", "-(Vector3d)", true)]
  [InlineData("Vector3d", "conversion", "explicit Vector3(Vector3d)", true)]
  [InlineData("Vector3d", "conversion", "implicit Vector3(Vector3d)", false)]
  [InlineData("Matrix4d", "operator", "*(Matrix4d, float)", true)]
  [InlineData("Vector3d", "indexer", "this[int]", true)]
  [InlineData("Vector3d", "ctor", "Vector3d(Vector3h)", false)]
  public void The_checker_tells_present_from_absent(string type, string kind, string signature, bool expected) =>
    Assert.Equal(expected, Exists(new Member(type, kind, signature)));
}
