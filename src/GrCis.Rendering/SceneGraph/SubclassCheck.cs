using System;
using System.Collections.Concurrent;
using System.Collections.Generic;
using System.Reflection;
using System.Runtime.CompilerServices;
using OpenTK.Mathematics;

namespace Rendering.Accel;

/// <summary>
/// The one place that decides whether a script's subclass of a library type (a solid, a material, a
/// texture, a light, an image function) still behaves as the library type, so that the library's own
/// allocation-free code may answer for it. Decided by reflection once per class and cached: a subclass
/// that overrides nothing relevant keeps every shortcut, one that overrides a relevant member gets
/// GrCis's general path for that part only. The scene preparation (<see cref="PreparedScene"/>) and the
/// image functions ask here, through the named predicates of <see cref="LibraryTypes"/> (what each fast path
/// needs), which also hold the fast path's exact-class tests (the library classes a kernel calls directly).
/// </summary>
internal static class SubclassCheck
{
  const BindingFlags Declared = BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.DeclaredOnly;

  static readonly ConcurrentDictionary<(Type Actual, Type Library), bool> overridesNothing = new();
  static readonly ConcurrentDictionary<(Type Actual, Type Library), bool> keepsGeometry = new();
  static readonly ConcurrentDictionary<(Type Actual, string Names), bool> overridesAny = new();
  static readonly ConcurrentDictionary<(Type Actual, Type Library, string Name), bool> overridesMethod = new();
  static readonly ConcurrentDictionary<(Type Actual, Type Library, string Names), bool> overridesBelow = new();

  /// <summary>
  /// True when <paramref name="o"/> is a <paramref name="library"/> whose class overrides none of the
  /// library's virtual members, re-implements none of its interfaces and adds no interface (such as
  /// <c>ITimeDependent</c>, which makes a node change with time): it behaves exactly as the library type.
  /// </summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static bool OverridesNothing(object? o, Type library) =>
    o != null && (o.GetType() == library || SubclassOverridesNothing(o.GetType(), library));

  // Asked per hit by the shading: the exact library type is answered inline above, a subclass from the cache.
  static bool SubclassOverridesNothing(Type actual, Type library) =>
    overridesNothing.GetOrAdd((actual, library), static k =>
      k.Actual.GetInterfaces().Length == k.Library.GetInterfaces().Length && !Overrides(k.Actual, k.Library, null));

  /// <summary>
  /// True when <paramref name="solid"/>'s records are those of <paramref name="library"/>: its class does not
  /// override <c>Intersect</c> or <c>GetBoundingBox</c> below the library type (it may change shading,
  /// completion or anything else). Only then may the library's record kernel answer for it.
  /// </summary>
  public static bool KeepsGeometry(object solid, Type library)
  {
    Type actual = solid.GetType();
    return actual == library || keepsGeometry.GetOrAdd((actual, library), static k =>
    {
      MethodInfo? intersect = k.Actual.GetMethod(nameof(IIntersectable.Intersect), new[] { typeof(Vector3d), typeof(Vector3d) });
      Type byRef = typeof(Vector3d).MakeByRefType();
      MethodInfo? box = k.Actual.GetMethod(nameof(ISolid.GetBoundingBox), new[] { byRef, byRef });
      return intersect?.DeclaringType == k.Library && box?.DeclaringType != null && box.DeclaringType.IsAssignableFrom(k.Library);
    });
  }

  /// <summary>
  /// True when a class of <paramref name="actual"/>'s chain declared outside this library (a script's or a
  /// module's) overrides a virtual member named in <paramref name="names"/> (any overload, any accessibility).
  /// </summary>
  public static bool OverridesAny(Type actual, IReadOnlyCollection<string> names) =>
    actual.Assembly != Library && overridesAny.GetOrAdd((actual, string.Join(",", names)), k => Overrides(k.Actual, typeof(object), names));

  /// <summary>
  /// True when a class of <paramref name="actual"/>'s chain below <paramref name="library"/>, the library's own
  /// subclasses included, overrides a virtual member named in <paramref name="names"/> (any overload).
  /// </summary>
  public static bool OverridesAnyBelow(Type actual, Type library, IReadOnlyCollection<string> names) =>
    actual != library && overridesBelow.GetOrAdd((actual, library, string.Join(",", names)), k =>
    {
      for (Type? c = k.Actual; c != null && c != k.Library; c = c.BaseType)
        foreach (MethodInfo m in c.GetMethods(Declared))
          if (m.IsVirtual && m.GetBaseDefinition().DeclaringType != c && Contains(names, m.Name))
            return true;
      return false;
    });

  /// <summary>
  /// True when <paramref name="actual"/> overrides (not merely hides) <paramref name="library"/>'s virtual method
  /// <paramref name="name"/> with exactly <paramref name="parameters"/>, in any class below <paramref name="library"/>.
  /// </summary>
  public static bool OverridesMethod(Type actual, Type library, string name, Type[] parameters) =>
    overridesMethod.GetOrAdd((actual, library, name + "(" + string.Join<Type>(",", parameters) + ")"), k =>
    {
      MethodInfo? m = k.Actual.GetMethod(name, parameters);
      return m != null && m.DeclaringType != k.Library && m.GetBaseDefinition().DeclaringType == k.Library;
    });

  /// <summary>The library's own assembly: a type declared here is not a script's or a module's.</summary>
  public static readonly Assembly Library = typeof(SubclassCheck).Assembly;

  static bool Overrides(Type actual, Type library, IReadOnlyCollection<string>? names)
  {
    if (!library.IsAssignableFrom(actual))
      return true;
    for (Type? c = actual; c != null && c != library && (names == null || c.Assembly != Library); c = c.BaseType)
    {
      foreach (MethodInfo m in c.GetMethods(Declared))
        if (m.IsVirtual && m.GetBaseDefinition().DeclaringType != c && (names == null || Contains(names, m.Name)))
          return true;
      if (names == null && ReimplementsInterface(c, library))
        return true;
    }
    return false;
  }

  /// <summary>An interface of the library type mapped to a method of <paramref name="c"/> (an explicit re-implementation).</summary>
  static bool ReimplementsInterface(Type c, Type library)
  {
    foreach (Type itf in library.GetInterfaces())
      foreach (MethodInfo target in c.GetInterfaceMap(itf).TargetMethods)
        if (target.DeclaringType == c)
          return true;
    return false;
  }

  static bool Contains(IReadOnlyCollection<string> names, string name)
  {
    foreach (string n in names)
      if (n == name)
        return true;
    return false;
  }
}
