namespace GrCis.Studio;

/// <summary>An animation run as the page shows it (<c>GET /api/animation</c>, the <c>animation</c> event).</summary>
/// <param name="Running">True until the last frame is done, the run stopped, or a frame failed.</param>
/// <param name="FramesDone">Finished frames, each served as <c>/api/animation/frame/{k}.png</c> (0-based).</param>
/// <param name="EtaSeconds">Estimated time to the last frame.</param>
/// <param name="Error">Why the run ended early, or null.</param>
/// <param name="Folder">Where the frames are written, or null (kept in memory).</param>
/// <param name="Fps">The run's frames per second: the rate the page plays the finished frames at.</param>
public sealed record AnimationStatus(bool Running, int FramesDone, int FramesTotal, double Seconds, double EtaSeconds, string? Error, string? Folder,
                                     double Fps);
