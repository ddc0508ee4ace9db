using System;
using System.Runtime.CompilerServices;
using System.Threading;

namespace Rendering.Execution;

/// <summary>
/// Makes user code stoppable. Scripts and modules are compiled with a call to <see cref="Poll"/> in every
/// loop body and before every <c>goto</c>, so a scene script or a texture stuck in <c>while (true) {}</c>
/// ends with an <see cref="OperationCanceledException"/> once the host cancels the token it set for the
/// thread (the demo's Stop, the studio, Ctrl+C). .NET cannot abort a thread; this is the cooperative
/// alternative. Code that blocks without looping (a sleep, a deadlock, a library call) is not reached.
/// </summary>
public static class Interruption
{
  /// <summary>The token user code on the calling thread obeys (its <see cref="WorkerContext"/>'s).</summary>
  public static CancellationToken Current => WorkerContext.Current.Cancel;

  /// <summary>Called by compiled user code at each loop iteration: throws once the thread's token is cancelled.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static void Poll()
  {
    if (WorkerContext.Current.Cancel.IsCancellationRequested)
      Stop();
  }

  /// <summary>User code run on the calling thread until the scope is disposed obeys <paramref name="cancel"/>.</summary>
  public static Scope Use(CancellationToken cancel)
  {
    WorkerContext c = WorkerContext.Current;
    CancellationToken previous = c.Cancel;
    c.Cancel = cancel;
    return new Scope(c, previous);
  }

  [MethodImpl(MethodImplOptions.NoInlining)]
  static void Stop() => throw new OperationCanceledException("Stopped while running user code.", WorkerContext.Current.Cancel);

  /// <summary>Restores the thread's previous token.</summary>
  public readonly struct Scope : IDisposable
  {
    readonly WorkerContext? context;
    readonly CancellationToken previous;

    internal Scope(WorkerContext context, CancellationToken previous)
    {
      this.context = context;
      this.previous = previous;
    }

    /// <summary>Gives the thread its previous token back.</summary>
    public void Dispose()
    {
      if (context != null)
        context.Cancel = previous;
    }
  }
}
