using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;

namespace GrCis.StaticPgo;

/// <summary>
/// Reads the profile the runtime writes at exit with <c>DOTNET_WritePGOData=1</c> and <c>DOTNET_PGODataPath</c>:
/// per method a header line (<c>@@@ codehash … ilSize 0x… records 0x…</c>), its name and signature, then each schema
/// record (<c>Schema InstrumentationKind K ILOffset O Count C Other X</c>) followed by its C values, one a line: a
/// number, two 32-bit halves (low first) for an eight-byte value, or <c>TypeHandle: name</c> / <c>MethodHandle: name</c>.
/// </summary>
internal static class PgoTextDump
{
  public static List<ProfiledMethod> Read(string path)
  {
    using var reader = new StreamReader(path);
    return Read(reader, path);
  }

  public static List<ProfiledMethod> Read(TextReader reader, string source)
  {
    var methods = new List<ProfiledMethod>();
    int lineNumber = 0;
    string Next()
    {
      string next = reader.ReadLine() ?? throw Bad("the file ends inside a method's records");
      lineNumber++;
      return next;
    }
    FormatException Bad(string what) => new($"{source}:{lineNumber}: {what}");

    string? line;
    while ((line = reader.ReadLine()) != null)
    {
      lineNumber++;
      if (!line.StartsWith("@@@ ", StringComparison.Ordinal)) continue;
      string[] header = line.Split(' ', StringSplitOptions.RemoveEmptyEntries);
      int ilSize = Hex(Field(header, "ilSize"));
      int records = Hex(Field(header, "records"));
      string name = After(Next(), "MethodName: ");
      string signature = After(Next(), "Signature: ");
      var schema = new List<SchemaEntry>(records);
      for (int r = 0; r < records; r++)
      {
        string[] s = Next().Split(' ', StringSplitOptions.RemoveEmptyEntries);
        if (s.Length != 9 || s[0] != "Schema") throw Bad("expected a Schema record");
        int kind = Number(s[2]), count = Number(s[6]);
        var values = new long[count];
        var handles = new string[count];
        int marshal = kind & 0xF;
        for (int v = 0; v < count; v++)
        {
          string value = Next();
          switch (marshal)
          {
            case SchemaEntry.FourByte: values[v] = UInt(value); break;
            case SchemaEntry.EightByte:
              {
                string[] halves = value.Split(' ');
                if (halves.Length != 2) throw Bad("expected two 32-bit halves");
                values[v] = UInt(halves[1]) << 32 | UInt(halves[0]);
                break;
              }
            case SchemaEntry.TypeHandle: handles[v] = After(value, "TypeHandle: "); break;
            case SchemaEntry.MethodHandle: handles[v] = After(value, "MethodHandle: "); break;
          }
        }
        schema.Add(new SchemaEntry
        {
          Kind = kind, IlOffset = Number(s[4]), Count = count, Other = Number(s[8]), Values = values, Handles = handles,
        });
      }
      methods.Add(new ProfiledMethod { Name = name, Signature = signature, IlSize = ilSize, Schema = schema });
    }
    return methods;

    string Field(string[] parts, string key)
    {
      int i = Array.IndexOf(parts, key);
      return i >= 0 && i + 1 < parts.Length ? parts[i + 1] : throw Bad($"the method header has no {key}");
    }
    int Hex(string text) =>
      text.StartsWith("0x", StringComparison.Ordinal)
      && int.TryParse(text.AsSpan(2), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out int n)
        ? n : throw Bad($"'{text}' is not a hexadecimal number");
    // The runtime prints unsigned 32-bit numbers; the schema keeps them as 32-bit ints (a flag in the top bit).
    int Number(string text) => unchecked((int)UInt(text));
    long UInt(string text) =>
      uint.TryParse(text, NumberStyles.None, CultureInfo.InvariantCulture, out uint n) ? n : throw Bad($"'{text}' is not a count");
    string After(string text, string prefix) =>
      text.StartsWith(prefix, StringComparison.Ordinal) ? text[prefix.Length..] : throw Bad($"expected '{prefix.Trim()}'");
  }
}
