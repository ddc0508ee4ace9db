using System;
using System.Collections.Generic;
using System.IO;
using System.IO.Compression;
using System.Linq;
using System.Reflection.Metadata;
using System.Reflection.PortableExecutable;
using System.Text.Json.Nodes;
using System.Xml.Linq;

namespace GrCis.Cli.Tests;

/// <summary>
/// What a tool package of grcis must hold, read from the .nupkg itself: the pointer package <c>GrCis.Cli</c> names a
/// package per platform; a platform's package holds the launcher (apphost) of that platform, grcis's runtime settings,
/// and grcis and the library compiled ahead of time (ReadyToRun) for that operating system and processor.
/// </summary>
internal static class ToolPackageCheck
{
  /// <summary>A platform's ReadyToRun image keeps the processor in its PE machine field, xor a mark of the operating system.</summary>
  static readonly Dictionary<string, ushort> OperatingSystemMark = new() { ["win"] = 0, ["linux"] = 0x7B79, ["osx"] = 0x4644 };

  static readonly Dictionary<string, Machine> Processor = new() { ["x64"] = Machine.Amd64, ["arm64"] = Machine.Arm64 };

  /// <summary>The PE machine field a ReadyToRun image compiled for <paramref name="rid"/> (e.g. <c>osx-arm64</c>) carries.</summary>
  internal static ushort ReadyToRunMachine(string rid)
  {
    string[] parts = rid.Split('-');
    return (ushort)((ushort)Processor[parts[1]] ^ OperatingSystemMark[parts[0]]);
  }

  /// <summary>The platform packages the pointer package <paramref name="nupkg"/> names (its DotnetToolSettings.xml).</summary>
  internal static string[] PlatformsOfPointer(string nupkg)
  {
    using ZipArchive zip = ZipFile.OpenRead(nupkg);
    ZipArchiveEntry settings = Assert.Single(zip.Entries, e => e.Name == "DotnetToolSettings.xml");
    // The pointer carries no code of its own.
    Assert.DoesNotContain(zip.Entries, e => e.Name.EndsWith(".dll", StringComparison.Ordinal));
    using Stream s = settings.Open();
    return XDocument.Load(s).Descendants("RuntimeIdentifierPackage").Select(e => (string)e.Attribute("RuntimeIdentifier")!).ToArray();
  }

  /// <summary>
  /// Asserts what <paramref name="nupkg"/>, the package of platform <paramref name="rid"/>, holds: no file twice, the
  /// launcher for the platform, the tiering delay of grcis's runtime config, and each of <paramref name="readyToRun"/>
  /// compiled ahead of time for that platform.
  /// </summary>
  internal static void PlatformPackage(string nupkg, string rid, string tool, params string[] readyToRun)
  {
    using ZipArchive zip = ZipFile.OpenRead(nupkg);
    string folder = $"tools/net10.0/{rid}/";
    string[] names = zip.Entries.Select(e => e.FullName).ToArray();
    Assert.Equal(names.Length, names.Distinct(StringComparer.OrdinalIgnoreCase).Count());
    // Invariant globalization: resources of other languages would never load.
    Assert.DoesNotContain(names, n => n.EndsWith(".resources.dll", StringComparison.Ordinal));

    string launcher = rid.StartsWith("win", StringComparison.Ordinal) ? tool + ".exe" : tool;
    using (var s = new MemoryStream(Read(zip, folder + "DotnetToolSettings.xml")))
    {
      XElement command = Assert.Single(XDocument.Load(s).Descendants("Command"));
      Assert.Equal(launcher, (string?)command.Attribute("EntryPoint"));
      Assert.Equal("executable", (string?)command.Attribute("Runner"));
    }
    Assert.Equal(rid, Launcher(Read(zip, folder + launcher)));

    JsonNode config = JsonNode.Parse(Read(zip, folder + tool + ".runtimeconfig.json"))!;
    Assert.Equal(10, ExecutableTests.RuntimeOption(config, "System.Runtime.TieredCompilation.CallCountingDelayMs")?.GetValue<int>());

    foreach (string dll in readyToRun)
    {
      using var pe = new PEReader(new MemoryStream(Read(zip, folder + dll)));
      Assert.True(ReadyToRunTraits(pe) != null, $"{dll} in {Path.GetFileName(nupkg)} is not ReadyToRun");
      Assert.True(ReadyToRunMachine(rid) == (ushort)pe.PEHeaders.CoffHeader.Machine,
                  $"{dll} in {Path.GetFileName(nupkg)} is compiled for machine 0x{(ushort)pe.PEHeaders.CoffHeader.Machine:X4}, not {rid}'s 0x{ReadyToRunMachine(rid):X4}");
      // The library inlines its vector operations (another assembly's) in every platform's images.
      if (dll == "GrCis.Rendering.dll")
        CompiledAcrossAssemblies(pe, $"{dll} in {Path.GetFileName(nupkg)}");
    }
  }

  /// <summary>
  /// Asserts what the portable package <paramref name="nupkg"/> holds: grcis as plain code (any processor) that
  /// <c>dotnet</c> runs, with grcis's runtime settings.
  /// </summary>
  internal static void PortablePackage(string nupkg, string tool)
  {
    using ZipArchive zip = ZipFile.OpenRead(nupkg);
    const string Folder = "tools/net10.0/any/";
    Assert.DoesNotContain(zip.Entries, e => e.FullName.EndsWith(".resources.dll", StringComparison.Ordinal));
    using (var s = new MemoryStream(Read(zip, Folder + "DotnetToolSettings.xml")))
    {
      XElement command = Assert.Single(XDocument.Load(s).Descendants("Command"));
      Assert.Equal(tool + ".dll", (string?)command.Attribute("EntryPoint"));
      Assert.Equal("dotnet", (string?)command.Attribute("Runner"));
    }
    JsonNode config = JsonNode.Parse(Read(zip, Folder + tool + ".runtimeconfig.json"))!;
    Assert.Equal(10, ExecutableTests.RuntimeOption(config, "System.Runtime.TieredCompilation.CallCountingDelayMs")?.GetValue<int>());
    using var pe = new PEReader(new MemoryStream(Read(zip, Folder + tool + ".dll")));
    Assert.True(ReadyToRunTraits(pe) == null, "the portable package's tool is ReadyToRun");
  }

  /// <summary>
  /// The header flag (READYTORUN_FLAG_UNRELATED_R2R_CODE) of an image that holds generic code whose definitions live in
  /// other assemblies (crossgen2's <c>--non-local-generics-module</c>).
  /// </summary>
  internal const uint HoldsOtherAssemblysGenerics = 0x80;

  /// <summary>
  /// The fixup kind (READYTORUN_FIXUP_Check_IL_Body) the runtime resolves for each method of another assembly inlined
  /// into precompiled code (crossgen2's <c>--opt-cross-module</c>): the inlinee's IL is compared with the one loaded.
  /// </summary>
  const byte CheckInlineeBody = 0x35;

  /// <summary>
  /// What a ReadyToRun image was compiled with, read from its header: the header's flags, whether its code inlines
  /// methods of other assemblies (a fixup that checks an inlinee's IL), and whether it embeds a profile (a section of
  /// instrumentation data, crossgen2's <c>--embed-pgo-data</c>). Null for plain code.
  /// </summary>
  internal static (uint Flags, bool InlinesOtherAssemblies, bool EmbedsProfile)? ReadyToRunTraits(PEReader pe)
  {
    DirectoryEntry native = pe.PEHeaders.CorHeader?.ManagedNativeHeaderDirectory ?? default;
    if (native.Size == 0)
      return null;
    // READYTORUN_HEADER: signature "RTR", version, flags, section count, then (type, address, size) per section.
    BlobReader header = pe.GetSectionData(native.RelativeVirtualAddress).GetReader();
    Assert.Equal(0x00525452, header.ReadInt32());
    header.ReadUInt32();   // major and minor version
    uint flags = header.ReadUInt32();
    int sections = header.ReadInt32();
    bool inlines = false, profile = false;
    for (int i = 0; i < sections; i++)
    {
      int type = header.ReadInt32(), address = header.ReadInt32(), length = header.ReadInt32();
      const int ImportSections = 101, PgoInstrumentationData = 117;
      profile |= type == PgoInstrumentationData && length > 0;
      if (type != ImportSections)
        continue;
      // Each import section (20 bytes): its cells (address, size), flags, type, cell size, and the address of an array
      // of signature addresses, one per cell; a signature's first byte is its fixup kind (0x80: another module's).
      BlobReader imports = pe.GetSectionData(address).GetReader(0, length);
      while (imports.RemainingBytes >= 20 && !inlines)
      {
        imports.ReadInt32();
        int size = imports.ReadInt32();
        imports.ReadUInt16();
        imports.ReadByte();
        int cell = imports.ReadByte(), signatures = imports.ReadInt32();
        imports.ReadInt32();
        if (signatures == 0 || cell == 0)
          continue;
        BlobReader array = pe.GetSectionData(signatures).GetReader();
        for (int k = 0; k < size / cell && !inlines; k++)
          inlines = (pe.GetSectionData(array.ReadInt32()).GetReader().ReadByte() & 0x7F) == CheckInlineeBody;
      }
    }
    return (flags, inlines, profile);
  }

  /// <summary>
  /// Asserts that <paramref name="dll"/> was compiled with grcis's ReadyToRun options (src/GrCis.Cli/ToolPackages.props):
  /// its code inlines other assemblies' methods and the image may hold their generic code.
  /// </summary>
  internal static void CompiledAcrossAssemblies(PEReader pe, string dll)
  {
    var traits = ReadyToRunTraits(pe);
    Assert.True(traits is { InlinesOtherAssemblies: true }, $"{dll} inlines no method of another assembly (compiled without --opt-cross-module)");
    Assert.True((traits!.Value.Flags & HoldsOtherAssemblysGenerics) != 0, $"{dll} holds no generic code of other assemblies (compiled without --non-local-generics-module)");
  }

  /// <summary>The platform a launcher's bytes are for (<c>win-x64</c>, <c>linux-arm64</c>, <c>osx-arm64</c>...), from its header.</summary>
  internal static string Launcher(byte[] file)
  {
    if (file.Length > 0x40 && file[0] == 'M' && file[1] == 'Z')
    {
      using var pe = new PEReader(new MemoryStream(file));
      return "win-" + Processor.Single(p => p.Value == pe.PEHeaders.CoffHeader.Machine).Key;
    }
    if (file.Length > 20 && file[0] == 0x7F && file[1] == 'E' && file[2] == 'L' && file[3] == 'F')
      return "linux-" + BitConverter.ToUInt16(file, 18) switch { 62 => "x64", 183 => "arm64", ushort m => $"elf machine {m}" };
    if (file.Length > 8 && BitConverter.ToUInt32(file, 0) == 0xFEEDFACF)
      return "osx-" + BitConverter.ToUInt32(file, 4) switch { 0x01000007 => "x64", 0x0100000C => "arm64", uint c => $"cpu type {c:X}" };
    return "unknown";
  }

  static byte[] Read(ZipArchive zip, string name)
  {
    ZipArchiveEntry entry = zip.GetEntry(name) ?? throw new Xunit.Sdk.XunitException($"{name} is missing");
    using Stream s = entry.Open();
    using var copy = new MemoryStream();
    s.CopyTo(copy);
    return copy.ToArray();
  }
}
