using System;
using System.Threading.Tasks;

namespace GrCis.Studio.Tests;

/// <summary>The studio's state as a test's failure message tells it, so a render that never ends says where it stands.</summary>
internal static class StudioState
{
  /// <summary>
  /// The session's status and the controller's state in one line; read on a thread of its own and waited for at most
  /// 10 s, so a studio whose locks are held for good (a deadlock) says so instead of hanging the message too.
  /// </summary>
  public static string Describe(StudioSession session)
  {
    Task<string> read = Task.Run(() =>
    {
      StudioStatus s = session.Status();
      GrCis.Interactive.DemoController c = session.Controller;
      return $"the studio: phase {s.Phase}, rendering {s.Rendering}, render {s.RenderId} (last completed {s.CompletedRenderId}, " +
             $"{s.Completions} completions, cancelled {s.Cancelled}), error {s.Error ?? "none"}, image version {s.Version}, " +
             $"fraction {s.Fraction:0.###}, samples {s.Samples?.ToString() ?? "-"}; controller building {c.IsBuilding}, " +
             $"session running {c.IsRendering}; {session.EventStreams} event streams";
    });
    return read.Wait(TimeSpan.FromSeconds(10))
      ? read.Result
      : "the studio's status did not answer within 10 s: a lock of the session or the controller is held for good (a deadlock?)";
  }
}
