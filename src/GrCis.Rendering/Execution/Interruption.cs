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
  [ThreadStatic]
  static CancellationToken token;

  /// <summary>The token user code on the calling thread obeys.</summary>
  public static CancellationToken Current => token;

  /// <summary>Called by compiled user code at each loop iteration: throws once the thread's token is cancelled.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static void Poll()
  {
    if (token.IsCancellationRequested)
      Stop();
  }

  /// <summary>User code run on the calling thread until the scope is disposed obeys <paramref name="cancel"/>.</summary>
  public static Scope Use(CancellationToken cancel)
  {
    CancellationToken previous = token;
    token = cancel;
    return new Scope(previous);
  }

  [MethodImpl(MethodImplOptions.NoInlining)]
  static void Stop() => throw new OperationCanceledException("Stopped while running user code.", token);

  /// <summary>Restores the thread's previous token.</summary>
  public readonly struct Scope : IDisposable
  {
    readonly CancellationToken previous;

    internal Scope(CancellationToken previous) => this.previous = previous;

    public void Dispose() => token = previous;
  }
}
