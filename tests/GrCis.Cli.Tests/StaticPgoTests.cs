using System;
using System.Buffers.Binary;
using System.Collections.Generic;
using System.Collections.Immutable;
using System.IO;
using System.Linq;
using System.Reflection.Metadata;
using System.Reflection.Metadata.Ecma335;
using System.Reflection.PortableExecutable;
using GrCis.StaticPgo;

namespace GrCis.Cli.Tests;

/// <summary>
/// The static profile's writer (src/GrCis.StaticPgo): the runtime's text dump read as written, runs merged, and the
/// .mibc read back the way the ReadyToRun compiler reads it: every method reference names the method it was written
/// for (its type, name and signature), every record's numbers and types come back in order.
/// </summary>
public class StaticPgoTests
{
  const string Dump = """
    *** START PGO Data, max index = 2 ***
    @@@ codehash 0x2B140A04 methodhash 0xC107273F ilSize 0x0000002C records 0x00000004
    MethodName: Rendering.Accel.PreparedScene.NotFar
    Signature: bool  (float64,float64)
    Schema InstrumentationKind 385 ILOffset 8 Count 1 Other 30
    4000000000
    Schema InstrumentationKind 177 ILOffset 12 Count 1 Other 2147483648
    7
    Schema InstrumentationKind 195 ILOffset 12 Count 3 Other 2147483648
    TypeHandle: Rendering.Sphere, GrCis.Rendering, Version=0.1.0.0, Culture=neutral, PublicKeyToken=null
    TypeHandle: NULL
    TypeHandle: System.Collections.Generic.List`1[[System.Int32, System.Private.CoreLib]], System.Private.CoreLib, Version=10.0.0.0, Culture=neutral, PublicKeyToken=7cec85d7bea7798e
    Schema InstrumentationKind 66 ILOffset 20 Count 1 Other 0
    5 1
    @@@ codehash 0x00000001 methodhash 0x00000002 ilSize 0x00000010 records 0x00000000
    MethodName: Rendering.Nothing.Empty
    Signature: instance void  ()
    *** END PGO Data ***
    """;

  [Fact]
  public void A_text_dump_reads_every_record_with_its_values()
  {
    List<ProfiledMethod> methods = PgoTextDump.Read(new StringReader(Dump), "dump.txt");

    Assert.Equal(2, methods.Count);
    ProfiledMethod m = methods[0];
    Assert.Equal(("Rendering.Accel.PreparedScene.NotFar", "bool  (float64,float64)", 0x2C, 2), (m.Name, m.Signature, m.IlSize, m.ParameterCount));
    Assert.Equal(4, m.Schema.Count);
    // Unsigned 32-bit numbers: counts keep their value, a flag in the top bit of Other is the int's sign bit.
    Assert.Equal((385, 8, 1, 30, 4_000_000_000L), (m.Schema[0].Kind, m.Schema[0].IlOffset, m.Schema[0].Count, m.Schema[0].Other, m.Schema[0].Values[0]));
    Assert.Equal(int.MinValue, m.Schema[1].Other);
    Assert.Equal("Rendering.Sphere, GrCis.Rendering, Version=0.1.0.0, Culture=neutral, PublicKeyToken=null", m.Schema[2].Handles[0]);
    Assert.Equal("NULL", m.Schema[2].Handles[1]);
    // An eight-byte value is written as its low half, then its high half.
    Assert.Equal((1L << 32) + 5, m.Schema[3].Values[0]);
    Assert.Empty(methods[1].Schema);
    Assert.Equal(0, methods[1].ParameterCount);
  }

  [Theory]
  [InlineData(6, "dump.txt:6: the file ends inside a method's records")]
  [InlineData(5, "dump.txt:5: the file ends inside a method's records")]
  [InlineData(3, "dump.txt:3: the file ends inside a method's records")]
  public void A_cut_dump_names_its_file_and_line(int lines, string message)
  {
    string cut = string.Join('\n', Dump.Split('\n').Take(lines));
    var e = Assert.Throws<FormatException>(() => PgoTextDump.Read(new StringReader(cut), "dump.txt"));
    Assert.Equal(message, e.Message);
  }

  [Fact]
  public void A_record_that_is_not_a_number_names_its_line()
  {
    string bad = Dump.Replace("4000000000", "four", StringComparison.Ordinal);
    var e = Assert.Throws<FormatException>(() => PgoTextDump.Read(new StringReader(bad), "dump.txt"));
    Assert.Equal("dump.txt:6: 'four' is not a count", e.Message);
  }

  [Fact]
  public void Runs_add_up_their_edge_counts_and_keep_the_histogram_that_saw_more_calls()
  {
    ProfiledMethod first = PgoTextDump.Read(new StringReader(Dump), "a")[0];
    ProfiledMethod second = PgoTextDump.Read(new StringReader(Dump.Replace("\n7\n", "\n9\n", StringComparison.Ordinal)
      .Replace("TypeHandle: NULL", "TypeHandle: Rendering.Plane, GrCis.Rendering", StringComparison.Ordinal)), "b")[0];

    first.Add(second);

    Assert.Equal(8_000_000_000L, first.Schema[0].Values[0]);
    Assert.Equal(9, first.Schema[1].Values[0]);
    Assert.Equal("Rendering.Plane, GrCis.Rendering", first.Schema[2].Handles[1]);
    Assert.Equal(2 * ((1L << 32) + 5), first.Schema[3].Values[0]);
  }

  [Fact]
  public void Each_training_run_weighs_alike_whatever_its_length()
  {
    // A long run (billions of counts) and a short one (a few) of the same method, with other shapes.
    List<ProfiledMethod> longRun = PgoTextDump.Read(new StringReader(Dump), "long");
    List<ProfiledMethod> shortRun = PgoTextDump.Read(new StringReader(Dump.Replace("4000000000", "4", StringComparison.Ordinal)
      .Replace("5 1", "1 0", StringComparison.Ordinal)), "short");
    double longTotal = 4_000_000_000.0 + ((1L << 32) + 5), shortTotal = 4 + 1;
    var builder = new ProfileBuilder();

    builder.AddRun(longRun);
    builder.AddRun(shortRun);

    // The sum holds each run's counts as fractions of its own total, at the same weight: the short run is not lost.
    ProfiledMethod merged = longRun[0];
    double w = ProfileBuilder.RunWeight;
    Assert.Equal(w * (4e9 / longTotal + 4 / shortTotal), merged.Schema[0].Values[0], 2.0);
    Assert.Equal(w * (((1L << 32) + 5) / longTotal + 1 / shortTotal), merged.Schema[3].Values[0], 2.0);
    // A histogram's call count is weighed the same way (it decides which run's histogram is kept).
    Assert.Equal(Math.Max(1L, (long)Math.Round(7 * w / shortTotal)), merged.Schema[1].Values[0]);
  }

  [Fact]
  public void A_block_a_run_reached_stays_reached_when_weighed()
  {
    List<ProfiledMethod> run = PgoTextDump.Read(new StringReader(Dump.Replace("5 1", "1 0", StringComparison.Ordinal)), "run");
    new ProfileBuilder().AddRun(run);
    // One count beside four billion: below one after scaling, kept at one.
    Assert.Equal(1, run[0].Schema[3].Values[0]);
  }

  [Fact]
  public void A_run_with_another_schema_is_left_out_of_the_sum()
  {
    ProfiledMethod first = PgoTextDump.Read(new StringReader(Dump), "a")[0];
    ProfiledMethod other = PgoTextDump.Read(new StringReader(Dump.Replace("ILOffset 8 ", "ILOffset 9 ", StringComparison.Ordinal)), "b")[0];

    first.Add(other);

    Assert.Equal(4_000_000_000L, first.Schema[0].Values[0]);
  }

  /// <summary>
  /// Every method of the library the writer can name (all but generic ones and function pointers in signatures), each
  /// with a record of every value kind: read back as Crossgen2 reads it, each reference is the method's own type, name
  /// and signature (so a reference resolves to that method, not an overload), and its records are the ones written.
  /// </summary>
  [Fact]
  public void Every_library_method_reads_back_as_itself_with_its_records()
  {
    string library = typeof(Rendering.Sphere).Assembly.Location;
    // Methods the text dump cannot tell apart (same name, IL size and parameter count) share one entry.
    var byKey = new Dictionary<string, List<(string Type, string Name, string Signature)>>();
    var dump = new List<ProfiledMethod>();
    using (var assembly = new ProfiledAssembly(library))
    {
      foreach ((string name, MethodDefinitionHandle handle, int ilSize) in assembly.Methods())
      {
        MethodDefinition method = assembly.Metadata.GetMethodDefinition(handle);
        string signature = SignatureText(assembly.Metadata, method.Signature);
        if (signature.Contains("fnptr", StringComparison.Ordinal)) continue;
        var profiled = new ProfiledMethod
        {
          Name = name, IlSize = ilSize,
          Signature = "void  (" + string.Join(",", Enumerable.Repeat("int32", assembly.ParameterCount(handle))) + ")",
          Schema = Records(byKey.Count + 1),
        };
        if (!byKey.TryGetValue(profiled.Key, out var same))
        {
          byKey[profiled.Key] = same = [];
          dump.Add(profiled);
        }
        same.Add((assembly.TypeName(method.GetDeclaringType()), assembly.Metadata.GetString(method.Name), signature));
      }
    }
    Assert.True(byKey.Count > 2000, $"only {byKey.Count} methods");

    var builder = new ProfileBuilder();
    builder.AddDump(dump);
    var log = new StringWriter();
    var image = new MemoryStream();
    int written = builder.Write([library], image, "probe", log);

    List<(string Type, string Name, string Signature, List<object> Data)> read = ReadBack(image.ToArray());
    Assert.Equal(byKey.Values.Count(v => v.Count == 1), written);
    Assert.Equal(byKey.Values.Count(v => v.Count > 1), log.ToString().Split('\n').Count(l => l.Contains("overloads of the same IL size", StringComparison.Ordinal)));
    Assert.Equal(written, read.Count);
    var seeds = dump.Select((d, i) => (Method: byKey[d.Key], Seed: i + 1)).Where(x => x.Method.Count == 1).ToDictionary(x => x.Method[0], x => x.Seed);
    foreach ((string type, string name, string signature, List<object> data) in read)
      Assert.Equal(Expected(seeds[(type, name, signature)]), data);
    Assert.Equal(written, read.Select(r => (r.Type, r.Name, r.Signature)).Distinct().Count());
  }

  /// <summary>
  /// The whole way on real counts: a training render of the built grcis writes the runtime's text profile, the writer
  /// turns it into a profile of the library, and the ReadyToRun compiler of this machine reads it and embeds it
  /// (its map lists the instrumentation data table the runtime reads, which a compilation without it lacks).
  /// </summary>
  [Fact]
  public void The_ReadyToRun_compiler_embeds_a_profile_written_from_a_training_render()
  {
    string rid = System.Runtime.InteropServices.RuntimeInformation.RuntimeIdentifier;
    string packs = Path.Combine(ReadmeTests.GlobalPackagesFolder(), $"microsoft.netcore.app.crossgen2.{rid}");
    string? crossgen = Directory.Exists(packs)
      ? Directory.GetFiles(packs, OperatingSystem.IsWindows() ? "crossgen2.exe" : "crossgen2", SearchOption.AllDirectories).OrderDescending().FirstOrDefault()
      : null;
    Assert.True(crossgen != null, $"no ReadyToRun compiler in {packs} (the restore of src/GrCis.Cli fetches it)");

    using var tmp = new TempDirectory();
    File.WriteAllText(tmp.File("runs.txt"), "# one render\nrender fiveballs --size 160x120 --spp 4 -o {work}/f.png\n");
    // What an earlier training cached is dropped: a script cached then would not be compiled, nor the compiler profiled.
    Directory.CreateDirectory(tmp.File("work/cache/scripts"));
    File.WriteAllText(tmp.File("work/cache/scripts/stale.bin"), "an earlier training's entry");
    List<string> dumps = TrainingRuns.Run(GrcisProcess.Dotnet, GrcisProcess.Dll, TrainingRuns.Read(tmp.File("runs.txt")),
      tmp.File("work"), tmp.Path, TextWriter.Null);
    Assert.True(File.Exists(tmp.File("work/f.png")));
    Assert.False(File.Exists(tmp.File("work/cache/scripts/stale.bin")));
    var builder = new ProfileBuilder();
    builder.AddDump(PgoTextDump.Read(Assert.Single(dumps)));
    string library = typeof(Rendering.Sphere).Assembly.Location;
    using (FileStream file = File.Create(tmp.File("grcis.mibc")))
      Assert.True(builder.Write([library], file, "grcis", TextWriter.Null) > 20);

    string framework = Path.GetDirectoryName(typeof(object).Assembly.Location)!;
    string Compile(string name, params string[] extra)
    {
      (int code, string output) = Shell.Run(tmp.Path, null, TimeSpan.FromMinutes(3), crossgen,
        [library, "-o", tmp.File(name + ".dll"), "-r:" + Path.Combine(framework, "*.dll"),
         "-r:" + Path.Combine(Path.GetDirectoryName(library)!, "*.dll"), "-O", "--map", .. extra]);
      Assert.True(code == 0, output);
      return File.ReadAllText(tmp.File(name + ".map"));
    }
    Assert.Contains("__ReadyToRunInstrumentationDataTable", Compile("with", "--mibc", tmp.File("grcis.mibc"), "--embed-pgo-data"), StringComparison.Ordinal);
    Assert.DoesNotContain("__ReadyToRunInstrumentationDataTable", Compile("without"), StringComparison.Ordinal);
  }

  /// <summary>A method's records: an edge count, a four-byte count above int.MaxValue, an eight-byte one, a histogram.</summary>
  static List<SchemaEntry> Records(int seed) =>
  [
    new() { Kind = 385, IlOffset = seed % 1000, Count = 1, Other = seed % 777, Values = [seed], Handles = new string[1] },
    new() { Kind = 65, IlOffset = 3, Count = 1, Other = 0, Values = [3_000_000_000L], Handles = new string[1] },
    new() { Kind = 66, IlOffset = 4, Count = 1, Other = 0, Values = [(long)seed << 33], Handles = new string[1] },
    new() { Kind = 177, IlOffset = 5, Count = 1, Other = int.MinValue, Values = [seed], Handles = new string[1] },
    new()
    {
      Kind = 195, IlOffset = 5, Count = 4, Other = int.MinValue, Values = new long[4],
      Handles = ["Rendering.Sphere, GrCis.Rendering, Version=0.1.0.0", "NULL",
                 "System.String[], System.Private.CoreLib, Version=10.0.0.0, PublicKeyToken=7cec85d7bea7798e",
                 "Rendering.Accel.PreparedScene+Query, GrCis.Rendering, Version=0.1.0.0"],
    },
  ];

  /// <summary>What Crossgen2 reads for <see cref="Records"/>: per record its fields, then its values.</summary>
  static List<object> Expected(int seed) =>
  [
    0xFL, (long)(seed % 1000), 385L, 1L, (long)(seed % 777), (long)seed,
    0xFL, 3L, 65L, 1L, 0L, (long)unchecked((int)3_000_000_000L),
    0xFL, 4L, 66L, 1L, 0L, (long)seed << 33,
    0xFL, 5L, 177L, 1L, (long)int.MinValue, (long)seed,
    // An array type is named by no reference: a small number, the same for the same name.
    0xFL, 5L, 195L, 4L, (long)int.MinValue, "GrCis.Rendering!Rendering.Sphere", 0L, 1L, "GrCis.Rendering!Rendering.Accel.PreparedScene+Query",
  ];

  /// <summary>
  /// Reads a profile as the ReadyToRun compiler's parser does: AssemblyDictionary's groups, each group's methods, each
  /// method's numbers between "InstrumentationDataStart" and "InstrumentationDataEnd" (a type as "Assembly!Name").
  /// </summary>
  static List<(string, string, string, List<object>)> ReadBack(byte[] image)
  {
    using var pe = new PEReader(ImmutableArray.Create(image));
    MetadataReader md = pe.GetMetadataReader();
    var result = new List<(string, string, string, List<object>)>();
    MethodDefinition root = md.MethodDefinitions.Select(md.GetMethodDefinition).Single(m => md.GetString(m.Name) == "AssemblyDictionary");
    Assert.Equal("<Module>", md.GetString(md.GetTypeDefinition(root.GetDeclaringType()).Name));
    string? group = null;
    foreach ((byte op, int token, long _) in Il(pe, root))
      switch (op)
      {
        case 0x72: group = md.GetUserString(MetadataTokens.UserStringHandle(token)); break;
        case 0xD0:
          Assert.Equal("GrCis.Rendering;", group);
          ReadGroup(md.GetMethodDefinition(MetadataTokens.MethodDefinitionHandle(token)));
          break;
      }
    return result;

    void ReadGroup(MethodDefinition method)
    {
      (string, string, string)? current = null;
      List<object>? data = null;
      foreach ((byte op, int token, long value) in Il(pe, method))
      {
        if (op == 0x72)
        {
          string s = md.GetUserString(MetadataTokens.UserStringHandle(token));
          data = s == "InstrumentationDataStart" ? [] : data;
          if (s == "InstrumentationDataEnd") result.Add((current!.Value.Item1, current.Value.Item2, current.Value.Item3, data!));
        }
        else if (op == 0xD0 && data == null)
        {
          MemberReference reference = md.GetMemberReference(MetadataTokens.MemberReferenceHandle(token));
          current = (TypeRefName(md, (TypeReferenceHandle)reference.Parent).Split('!')[1], md.GetString(reference.Name), SignatureText(md, reference.Signature));
        }
        else if (op == 0xD0) data!.Add(TypeRefName(md, MetadataTokens.TypeReferenceHandle(token & 0xFFFFFF)));
        else if (op == 0x26) data = null;
        else if (data != null && op != 0x2A) data.Add(value);
      }
    }
  }

  static string TypeRefName(MetadataReader md, TypeReferenceHandle handle)
  {
    TypeReference type = md.GetTypeReference(handle);
    string name = md.GetString(type.Name);
    if (type.ResolutionScope.Kind == HandleKind.TypeReference)
      return TypeRefName(md, (TypeReferenceHandle)type.ResolutionScope) + "+" + name;
    string assembly = md.GetString(md.GetAssemblyReference((AssemblyReferenceHandle)type.ResolutionScope).Name);
    string space = md.GetString(type.Namespace);
    return assembly + "!" + (space.Length == 0 ? name : space + "." + name);
  }

  /// <summary>The instructions a profile is made of: opcode, token (ldstr, ldtoken) and constant (ldc.*).</summary>
  static IEnumerable<(byte Op, int Token, long Value)> Il(PEReader pe, MethodDefinition method)
  {
    byte[] il = pe.GetMethodBody(method.RelativeVirtualAddress).GetILBytes()!;
    for (int i = 0; i < il.Length;)
    {
      byte op = il[i++];
      switch (op)
      {
        case >= 0x15 and <= 0x1E: yield return (0x20, 0, op - 0x16); break; // ldc.i4.m1 … ldc.i4.8
        case 0x1F: yield return (0x20, 0, (sbyte)il[i]); i += 1; break;
        case 0x20: yield return (op, 0, BinaryPrimitives.ReadInt32LittleEndian(il.AsSpan(i))); i += 4; break;
        case 0x21: yield return (op, 0, BinaryPrimitives.ReadInt64LittleEndian(il.AsSpan(i))); i += 8; break;
        case 0x72 or 0xD0: yield return (op, BinaryPrimitives.ReadInt32LittleEndian(il.AsSpan(i)), 0); i += 4; break;
        case 0x26 or 0x2A: yield return (op, 0, 0); break;
        default: throw new InvalidDataException($"opcode 0x{op:X2} in a profile");
      }
    }
  }

  /// <summary>A signature as text with its types by name, the same for a definition and a reference to it.</summary>
  static string SignatureText(MetadataReader md, BlobHandle signature)
  {
    BlobReader reader = md.GetBlobReader(signature);
    MethodSignature<string> s = new SignatureDecoder<string, object?>(new TextProvider(), md, null).DecodeMethodSignature(ref reader);
    return $"{s.Header.CallingConvention} {s.Header.IsInstance} {s.GenericParameterCount} {s.ReturnType} ({string.Join(", ", s.ParameterTypes)})";
  }

  sealed class TextProvider : ISignatureTypeProvider<string, object?>
  {
    public string GetArrayType(string element, ArrayShape shape) => $"{element}[{shape.Rank}]";
    public string GetByReferenceType(string element) => element + "&";
    public string GetFunctionPointerType(MethodSignature<string> signature) => "fnptr";
    public string GetGenericInstantiation(string generic, ImmutableArray<string> arguments) => $"{generic}<{string.Join(",", arguments)}>";
    public string GetGenericMethodParameter(object? context, int index) => "!!" + index;
    public string GetGenericTypeParameter(object? context, int index) => "!" + index;
    public string GetModifiedType(string modifier, string unmodified, bool isRequired) => $"{unmodified} {(isRequired ? "modreq" : "modopt")}({modifier})";
    public string GetPinnedType(string element) => element + " pinned";
    public string GetPointerType(string element) => element + "*";
    public string GetPrimitiveType(PrimitiveTypeCode code) => code.ToString();
    public string GetSZArrayType(string element) => element + "[]";
    public string GetTypeFromDefinition(MetadataReader reader, TypeDefinitionHandle handle, byte rawTypeKind)
    {
      TypeDefinition type = reader.GetTypeDefinition(handle);
      string name = reader.GetString(type.Name);
      if (type.IsNested) return GetTypeFromDefinition(reader, type.GetDeclaringType(), 0) + "+" + name;
      string space = reader.GetString(type.Namespace);
      string assembly = reader.GetString(reader.GetAssemblyDefinition().Name);
      return assembly + "!" + (space.Length == 0 ? name : space + "." + name);
    }
    public string GetTypeFromReference(MetadataReader reader, TypeReferenceHandle handle, byte rawTypeKind) => TypeRefName(reader, handle);
    public string GetTypeFromSpecification(MetadataReader reader, object? context, TypeSpecificationHandle handle, byte rawTypeKind) =>
      reader.GetTypeSpecification(handle).DecodeSignature(this, context);
  }
}
