using System;
using System.Collections.Generic;
using System.Linq;
using System.Reflection;

namespace Utilities;

/// <summary>Finding types by reflection (GrCis), e.g. every class that implements an interface.</summary>
public static class TypeLoader
{
  /// <summary>The types of <paramref name="assembly"/> that load; types whose dependencies are missing are left out instead of failing.</summary>
  public static IEnumerable<Type> GetLoadableTypes(this Assembly assembly)
  {
    ArgumentNullException.ThrowIfNull(assembly);
    try
    {
      return assembly.GetTypes();
    }
    catch (ReflectionTypeLoadException e)
    {
      return e.Types.OfType<Type>();
    }
  }

  /// <summary>Every loaded type (in all assemblies of the process) assignable to <typeparamref name="Interface"/>, except that type itself.</summary>
  public static IEnumerable<Type> GetTypesWithInterface<Interface>()
  {
    Type it = typeof(Interface);
    var result = new List<Type>();
    foreach (Assembly asm in AppDomain.CurrentDomain.GetAssemblies())
      foreach (Type t in asm.GetLoadableTypes())
        if (t != it && it.IsAssignableFrom(t))
          result.Add(t);
    return result;
  }
}
