using System;
using System.Collections.Immutable;
using System.Reflection.Metadata;
using System.Reflection.Metadata.Ecma335;

namespace GrCis.StaticPgo;

/// <summary>
/// A type in a method signature, decoded from one assembly's metadata with its type names already moved into the
/// profile's own tables, so it can be written again there (<see cref="Encode"/>).
/// </summary>
internal abstract record SignatureType
{
  public sealed record Primitive(PrimitiveTypeCode Code) : SignatureType;
  public sealed record Named(EntityHandle Handle, bool IsValueType) : SignatureType;
  public sealed record SzArray(SignatureType Element) : SignatureType;
  public sealed record Array(SignatureType Element, ArrayShape Shape) : SignatureType;
  public sealed record Pointer(SignatureType Element) : SignatureType;
  public sealed record ByReference(SignatureType Element) : SignatureType;
  public sealed record Instance(Named Generic, ImmutableArray<SignatureType> Arguments) : SignatureType;
  public sealed record Parameter(int Index, bool OfMethod) : SignatureType;
  public sealed record Modified(Named Modifier, SignatureType Unmodified, bool Required) : SignatureType;

  /// <summary>Writes a type that is not a parameter's or the return's outer level (no by-ref, no void there).</summary>
  public static void Encode(SignatureTypeEncoder encoder, SignatureType type)
  {
    switch (type)
    {
      case Primitive { Code: PrimitiveTypeCode.Object }: encoder.Object(); break;
      case Primitive { Code: PrimitiveTypeCode.String }: encoder.String(); break;
      case Primitive p: encoder.PrimitiveType(p.Code); break;
      case Named n: encoder.Type(n.Handle, n.IsValueType); break;
      case SzArray a: Encode(encoder.SZArray(), a.Element); break;
      case Array a:
        encoder.Array(out SignatureTypeEncoder element, out ArrayShapeEncoder shape);
        Encode(element, a.Element);
        shape.Shape(a.Shape.Rank, a.Shape.Sizes, a.Shape.LowerBounds);
        break;
      case Pointer p: Encode(encoder.Pointer(), p.Element); break;
      case Instance g:
        {
          GenericTypeArgumentsEncoder arguments = encoder.GenericInstantiation(g.Generic.Handle, g.Arguments.Length, g.Generic.IsValueType);
          foreach (SignatureType argument in g.Arguments) Encode(arguments.AddArgument(), argument);
          break;
        }
      case Parameter { OfMethod: true } p: encoder.GenericMethodTypeParameter(p.Index); break;
      case Parameter p: encoder.GenericTypeParameter(p.Index); break;
      case Modified m:
        encoder.CustomModifiers().AddModifier(m.Modifier.Handle, isOptional: !m.Required);
        Encode(encoder, m.Unmodified);
        break;
      default: throw new NotSupportedException($"a {type.GetType().Name} inside a signature");
    }
  }

  /// <summary>Writes a parameter or the return type: its modifiers, then by-ref or void, then the type.</summary>
  public static void EncodeOuter(SignatureType type, Func<CustomModifiersEncoder> modifiers, Func<bool, SignatureTypeEncoder> typeOf, Action asVoid)
  {
    while (type is Modified m)
    {
      modifiers().AddModifier(m.Modifier.Handle, isOptional: !m.Required);
      type = m.Unmodified;
    }
    switch (type)
    {
      case Primitive { Code: PrimitiveTypeCode.Void }: asVoid(); break;
      case ByReference r: Encode(typeOf(true), r.Element); break;
      default: Encode(typeOf(false), type); break;
    }
  }
}
