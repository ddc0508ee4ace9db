namespace GrCis.Cli;

/// <summary>Process exit codes of <c>grcis</c>.</summary>
public static class ExitCodes
{
  public const int Success = 0;

  /// <summary>The command was valid but failed while running (scene error, output not writable).</summary>
  public const int Failure = 1;

  /// <summary>The command line was wrong (unknown option or scene, malformed value).</summary>
  public const int Usage = 2;

  /// <summary>Interrupted by Ctrl+C (128 + SIGINT, as shells report it).</summary>
  public const int Cancelled = 130;
}
