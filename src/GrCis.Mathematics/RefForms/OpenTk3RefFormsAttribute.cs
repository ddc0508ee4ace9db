using System;
using System.Diagnostics;

namespace OpenTK.Mathematics;

/// <summary>
/// Asks for OpenTK 3's <c>ref</c> forms of the type's static methods: for every public static method with an
/// <c>in</c> parameter, GrCis.Mathematics.Generators (<c>RefFormGenerator</c>) adds at build time a twin that takes
/// those parameters by <c>ref</c> and one more optional <see cref="OpenTk3RefForm"/> parameter, and calls the
/// <c>in</c> method (see <see cref="OpenTk3RefForm"/> for why). The twins are written nowhere in the source; the
/// generated files are under <c>obj/</c>. Only the generator reads this attribute: it is not compiled into the assembly.
/// </summary>
[Conditional("GRCIS_GENERATOR_ONLY")]
[AttributeUsage(AttributeTargets.Struct, Inherited = false)]
internal sealed class OpenTk3RefFormsAttribute : Attribute
{
}
