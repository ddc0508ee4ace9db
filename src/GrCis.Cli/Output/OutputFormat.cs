namespace GrCis.Cli.Output;

/// <summary>File formats <c>grcis render</c> writes.</summary>
public enum OutputFormat
{
  /// <summary>8-bit RGB PNG, gamma applied.</summary>
  Png,

  /// <summary>Linear 32-bit float Portable Float Map (no gamma).</summary>
  Pfm,

  /// <summary>One part of a scaled-out still (<c>render --tiles i/n</c>), for <c>grcis merge</c>.</summary>
  Part,
}
