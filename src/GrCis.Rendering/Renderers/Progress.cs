namespace Rendering;

/// <summary>Shared progress record: the renderer advances it, a UI reads it and may ask to stop.</summary>
public class Progress
{
  /// <summary>Completed fraction in [0, 1].</summary>
  public float Finished;

  /// <summary>Set by the caller to ask the renderer to stop.</summary>
  public bool Continue = true;

  /// <summary>Minimal interval between Sync calls in milliseconds.</summary>
  public long SyncInterval = 8000L;

  public string? Message;

  /// <summary>Called by renderers at safe points; subclasses may show progress.</summary>
  public virtual void Sync(object? msg) { }
}
