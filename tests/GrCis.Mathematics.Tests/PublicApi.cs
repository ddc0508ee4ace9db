using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using System.Reflection;
using System.Runtime.CompilerServices;

namespace GrCis.Mathematics.Tests;

/// <summary>
/// The public surface of a namespace as text, one line per type and per member: kind, modifiers, types, names,
/// parameter modifiers and default values. Two builds with the same lines offer the same API to source and binaries.
/// </summary>
static class PublicApi
{
  const BindingFlags Declared = BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Instance | BindingFlags.Static | BindingFlags.DeclaredOnly;

  /// <summary>Every line for the exported types of <paramref name="ns"/> in <paramref name="assembly"/>, sorted (ordinal).</summary>
  public static List<string> Describe(Assembly assembly, string ns)
  {
    var lines = new List<string>();
    foreach (Type t in assembly.GetExportedTypes().Where(t => t.Namespace == ns))
    {
      string owner = Name(t);
      lines.Add($"{owner}: {TypeLine(t)}");
      foreach (MemberInfo m in t.GetMembers(Declared).Where(Visible))
        if (MemberLine(m) is string line)
          lines.Add($"{owner}: {line}");
    }
    lines.Sort(StringComparer.Ordinal);
    return lines;
  }

  static bool Visible(MemberInfo m) => m switch
  {
    FieldInfo f => f.IsPublic || f.IsFamily || f.IsFamilyOrAssembly,
    MethodBase b => b.IsPublic || b.IsFamily || b.IsFamilyOrAssembly,
    PropertyInfo p => p.GetAccessors(true).Any(a => Visible(a)),
    EventInfo e => e.AddMethod is { } add && Visible(add),
    Type n => n.IsNestedPublic || n.IsNestedFamily || n.IsNestedFamORAssem,
    _ => false,
  };

  static string TypeLine(Type t)
  {
    string kind = t.IsEnum ? "enum" : t.IsValueType ? "struct" : t.IsInterface ? "interface"
      : t.IsAbstract && t.IsSealed ? "static class" : t.IsAbstract ? "abstract class" : t.IsSealed ? "sealed class" : "class";
    if (t.IsValueType && t.IsDefined(typeof(IsReadOnlyAttribute), false))
      kind = "readonly " + kind;
    var bases = new List<string>();
    if (t.IsEnum)
      bases.Add(Name(Enum.GetUnderlyingType(t)));
    else if (t.BaseType is { } b && b != typeof(object) && b != typeof(ValueType))
      bases.Add(Name(b));
    bases.AddRange(t.GetInterfaces().Select(Name).Order(StringComparer.Ordinal));
    string layout = t.IsValueType && !t.IsEnum ? $" [{t.StructLayoutAttribute?.Value}{(t.IsSerializable ? ", Serializable" : "")}]" : "";
    return $"{kind} {Name(t)}{Generics(t)}{(bases.Count > 0 ? " : " + string.Join(", ", bases) : "")}{layout}";
  }

  static string? MemberLine(MemberInfo m)
  {
    switch (m)
    {
      case FieldInfo f:
        if (f.IsLiteral)
          return $"const {Name(f.FieldType)} {f.Name} = {Value(f.GetRawConstantValue())}";
        return $"field {(f.IsStatic ? "static " : "")}{(f.IsInitOnly ? "readonly " : "")}{Name(f.FieldType)} {f.Name}";
      case ConstructorInfo c:
        return $"{(c.IsStatic ? "static " : "")}ctor({Parameters(c)})";
      case MethodInfo mi:
        if (mi.IsSpecialName && (mi.Name.StartsWith("get_", StringComparison.Ordinal) || mi.Name.StartsWith("set_", StringComparison.Ordinal)
                                 || mi.Name.StartsWith("add_", StringComparison.Ordinal) || mi.Name.StartsWith("remove_", StringComparison.Ordinal))
            && IsAccessor(mi))
          return null;
        return $"method {Modifiers(mi)}{Returns(mi)} {mi.Name}{Generics(mi)}({Parameters(mi)})";
      case PropertyInfo p:
        string index = p.GetIndexParameters().Length > 0 ? $"[{Parameters(p.GetIndexParameters())}]" : "";
        string accessors = string.Join(" ", new[] { ("get", p.GetMethod), ("set", p.SetMethod) }
          .Where(a => a.Item2 is { } x && Visible(x))
          .Select(a => (a.Item2!.IsDefined(typeof(IsReadOnlyAttribute), false) ? "readonly " : "")
                       + (a.Item1 == "set" && IsInit(a.Item2!) ? "init" : a.Item1) + ";"));
        MethodInfo any = p.GetAccessors(true).First();
        return $"property {(any.IsStatic ? "static " : "")}{RefReturn(any)}{Name(p.PropertyType)} {p.Name}{index} {{ {accessors} }}";
      case EventInfo e:
        return $"event {Name(e.EventHandlerType!)} {e.Name}";
      case Type n:
        return $"nested {Name(n)}";
      default:
        return null;
    }
  }

  static bool IsAccessor(MethodInfo m) =>
    m.DeclaringType!.GetProperties(Declared).Any(p => p.GetMethod == m || p.SetMethod == m)
    || m.DeclaringType!.GetEvents(Declared).Any(e => e.AddMethod == m || e.RemoveMethod == m);

  static bool IsInit(MethodInfo set) =>
    set.ReturnParameter.GetRequiredCustomModifiers().Contains(typeof(IsExternalInit));

  static string Modifiers(MethodInfo m)
  {
    string s = m.IsStatic ? "static " : "";
    if (m.IsAbstract) s += "abstract ";
    else if (m.IsVirtual && !m.IsFinal && m.GetBaseDefinition() == m && !m.DeclaringType!.IsInterface) s += "virtual ";
    else if (m.IsVirtual && m.GetBaseDefinition() != m) s += "override ";
    if (m.IsDefined(typeof(IsReadOnlyAttribute), false)) s += "readonly ";
    return s;
  }

  static string RefReturn(MethodInfo m) =>
    !m.ReturnType.IsByRef ? "" : m.ReturnParameter.IsDefined(typeof(IsReadOnlyAttribute), false) ? "ref readonly " : "ref ";

  static string Returns(MethodInfo m) => RefReturn(m) + Name(m.ReturnType);

  static string Generics(MemberInfo m)
  {
    Type[] args = m switch
    {
      Type t when t.IsGenericTypeDefinition => t.GetGenericArguments(),
      MethodInfo mi when mi.IsGenericMethodDefinition => mi.GetGenericArguments(),
      _ => Type.EmptyTypes,
    };
    return args.Length == 0 ? "" : "<" + string.Join(", ", args.Select(a => a.Name)) + ">";
  }

  static string Parameters(MethodBase m) => Parameters(m.GetParameters());

  static string Parameters(ParameterInfo[] ps) => string.Join(", ", ps.Select(p =>
  {
    string modifier = p.ParameterType.IsByRef ? (p.IsOut ? "out " : p.IsIn ? "in " : "ref ") : "";
    if (p.IsDefined(typeof(ParamArrayAttribute), false))
      modifier = "params " + modifier;
    string value = p.HasDefaultValue ? " = " + Value(p.RawDefaultValue) : "";
    return $"{modifier}{Name(p.ParameterType)} {p.Name}{value}";
  }));

  static string Value(object? v) => v switch
  {
    null => "null",
    string s => "\"" + s + "\"",
    bool b => b ? "true" : "false",
    float f => f.ToString("R", CultureInfo.InvariantCulture) + "f",
    double d => d.ToString("R", CultureInfo.InvariantCulture),
    IFormattable x => x.ToString(null, CultureInfo.InvariantCulture),
    _ => v.ToString()!,
  };

  static readonly Dictionary<Type, string> keywords = new()
  {
    [typeof(void)] = "void", [typeof(bool)] = "bool", [typeof(byte)] = "byte", [typeof(sbyte)] = "sbyte", [typeof(short)] = "short",
    [typeof(ushort)] = "ushort", [typeof(int)] = "int", [typeof(uint)] = "uint", [typeof(long)] = "long", [typeof(ulong)] = "ulong",
    [typeof(float)] = "float", [typeof(double)] = "double", [typeof(decimal)] = "decimal", [typeof(char)] = "char",
    [typeof(string)] = "string", [typeof(object)] = "object",
  };

  /// <summary>A type as C# writes it, namespaces included (by-reference types without their <c>&amp;</c>: the modifier says it).</summary>
  public static string Name(Type t)
  {
    if (t.IsByRef)
      return Name(t.GetElementType()!);
    if (t.IsArray)
      return Name(t.GetElementType()!) + "[" + new string(',', t.GetArrayRank() - 1) + "]";
    if (t.IsPointer)
      return Name(t.GetElementType()!) + "*";
    if (t.IsGenericParameter)
      return t.Name;
    if (keywords.TryGetValue(t, out string? k))
      return k;
    string name = t.IsNested ? Name(t.DeclaringType!) + "." + t.Name : (t.Namespace is null ? "" : t.Namespace + ".") + t.Name;
    int tick = name.IndexOf('`');
    if (tick >= 0)
      name = name[..tick];
    if (t.IsGenericType && !t.IsGenericTypeDefinition)
      name += "<" + string.Join(", ", t.GetGenericArguments().Select(Name)) + ">";
    return name;
  }
}
