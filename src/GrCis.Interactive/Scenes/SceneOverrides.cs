namespace GrCis.Interactive;

/// <summary>
/// What a scene script asked for through its context (GrCis's CTX_* keys): image size, supersampling,
/// algorithm and animation range. Null means "not set by the script"; the demo shows these back to the user.
/// </summary>
public sealed record SceneOverrides
{
  public int? Width { get; init; }
  public int? Height { get; init; }
  public int? Supersampling { get; init; }

  /// <summary>Class name of the image function the script chose (CTX_ALGORITHM), e.g. "PathTracing".</summary>
  public string? Algorithm { get; init; }

  /// <summary>Animation range and frame rate (CTX_START_ANIM, CTX_END_ANIM, CTX_FPS).</summary>
  public double? Start { get; init; }
  public double? End { get; init; }
  public double? Fps { get; init; }

  public bool IsEmpty => Width == null && Height == null && Supersampling == null && Algorithm == null && Start == null && End == null && Fps == null;

  /// <summary>Short text for a status line, e.g. "640x480, ss 4, t 0–10 @ 25 fps".</summary>
  public override string ToString()
  {
    var parts = new System.Collections.Generic.List<string>();
    if (Width != null || Height != null)
      parts.Add($"{Width?.ToString() ?? "?"}x{Height?.ToString() ?? "?"}");
    if (Supersampling != null)
      parts.Add($"ss {Supersampling}");
    if (Algorithm != null)
      parts.Add(Algorithm);
    if (Start != null || End != null)
      parts.Add(System.FormattableString.Invariant($"t {Start ?? 0}–{End ?? 0}"));
    if (Fps != null)
      parts.Add(System.FormattableString.Invariant($"{Fps} fps"));
    return string.Join(", ", parts);
  }
}
