using System;
using System.Collections.Generic;

namespace Utilities;

/// <summary>
/// Estimated time of finish of a long computation (GrCis's ETF): a blend of the global rate (time so far over
/// the part finished) and a local rate measured against a progress report a few calls back, smoothed.
/// </summary>
public class ETF
{
  readonly float globalWeight;

  // Progress reports of the last calls, oldest first; the oldest becomes the point the local rate is measured from.
  readonly Queue<(float Time, float Finished)> recent = new();
  readonly bool keepsHistory;

  (float Time, float Finished) reference;
  float localTotal;

  /// <param name="global">Weight of the global estimate against the local one, 0 to 1.</param>
  /// <param name="intermediateSteps">How many calls back the local rate is measured from (0: the previous call).</param>
  public ETF(in float global = 0.4f, in int intermediateSteps = 2)
  {
    globalWeight = Math.Clamp(global, 0.0f, 1.0f);
    int steps = Math.Max(0, intermediateSteps);
    keepsHistory = steps > 0;
    for (int i = 0; i < steps; i++)
      recent.Enqueue((0.0f, 0.0f));
  }

  /// <summary>
  /// Total time the computation is estimated to take, from <paramref name="time"/> spent so far and the
  /// <paramref name="finished"/> part (0 to 1); <paramref name="etf"/> is the time still to go. Both are 0 before
  /// anything is finished or after everything is.
  /// </summary>
  public float Estimate(float time, float finished, out float etf)
  {
    if (finished <= float.Epsilon || finished >= 1.0f)
      return etf = 0.0f;

    float globalTotal = time / finished;
    if (localTotal == 0.0f)
      localTotal = globalTotal;
    if (finished > reference.Finished)
      localTotal = 0.5f * (localTotal + (time - reference.Time) / (finished - reference.Finished));

    if (keepsHistory)
    {
      reference = recent.Dequeue();
      recent.Enqueue((time, finished));
    }
    else
      reference = (time, finished);

    float total = globalTotal * globalWeight + localTotal * (1.0f - globalWeight);
    etf = (1.0f - finished) * total;
    return total;
  }
}
