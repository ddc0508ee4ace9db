namespace GrCis.Cli.Animation;

/// <summary>The state of one frame's file and why: the damage, or the fingerprint fields that differ.</summary>
public sealed record FrameCheck(FrameState State, string Detail = "")
{
  public static readonly FrameCheck Kept = new(FrameState.Kept);
  public static readonly FrameCheck Missing = new(FrameState.Missing);
}
