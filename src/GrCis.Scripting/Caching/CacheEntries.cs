using System;
using System.Collections.Generic;
using System.IO;
using System.Security.Cryptography;
using System.Text;
using GrCis.Scripting.Compilation;

namespace GrCis.Scripting.Caching;

/// <summary>
/// The bytes of a cache entry: a header (magic, format, kind, key), the compiled image, and at the end an HMAC-SHA-256
/// of all that under the cache's secret (<see cref="ScriptCache"/>: a random key of the user's, kept private in the
/// cache folder). An entry cut short or damaged is told from a whole one, and so is one written by anybody who does not
/// hold the secret (a plain hash anyone can recompute): neither is ever loaded.
/// </summary>
internal static class CacheEntries
{
  /// <summary>Changes when the layout of an entry (or of what it holds) changes; part of every key too.</summary>
  public const int FormatVersion = 3;

  static readonly byte[] magic = "GRCIS-COMPILED\n"u8.ToArray();

  const byte ScriptKind = 1;
  const byte ModuleKind = 2;

  public static byte[] Write(string key, ScriptImage image, byte[] secret) => Write(key, secret, ScriptKind, w =>
  {
    w.Write(image.AssemblyName);
    WriteBytes(w, image.Assembly);
    WriteBytes(w, image.Pdb);
    w.Write(image.EntryType);
    w.Write(image.EntryMethod);
    WriteDiagnostics(w, image.Warnings);
    WriteMap(w, image.Map);
  });

  public static byte[] Write(string key, ModuleImage image, byte[] secret) => Write(key, secret, ModuleKind, w =>
  {
    w.Write(image.AssemblyName);
    WriteBytes(w, image.Assembly);
    WriteBytes(w, image.Pdb);
    WriteBytes(w, image.Documentation);
    WriteStrings(w, image.Files);
    WriteStrings(w, image.SkippedScripts);
    WriteDiagnostics(w, image.Warnings);
    w.Write(image.Maps.Count);
    foreach ((string file, SourceMap map) in image.Maps)
    {
      w.Write(file);
      WriteMap(w, map);
    }
    w.Write(image.Renamed.Count);
    foreach (ShadowedLibraryTypes.Renamed r in image.Renamed)
    {
      w.Write(r.Path);
      w.Write(r.Line);
      w.Write(r.Column);
      w.Write(r.FullName);
    }
  });

  /// <summary>The script image of an entry, or null when the bytes are not a whole entry of this key and format.</summary>
  public static ScriptImage? ReadScript(byte[] entry, string key, byte[] secret) => Read(entry, key, secret, ScriptKind, r => new ScriptImage(
    AssemblyName: r.ReadString(),
    Assembly: ReadBytes(r),
    Pdb: ReadBytes(r),
    EntryType: r.ReadString(),
    EntryMethod: r.ReadString(),
    Warnings: ReadDiagnostics(r),
    Map: ReadMap(r)));

  /// <summary>The module image of an entry, or null when the bytes are not a whole entry of this key and format.</summary>
  public static ModuleImage? ReadModule(byte[] entry, string key, byte[] secret) => Read(entry, key, secret, ModuleKind, r =>
  {
    string name = r.ReadString();
    byte[] assembly = ReadBytes(r);
    byte[] pdb = ReadBytes(r);
    byte[] documentation = ReadBytes(r);
    string[] files = ReadStrings(r);
    string[] skipped = ReadStrings(r);
    ScriptDiagnostic[] warnings = ReadDiagnostics(r);
    int mapCount = ReadCount(r);
    var maps = new Dictionary<string, SourceMap>(mapCount, StringComparer.Ordinal);
    for (int i = 0; i < mapCount; i++)
      maps.Add(r.ReadString(), ReadMap(r));
    var renamed = new ShadowedLibraryTypes.Renamed[ReadCount(r)];
    for (int i = 0; i < renamed.Length; i++)
      renamed[i] = new ShadowedLibraryTypes.Renamed(r.ReadString(), r.ReadInt32(), r.ReadInt32(), r.ReadString());
    return new ModuleImage(name, assembly, pdb, documentation, files, skipped, warnings, maps, renamed);
  });

  static byte[] Write(string key, byte[] secret, byte kind, Action<BinaryWriter> body)
  {
    var stream = new MemoryStream();
    using (var w = new BinaryWriter(stream, Encoding.UTF8, leaveOpen: true))
    {
      w.Write(magic);
      w.Write(FormatVersion);
      w.Write(kind);
      w.Write(key);
      body(w);
    }
    byte[] checksum = HMACSHA256.HashData(secret, stream.GetBuffer().AsSpan(0, (int)stream.Length));
    stream.Write(checksum);
    return stream.ToArray();
  }

  static T? Read<T>(byte[] entry, string key, byte[] secret, byte kind, Func<BinaryReader, T> body) where T : class
  {
    const int checksumLength = HMACSHA256.HashSizeInBytes;
    if (entry.Length < magic.Length + checksumLength || !entry.AsSpan(0, magic.Length).SequenceEqual(magic))
      return null;
    int length = entry.Length - checksumLength;
    if (!CryptographicOperations.FixedTimeEquals(HMACSHA256.HashData(secret, entry.AsSpan(0, length)), entry.AsSpan(length)))
      return null;
    try
    {
      using var r = new BinaryReader(new MemoryStream(entry, magic.Length, length - magic.Length, writable: false), Encoding.UTF8);
      if (r.ReadInt32() != FormatVersion || r.ReadByte() != kind || r.ReadString() != key)
        return null;
      T image = body(r);
      return r.BaseStream.Position == r.BaseStream.Length ? image : null;
    }
    catch (Exception e) when (e is EndOfStreamException or InvalidDataException or ArgumentException or FormatException or DecoderFallbackException)
    {
      return null;
    }
  }

  static void WriteBytes(BinaryWriter w, byte[] bytes)
  {
    w.Write(bytes.Length);
    w.Write(bytes);
  }

  static byte[] ReadBytes(BinaryReader r)
  {
    int n = ReadCount(r);
    byte[] bytes = r.ReadBytes(n);
    return bytes.Length == n ? bytes : throw new EndOfStreamException();
  }

  static void WriteStrings(BinaryWriter w, IReadOnlyList<string> strings)
  {
    w.Write(strings.Count);
    foreach (string s in strings)
      w.Write(s);
  }

  static string[] ReadStrings(BinaryReader r)
  {
    var strings = new string[ReadCount(r)];
    for (int i = 0; i < strings.Length; i++)
      strings[i] = r.ReadString();
    return strings;
  }

  static void WriteDiagnostics(BinaryWriter w, IReadOnlyList<ScriptDiagnostic> diagnostics)
  {
    w.Write(diagnostics.Count);
    foreach (ScriptDiagnostic d in diagnostics)
    {
      w.Write(d.Path);
      w.Write(d.Line);
      w.Write(d.Column);
      w.Write(d.Severity);
      w.Write(d.Id);
      w.Write(d.Message);
    }
  }

  static ScriptDiagnostic[] ReadDiagnostics(BinaryReader r)
  {
    var diagnostics = new ScriptDiagnostic[ReadCount(r)];
    for (int i = 0; i < diagnostics.Length; i++)
      diagnostics[i] = new ScriptDiagnostic(r.ReadString(), r.ReadInt32(), r.ReadInt32(), r.ReadString(), r.ReadString(), r.ReadString());
    return diagnostics;
  }

  static void WriteMap(BinaryWriter w, SourceMap map)
  {
    w.Write(map.OriginalLength);
    WriteInts(w, map.OriginalLineStarts);
    w.Write(map.InstrumentedLength);
    WriteInts(w, map.InstrumentedLineStarts);
    w.Write(map.Insertions.Length);
    foreach ((int position, int length) in map.Insertions)
    {
      w.Write(position);
      w.Write(length);
    }
  }

  static SourceMap ReadMap(BinaryReader r)
  {
    int originalLength = r.ReadInt32();
    int[] originalStarts = ReadInts(r);
    int instrumentedLength = r.ReadInt32();
    int[] instrumentedStarts = ReadInts(r);
    var insertions = new (int, int)[ReadCount(r)];
    for (int i = 0; i < insertions.Length; i++)
      insertions[i] = (r.ReadInt32(), r.ReadInt32());
    return new SourceMap(originalLength, originalStarts, instrumentedLength, instrumentedStarts, insertions);
  }

  static void WriteInts(BinaryWriter w, int[] values)
  {
    w.Write(values.Length);
    foreach (int v in values)
      w.Write(v);
  }

  static int[] ReadInts(BinaryReader r)
  {
    var values = new int[ReadCount(r)];
    for (int i = 0; i < values.Length; i++)
      values[i] = r.ReadInt32();
    return values;
  }

  /// <summary>A count that fits in what is left of the entry (a damaged one must not allocate gigabytes).</summary>
  static int ReadCount(BinaryReader r)
  {
    int n = r.ReadInt32();
    if (n < 0 || n > r.BaseStream.Length - r.BaseStream.Position)
      throw new InvalidDataException("a count beyond the entry's end");
    return n;
  }
}
