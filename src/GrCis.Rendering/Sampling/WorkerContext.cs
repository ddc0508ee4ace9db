using System;
using System.Runtime.CompilerServices;
using System.Threading;
using MathSupport;

namespace Rendering.Execution;

/// <summary>
/// What every render worker works with, in one object: its <see cref="Sampler"/> (which also holds the current pixel
/// and sample), its random generator, the current sample's image position and time, the cancellation its user code
/// obeys, the script folder data files are looked up in, and a slot per component that keeps state of its own per
/// worker (the shading scratch, the path tracer's lights, a mesh's crossings …: each component owns its
/// <see cref="WorkerSlot{T}"/>, the context knows none of their types). Built by <c>WorkerContext.Begin</c> (see
/// <see cref="WorkerRendering"/>) for every kind of worker. GrCis's API has no context parameter, so a thread finds its
/// context in the one thread static, <see cref="Current"/>; GrCis's <see cref="MT"/> statics read and write it. A thread
/// that never began one (the main thread, a student's own) gets a default context of its own on first use.
/// </summary>
public sealed class WorkerContext
{
  [ThreadStatic] static WorkerContext? current;

  static int slotCount;

  /// <summary>The calling thread's context.</summary>
  public static WorkerContext Current
  {
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    get => current ?? CreateDefault();
  }

  [MethodImpl(MethodImplOptions.NoInlining)]
  static WorkerContext CreateDefault() => current = new WorkerContext(new CorrelatedMultiJitterSampler());

  internal WorkerContext(Sampler sampler) => Sampler = sampler;

  /// <summary>The worker's sample generator and current pixel sample.</summary>
  public Sampler Sampler { get; }

  /// <summary>Index of the worker among its render's threads (<c>MT.threadID</c>).</summary>
  public int ThreadID { get; internal set; }

  /// <summary>The cancellation user code on this worker obeys (<c>Interruption</c>).</summary>
  public CancellationToken Cancellation => Cancel;

  // GrCis's per-thread values behind MT (fields: MT's properties are on hot paths).
  internal RandomJames? Rnd;
  internal double DoubleX, DoubleY, Time;
  internal ulong PixelHash;

  internal CancellationToken Cancel;

  /// <summary>
  /// How many calls of user code are under way on this thread. The recursion guards compiled into user code count
  /// them (<see cref="Recursion.Enter"/> up, the guard's <c>finally</c> down, inline: a field, not a call, as user
  /// code is not optimised); nothing else writes it.
  /// </summary>
  [System.ComponentModel.EditorBrowsable(System.ComponentModel.EditorBrowsableState.Never)]
  public int RecursionDepth;

  /// <summary>Folder of the script whose code runs here (<see cref="Utilities.DataFiles"/>).</summary>
  internal string? ScriptDirectory;

  /// <summary>Where <see cref="Utilities.DataFiles"/> notes the files it found on this thread (null: nowhere).</summary>
  internal System.Collections.Generic.ICollection<string>? DataFileLog;

  // The components' per-worker state, by their keys' indices.
  object?[] slots = new object?[8];

  /// <summary>A new key index (<see cref="WorkerSlot{T}"/>).</summary>
  internal static int NewSlot() => Interlocked.Increment(ref slotCount) - 1;

  /// <summary>This worker's state of <paramref name="key"/>, made by the key's factory on first use (null when it has none and nothing was set).</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  internal T Get<T>(WorkerSlot<T> key) where T : class
  {
    object?[] s = slots;
    int i = key.Index;
    if ((uint)i < (uint)s.Length && s[i] is object o)
      return Unsafe.As<T>(o);
    return Make(key);
  }

  /// <summary>This worker's state of <paramref name="key"/>, or null (nothing made).</summary>
  internal T? Peek<T>(WorkerSlot<T> key) where T : class
  {
    object?[] s = slots;
    int i = key.Index;
    return (uint)i < (uint)s.Length ? Unsafe.As<T?>(s[i]) : null;
  }

  /// <summary>Sets this worker's state of <paramref name="key"/>.</summary>
  internal void Set<T>(WorkerSlot<T> key, T? value) where T : class
  {
    if (key.Index >= slots.Length)
      Array.Resize(ref slots, Math.Max(key.Index + 1, 2 * slots.Length));
    slots[key.Index] = value;
  }

  [MethodImpl(MethodImplOptions.NoInlining)]
  T Make<T>(WorkerSlot<T> key) where T : class
  {
    T value = key.Create?.Invoke() ?? throw new InvalidOperationException("The worker has no " + typeof(T).Name + ".");
    Set(key, value);
    return value;
  }

  /// <summary>Makes <paramref name="worker"/> the calling thread's context; returns the previous one.</summary>
  internal static WorkerContext Enter(WorkerContext worker)
  {
    WorkerContext previous = Current;
    current = worker;
    return previous;
  }

  /// <summary>Makes <paramref name="previous"/> the calling thread's context again.</summary>
  internal static void Leave(WorkerContext previous) => current = previous;

  /// <summary>A worker's time: on disposal its owner's ending runs (its counts go to the render) and the thread's previous context is back.</summary>
  public readonly struct Scope : IDisposable
  {
    readonly WorkerContext? previous, worker;
    readonly Action<WorkerContext, WorkerContext>? end;

    internal Scope(WorkerContext previous, WorkerContext worker, Action<WorkerContext, WorkerContext>? end)
    {
      this.previous = previous;
      this.worker = worker;
      this.end = end;
    }

    /// <summary>The worker's context.</summary>
    public WorkerContext? Context => worker;

    /// <summary>Ends the worker (its ray and hit counts go to its render and to the thread's previous context) and makes that context current again.</summary>
    public void Dispose()
    {
      if (worker == null || previous == null)
        return;
      end?.Invoke(previous, worker);
      current = previous;
    }
  }
}
