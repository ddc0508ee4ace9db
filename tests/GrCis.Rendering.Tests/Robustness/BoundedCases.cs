using System;
using System.Collections.Generic;
using System.Threading.Tasks;

namespace Rendering.Tests.Robustness;

/// <summary>
/// Runs a reader over many damaged inputs, each on its own task with a time limit: a case must end with a
/// result or one of the expected exception types. A case that overruns fails the test at once, naming it
/// (its thread cannot be stopped, so nothing more is run after it).
/// </summary>
internal static class BoundedCases
{
  /// <summary>
  /// Generous: most cases take well under a millisecond, but a damaged header may declare an image of up to
  /// <c>Rgb8Image.MaxPixels</c>, whose decoding into memory takes seconds on a loaded machine; only a hang comes near it.
  /// </summary>
  public static readonly TimeSpan Limit = TimeSpan.FromSeconds(60);

  public static int Run(IEnumerable<(string Name, byte[] Bytes)> cases, Action<byte[]> read, Func<Exception, bool> expected)
  {
    var wrong = new List<string>();
    int count = 0;
    foreach ((string name, byte[] bytes) in cases)
    {
      count++;
      Task<Exception?> task = Task.Run(() =>
      {
        try
        {
          read(bytes);
          return null;
        }
        catch (Exception e)
        {
          return e;
        }
      });
      if (!task.Wait(Limit))
        Assert.Fail($"{name}: still reading after {Limit.TotalSeconds} s (a hang)");
      if (task.Result is { } e && !expected(e))
        wrong.Add($"{name}: {e.GetType().Name}: {e.Message}");
    }
    Assert.True(wrong.Count == 0, $"{wrong.Count} of {count} cases threw an unexpected exception:\n" + string.Join("\n", wrong.GetRange(0, Math.Min(20, wrong.Count))));
    return count;
  }
}
