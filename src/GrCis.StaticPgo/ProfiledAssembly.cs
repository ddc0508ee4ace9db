using System;
using System.Collections.Generic;
using System.IO;
using System.Reflection.Metadata;
using System.Reflection.PortableExecutable;

namespace GrCis.StaticPgo;

/// <summary>
/// An assembly the profile describes: its methods by the runtime's name for them (type, '.', method), each with its
/// IL size and parameter count, which tell overloads apart as the text dump's header and signature do.
/// </summary>
internal sealed class ProfiledAssembly : IDisposable
{
  readonly PEReader pe;

  public ProfiledAssembly(string path)
  {
    pe = new PEReader(File.OpenRead(path));
    if (!pe.HasMetadata) throw new BadImageFormatException($"{path}: not a .NET assembly");
    Metadata = pe.GetMetadataReader();
    if (!Metadata.IsAssembly) throw new BadImageFormatException($"{path}: a module without an assembly manifest");
    AssemblyDefinition definition = Metadata.GetAssemblyDefinition();
    Name = Metadata.GetString(definition.Name);
    Version = definition.Version;
  }

  public MetadataReader Metadata { get; }
  public string Name { get; }
  public Version Version { get; }

  /// <summary>"Namespace.Type+Nested", the runtime's spelling of a type definition's name.</summary>
  public string TypeName(TypeDefinitionHandle handle)
  {
    TypeDefinition type = Metadata.GetTypeDefinition(handle);
    string name = Metadata.GetString(type.Name);
    if (type.IsNested) return TypeName(type.GetDeclaringType()) + "+" + name;
    string space = Metadata.GetString(type.Namespace);
    return space.Length == 0 ? name : space + "." + name;
  }

  /// <summary>
  /// The methods with IL a profile can describe. Generic types and generic methods are left out: their runtime name
  /// carries an instantiation, and the shared code a profile would name is not the definition.
  /// </summary>
  public IEnumerable<(string Name, MethodDefinitionHandle Handle, int IlSize)> Methods()
  {
    foreach (TypeDefinitionHandle typeHandle in Metadata.TypeDefinitions)
    {
      TypeDefinition type = Metadata.GetTypeDefinition(typeHandle);
      if (type.GetGenericParameters().Count > 0 || DeclaredInGeneric(type)) continue;
      string typeName = TypeName(typeHandle);
      foreach (MethodDefinitionHandle methodHandle in type.GetMethods())
      {
        MethodDefinition method = Metadata.GetMethodDefinition(methodHandle);
        if (method.RelativeVirtualAddress == 0 || method.GetGenericParameters().Count > 0) continue;
        int ilSize = pe.GetMethodBody(method.RelativeVirtualAddress).GetILReader().Length;
        yield return (typeName + "." + Metadata.GetString(method.Name), methodHandle, ilSize);
      }
    }
  }

  public int ParameterCount(MethodDefinitionHandle handle)
  {
    BlobReader signature = Metadata.GetBlobReader(Metadata.GetMethodDefinition(handle).Signature);
    SignatureHeader header = signature.ReadSignatureHeader();
    if (header.IsGeneric) signature.ReadCompressedInteger();
    return signature.ReadCompressedInteger();
  }

  bool DeclaredInGeneric(TypeDefinition type)
  {
    while (type.IsNested)
    {
      type = Metadata.GetTypeDefinition(type.GetDeclaringType());
      if (type.GetGenericParameters().Count > 0) return true;
    }
    return false;
  }

  public void Dispose() => pe.Dispose();
}
