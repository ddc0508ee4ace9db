using System;
using System.Collections.Generic;
using System.Linq;
using System.Reflection;
using OpenTK.Mathematics;

namespace GrCis.Mathematics.Tests;

/// <summary>
/// OpenTK 3 took its static methods' inputs by <c>ref</c>, OpenTK 4 by <c>in</c>, and the math types here follow
/// OpenTK 4. C# code of either year compiles against <c>in</c>, but F# does not: it passes a ref cell
/// (<c>Vector3.Add(ref a, ref b)</c>, OpenTK 3) only to <c>ref</c> and the address of an immutable value
/// (<c>Vector3.Add(&amp;a, &amp;b)</c>, OpenTK 4) only to <c>in</c>. So every such method has a twin with
/// <c>ref</c> inputs and one more optional parameter (<see cref="OpenTk3RefForm"/>): C# callers always get the
/// <c>in</c> method, F# callers the one their arguments fit. The twins are generated at build time
/// (GrCis.Mathematics.Generators' <c>RefFormGenerator</c>, for every struct marked <c>[OpenTk3RefForms]</c>).
/// </summary>
public class RefFormTests
{
  static readonly Assembly assembly = typeof(Vector3d).Assembly;

  /// <summary>Public static methods of the math types with an <c>in</c> parameter (operators aside).</summary>
  static IEnumerable<MethodInfo> InMethods(Type t) =>
    t.GetMethods(BindingFlags.Public | BindingFlags.Static | BindingFlags.DeclaredOnly)
     .Where(m => !m.IsSpecialName && m.GetParameters().Any(p => p.IsIn))
     .OrderBy(m => m.Name, StringComparer.Ordinal).ThenBy(m => Signature(m), StringComparer.Ordinal);

  static IEnumerable<Type> MathTypes() =>
    assembly.GetExportedTypes().Where(t => t.Namespace == "OpenTK.Mathematics" && t.IsValueType && !t.IsEnum)
            .OrderBy(t => t.Name, StringComparer.Ordinal);

  static string Signature(MethodInfo m) => string.Join(",", m.GetParameters().Select(p => p.ParameterType.Name));

  static MethodInfo? Twin(MethodInfo m)
  {
    ParameterInfo[] ps = m.GetParameters();
    Type[] types = ps.Select(p => p.ParameterType).Append(typeof(OpenTk3RefForm)).ToArray();
    MethodInfo? twin = m.DeclaringType!.GetMethod(m.Name, BindingFlags.Public | BindingFlags.Static, types);
    return twin != null && twin.GetParameters().Zip(ps).All(x => x.First.IsIn == false && x.First.IsOut == x.Second.IsOut) ? twin : null;
  }

  [Fact]
  public void Every_static_method_with_in_parameters_has_its_OpenTK_3_ref_twin()
  {
    var missing = MathTypes().SelectMany(InMethods).Where(m => Twin(m) == null)
                             .Select(m => $"{m.DeclaringType!.Name}.{m.Name}({Signature(m)})").ToList();
    Assert.True(missing.Count == 0, "no ref twin (is the type marked [OpenTk3RefForms]?): " + string.Join("; ", missing));
    Assert.True(MathTypes().SelectMany(InMethods).Count() > 100);
  }

  [Fact]
  public void A_ref_twin_gives_what_its_in_method_gives()
  {
    var a = new Vector3d(1, 2, 3);
    var b = new Vector3d(-4, 0.5, 2);
    Vector3d.Add(in a, in b, out Vector3d viaIn);
    Vector3d.Add(ref a, ref b, out Vector3d viaRef, OpenTk3RefForm.Ref);
    Assert.Equal(viaIn, viaRef);

    Matrix4 m = Matrix4.CreateRotationY(0.3f) * Matrix4.CreateTranslation(1, 2, 3);
    var v = new Vector3(0.5f, -1, 2);
    Vector3.TransformPosition(in v, in m, out Vector3 p1);
    Vector3.TransformPosition(ref v, ref m, out Vector3 p2, OpenTk3RefForm.Ref);
    Assert.Equal(p1, p2);

    // A C# call with ref arguments binds the in method (no marker needed), as OpenTK 3 code is written.
    Vector3d.Add(ref a, ref b, out Vector3d plain);
    Assert.Equal(viaIn, plain);
  }
}
