using System;
using System.Collections.Generic;
using System.Collections.Immutable;
using System.IO;
using System.Reflection;
using System.Reflection.Metadata;
using System.Reflection.Metadata.Ecma335;
using System.Reflection.PortableExecutable;

namespace GrCis.StaticPgo;

/// <summary>
/// Writes a static profile in the format the ReadyToRun compiler (Crossgen2, <c>--mibc</c>) reads: a .NET assembly
/// whose IL is the data. Its global method <c>AssemblyDictionary</c> lists groups (<c>ldstr "Assembly;"</c>,
/// <c>ldtoken</c> of the group's method, <c>pop</c>); a group's method lists, per profiled method, <c>ldtoken</c> of
/// a reference to it, <c>ldstr "InstrumentationDataStart"</c>, each schema record as five numbers (which fields follow,
/// then IL offset, kind, count, other) and its values, <c>ldstr "InstrumentationDataEnd"</c> and <c>pop</c>. A type in
/// a histogram is an <c>ldtoken</c> of a reference to it; one this writer cannot name (an instantiated generic type, an
/// array) is a small number, the same for the same name, which the compiler keeps as an unknown type.
/// </summary>
internal sealed class MibcWriter
{
  // Each record states all four fields (the compiler's reader also takes differences from the previous record).
  const int AllFields = 0xF;

  readonly MetadataBuilder metadata = new();
  readonly BlobBuilder ilStream = new();
  readonly MethodBodyStreamEncoder bodies;
  readonly Dictionary<string, AssemblyReferenceHandle> assemblies = new(StringComparer.Ordinal);
  readonly Dictionary<string, TypeReferenceHandle> types = new(StringComparer.Ordinal);
  readonly Dictionary<string, int> unknownHandles = new(StringComparer.Ordinal);
  readonly SortedDictionary<string, InstructionEncoder> groups = new(StringComparer.Ordinal);

  public MibcWriter() => bodies = new MethodBodyStreamEncoder(ilStream);

  public int MethodCount { get; private set; }

  /// <summary>Adds a method of <paramref name="assembly"/> with the counts of <paramref name="profile"/>.</summary>
  /// <exception cref="NotSupportedException">Its signature has a type a reference cannot name here (a function pointer).</exception>
  public void Add(ProfiledAssembly assembly, MethodDefinitionHandle method, ProfiledMethod profile)
  {
    EntityHandle reference = MethodReference(assembly, method);
    string group = assembly.Name + ";";
    if (!groups.TryGetValue(group, out InstructionEncoder il))
      groups[group] = il = new InstructionEncoder(new BlobBuilder());
    il.OpCode(ILOpCode.Ldtoken);
    il.Token(reference);
    il.LoadString(metadata.GetOrAddUserString("InstrumentationDataStart"));
    foreach (SchemaEntry entry in profile.Schema)
    {
      il.LoadConstantI4(AllFields);
      il.LoadConstantI4(entry.IlOffset);
      il.LoadConstantI4(entry.Kind);
      il.LoadConstantI4(entry.Count);
      il.LoadConstantI4(entry.Other);
      for (int v = 0; v < entry.Count; v++)
        switch (entry.Marshal)
        {
          case SchemaEntry.FourByte: il.LoadConstantI4(unchecked((int)(uint)Math.Min(entry.Values[v], uint.MaxValue))); break;
          case SchemaEntry.EightByte: il.LoadConstantI8(entry.Values[v]); break;
          case SchemaEntry.TypeHandle: TypeHandle(il, entry.Handles[v]); break;
          case SchemaEntry.MethodHandle: il.LoadConstantI4(Unknown(entry.Handles[v])); break;
        }
    }
    il.LoadString(metadata.GetOrAddUserString("InstrumentationDataEnd"));
    il.OpCode(ILOpCode.Pop);
    MethodCount++;
  }

  /// <summary>Writes the profile assembly; <paramref name="name"/> is its simple name.</summary>
  public void Write(Stream output, string name)
  {
    var voidSignature = new BlobBuilder();
    new BlobEncoder(voidSignature).MethodSignature().Parameters(0, r => r.Void(), _ => { });
    BlobHandle signature = metadata.GetOrAddBlob(voidSignature);

    var dictionary = new InstructionEncoder(new BlobBuilder());
    MethodDefinitionHandle first = default;
    int index = 0;
    foreach ((string group, InstructionEncoder il) in groups)
    {
      il.OpCode(ILOpCode.Ret);
      MethodDefinitionHandle method = GlobalMethod("Assemblies_" + ++index, il, signature);
      if (first.IsNil) first = method;
      dictionary.LoadString(metadata.GetOrAddUserString(group));
      dictionary.OpCode(ILOpCode.Ldtoken);
      dictionary.Token(method);
      dictionary.OpCode(ILOpCode.Pop);
    }
    dictionary.OpCode(ILOpCode.Ret);
    MethodDefinitionHandle root = GlobalMethod("AssemblyDictionary", dictionary, signature);
    if (first.IsNil) first = root;

    // The same input gives the same bytes: the module id is a fixed one, and the PE has no time stamp of its own.
    metadata.AddModule(0, metadata.GetOrAddString(name + ".dll"), metadata.GetOrAddGuid(new Guid("6f0c0b8e-8a0e-4f5b-9a57-5c1d1e0b7a31")), default, default);
    metadata.AddAssembly(metadata.GetOrAddString(name), new Version(1, 0, 0, 0), default, default, default, AssemblyHashAlgorithm.None);
    metadata.AddTypeDefinition(default, default, metadata.GetOrAddString("<Module>"), default,
      MetadataTokens.FieldDefinitionHandle(1), first);

    var pe = new ManagedPEBuilder(PEHeaderBuilder.CreateLibraryHeader(), new MetadataRootBuilder(metadata), ilStream,
      deterministicIdProvider: content => new BlobContentId(new Guid("0b6f1d55-3a3c-4a51-8d1e-7c0e3f6a9b42"), 0x4752_4349));
    var image = new BlobBuilder();
    pe.Serialize(image);
    image.WriteContentTo(output);
  }

  MethodDefinitionHandle GlobalMethod(string name, InstructionEncoder il, BlobHandle signature)
  {
    int offset = bodies.AddMethodBody(il, maxStack: 8);
    return metadata.AddMethodDefinition(MethodAttributes.Public | MethodAttributes.Static, MethodImplAttributes.IL,
      metadata.GetOrAddString(name), signature, offset, default);
  }

  void TypeHandle(InstructionEncoder il, string name)
  {
    if (name == "NULL") { il.LoadConstantI4(0); return; }
    if (NamedType(name) is { } type)
    {
      il.OpCode(ILOpCode.Ldtoken);
      il.Token(type);
    }
    else il.LoadConstantI4(Unknown(name));
  }

  int Unknown(string name)
  {
    if (name == "NULL") return 0;
    if (!unknownHandles.TryGetValue(name, out int index)) unknownHandles[name] = index = unknownHandles.Count + 1;
    return index;
  }

  /// <summary>A reference to a type the runtime wrote as "Namespace.Type+Nested, Assembly, Version=…", or none.</summary>
  TypeReferenceHandle? NamedType(string assemblyQualified)
  {
    int comma = assemblyQualified.IndexOf(", ", StringComparison.Ordinal);
    if (comma <= 0 || assemblyQualified.AsSpan(0, comma).IndexOfAny('[', '*', '&') >= 0) return null;
    AssemblyName assembly;
    try { assembly = new AssemblyName(assemblyQualified[(comma + 2)..]); }
    catch (Exception e) when (e is ArgumentException or FileLoadException) { return null; }
    if (assembly.Name is not { } assemblyName) return null;
    byte[]? token = assembly.GetPublicKeyToken();
    return TypeReference(AssemblyReference(assemblyName, assembly.Version ?? new Version(0, 0), token is { Length: > 0 } ? token : null),
      assemblyName, assemblyQualified[..comma]);
  }

  AssemblyReferenceHandle AssemblyReference(string name, Version version, byte[]? publicKeyToken)
  {
    if (!assemblies.TryGetValue(name, out AssemblyReferenceHandle handle))
      assemblies[name] = handle = metadata.AddAssemblyReference(metadata.GetOrAddString(name), version, default,
        publicKeyToken is null ? default : metadata.GetOrAddBlob(publicKeyToken), default, default);
    return handle;
  }

  TypeReferenceHandle TypeReference(AssemblyReferenceHandle assembly, string assemblyName, string fullName)
  {
    string key = assemblyName + "!" + fullName;
    if (types.TryGetValue(key, out TypeReferenceHandle handle)) return handle;
    int plus = fullName.LastIndexOf('+');
    if (plus >= 0)
      handle = metadata.AddTypeReference(TypeReference(assembly, assemblyName, fullName[..plus]), default,
        metadata.GetOrAddString(fullName[(plus + 1)..]));
    else
    {
      int dot = fullName.LastIndexOf('.');
      handle = metadata.AddTypeReference(assembly, dot < 0 ? default : metadata.GetOrAddString(fullName[..dot]),
        metadata.GetOrAddString(fullName[(dot + 1)..]));
    }
    types[key] = handle;
    return handle;
  }

  /// <summary>A type of <paramref name="assembly"/>'s metadata (definition or reference) as a reference of the profile's.</summary>
  EntityHandle Translate(ProfiledAssembly assembly, EntityHandle handle) => handle.Kind switch
  {
    HandleKind.TypeDefinition => TypeReference(AssemblyReference(assembly.Name, assembly.Version, null), assembly.Name,
      assembly.TypeName((TypeDefinitionHandle)handle)),
    HandleKind.TypeReference => Translate(assembly, (TypeReferenceHandle)handle),
    _ => throw new NotSupportedException($"a {handle.Kind} as a type"),
  };

  TypeReferenceHandle Translate(ProfiledAssembly assembly, TypeReferenceHandle handle)
  {
    MetadataReader reader = assembly.Metadata;
    (AssemblyReferenceHandle scope, string scopeName, string fullName) = Scoped(handle);
    return TypeReference(scope, scopeName, fullName);

    (AssemblyReferenceHandle, string, string) Scoped(TypeReferenceHandle h)
    {
      TypeReference type = reader.GetTypeReference(h);
      string name = reader.GetString(type.Name);
      switch (type.ResolutionScope.Kind)
      {
        case HandleKind.AssemblyReference:
          {
            System.Reflection.Metadata.AssemblyReference target = reader.GetAssemblyReference((AssemblyReferenceHandle)type.ResolutionScope);
            string targetName = reader.GetString(target.Name);
            byte[]? key = target.PublicKeyOrToken.IsNil ? null : reader.GetBlobBytes(target.PublicKeyOrToken);
            string space = reader.GetString(type.Namespace);
            return (AssemblyReference(targetName, target.Version, key), targetName, space.Length == 0 ? name : space + "." + name);
          }
        case HandleKind.TypeReference:
          {
            (AssemblyReferenceHandle a, string an, string outer) = Scoped((TypeReferenceHandle)type.ResolutionScope);
            return (a, an, outer + "+" + name);
          }
        default: throw new NotSupportedException($"a type reference scoped to a {type.ResolutionScope.Kind}");
      }
    }
  }

  EntityHandle MethodReference(ProfiledAssembly assembly, MethodDefinitionHandle handle)
  {
    MethodDefinition method = assembly.Metadata.GetMethodDefinition(handle);
    MethodSignature<SignatureType> signature = method.DecodeSignature(new Provider(this, assembly), genericContext: null);
    var blob = new BlobBuilder();
    new BlobEncoder(blob)
      .MethodSignature(signature.Header.CallingConvention, signature.GenericParameterCount, signature.Header.IsInstance)
      .Parameters(signature.ParameterTypes.Length, out ReturnTypeEncoder returns, out ParametersEncoder parameters);
    SignatureType.EncodeOuter(signature.ReturnType, () => returns.CustomModifiers(), byRef => returns.Type(byRef), () => returns.Void());
    foreach (SignatureType type in signature.ParameterTypes)
    {
      ParameterTypeEncoder parameter = parameters.AddParameter();
      SignatureType.EncodeOuter(type, () => parameter.CustomModifiers(), byRef => parameter.Type(byRef),
        () => throw new NotSupportedException("a void parameter"));
    }
    EntityHandle parent = Translate(assembly, method.GetDeclaringType());
    return metadata.AddMemberReference(parent, metadata.GetOrAddString(assembly.Metadata.GetString(method.Name)), metadata.GetOrAddBlob(blob));
  }

  sealed class Provider(MibcWriter writer, ProfiledAssembly assembly) : ISignatureTypeProvider<SignatureType, object?>
  {
    public SignatureType GetArrayType(SignatureType element, ArrayShape shape) => new SignatureType.Array(element, shape);
    public SignatureType GetByReferenceType(SignatureType element) => new SignatureType.ByReference(element);
    public SignatureType GetFunctionPointerType(MethodSignature<SignatureType> signature) => throw new NotSupportedException("a function pointer");
    public SignatureType GetGenericInstantiation(SignatureType generic, ImmutableArray<SignatureType> arguments) =>
      new SignatureType.Instance((SignatureType.Named)generic, arguments);
    public SignatureType GetGenericMethodParameter(object? context, int index) => new SignatureType.Parameter(index, OfMethod: true);
    public SignatureType GetGenericTypeParameter(object? context, int index) => new SignatureType.Parameter(index, OfMethod: false);
    public SignatureType GetModifiedType(SignatureType modifier, SignatureType unmodified, bool isRequired) =>
      new SignatureType.Modified((SignatureType.Named)modifier, unmodified, isRequired);
    public SignatureType GetPinnedType(SignatureType element) => throw new NotSupportedException("a pinned type");
    public SignatureType GetPointerType(SignatureType element) => new SignatureType.Pointer(element);
    public SignatureType GetPrimitiveType(PrimitiveTypeCode code) => new SignatureType.Primitive(code);
    public SignatureType GetSZArrayType(SignatureType element) => new SignatureType.SzArray(element);
    public SignatureType GetTypeFromDefinition(MetadataReader reader, TypeDefinitionHandle handle, byte rawTypeKind) =>
      new SignatureType.Named(writer.Translate(assembly, handle), rawTypeKind == (byte)SignatureTypeKind.ValueType);
    public SignatureType GetTypeFromReference(MetadataReader reader, TypeReferenceHandle handle, byte rawTypeKind) =>
      new SignatureType.Named(writer.Translate(assembly, handle), rawTypeKind == (byte)SignatureTypeKind.ValueType);
    public SignatureType GetTypeFromSpecification(MetadataReader reader, object? context, TypeSpecificationHandle handle, byte rawTypeKind) =>
      reader.GetTypeSpecification(handle).DecodeSignature(this, context);
  }
}
