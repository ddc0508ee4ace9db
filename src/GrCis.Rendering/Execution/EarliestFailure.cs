using System;
using System.Threading;

namespace Rendering.Execution;

/// <summary>
/// The failure of the earliest work item (tile, frame) among those that failed on any thread. Items are
/// handed out in order and in-flight ones run to the end, so the answer does not depend on the threads.
/// </summary>
public sealed class EarliestFailure
{
  readonly object sync = new();
  Exception? failure;
  int index = int.MaxValue;

  /// <summary>The earliest failure so far (null: none); workers check it to stop taking new items.</summary>
  public Exception? Exception => Volatile.Read(ref failure);

  /// <summary>Item <paramref name="item"/> failed with <paramref name="e"/>; kept when no earlier item failed.</summary>
  public void Report(int item, Exception e)
  {
    lock (sync)
      if (item < index)
      {
        index = item;
        Volatile.Write(ref failure, e);
      }
  }
}
