namespace OpenTK.Mathematics;

/// <summary>
/// The last, optional parameter of the <c>ref</c> twins of the math types' static methods (generated for the
/// types marked <c>[OpenTk3RefForms]</c>, at build time). OpenTK 3 took inputs by <c>ref</c>, OpenTK 4 by <c>in</c>; C# code of either year
/// binds the <c>in</c> methods, but F# passes a ref cell only to a <c>ref</c> parameter and the address of an
/// immutable value only to an <c>in</c> one, so F# code of each year finds its own form. Never passed by hand.
/// </summary>
public enum OpenTk3RefForm
{
  /// <summary>The only value: the call takes OpenTK 3's <c>ref</c> form.</summary>
  Ref,
}
