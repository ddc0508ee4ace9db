namespace GrCis.Scripting;

/// <summary>One compiler message about a script or module source file (1-based line and column).</summary>
public sealed class ScriptDiagnostic
{
  /// <summary>Id of the error given for a script with no code at all.</summary>
  public const string EmptyScriptId = "GRCIS002";

  /// <summary>Id of the error given for a file that is not text (a NUL byte).</summary>
  public const string BinaryScriptId = "GRCIS003";

  /// <summary>Id of the message about a <c>using</c> of a namespace that does not exist here (GrCis-era APIs).</summary>
  public const string MissingNamespaceId = "GRCIS004";

  /// <summary>Id of the warning about an override whose access is GrCis's of another year (see docs/compatibility.md).</summary>
  public const string OverrideAccessId = "GRCIS005";

  /// <summary>Id of the warning about a module type that has the full name of a library type (the module's wins).</summary>
  public const string ShadowedLibraryTypeId = "GRCIS007";

  /// <summary>Id of the error about a module's <c>partial</c> class that would add to a library class.</summary>
  public const string PartialLibraryTypeId = "GRCIS008";

  public ScriptDiagnostic(string path, int line, int column, string severity, string id, string message)
  {
    Path = path;
    Line = line;
    Column = column;
    Severity = severity;
    Id = id;
    Message = message;
  }

  /// <summary>Source file the message is about.</summary>
  public string Path { get; }

  /// <summary>1-based line in the user's file.</summary>
  public int Line { get; }

  /// <summary>1-based column.</summary>
  public int Column { get; }

  /// <summary>"error" or "warning".</summary>
  public string Severity { get; }

  /// <summary>Compiler id such as CS0103.</summary>
  public string Id { get; }

  public string Message { get; }

  public bool IsError => Severity == "error";

  /// <summary>The MSBuild-style form <c>path(line,col): error CSxxxx: message</c>.</summary>
  public override string ToString() => $"{Path}({Line},{Column}): {Severity} {Id}: {Message}";
}
