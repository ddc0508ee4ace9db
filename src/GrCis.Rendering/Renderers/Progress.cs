namespace MathSupport;

/// <summary>Shared progress record (GrCis's, in its namespace): the renderer advances it, a UI reads it and may ask to stop.</summary>
public class Progress
{
  /// <summary>Completed fraction in [0, 1].</summary>
  public float Finished { get; set; }

  /// <summary>Any message for the user.</summary>
  public string Message { get; set; } = "";

  /// <summary>Set to false by the caller to ask the renderer to stop.</summary>
  public bool Continue { get; set; } = true;

  /// <summary>Minimal interval between Sync calls in milliseconds.</summary>
  public long SyncInterval { get; set; } = 8000L;

  /// <summary>Called by renderers at safe points; subclasses may show progress.</summary>
  public virtual void Sync(object? msg) { }
}
