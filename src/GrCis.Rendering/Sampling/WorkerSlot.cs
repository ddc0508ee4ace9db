using System;

namespace Rendering.Execution;

/// <summary>
/// A key to one kind of per-worker state in <see cref="WorkerContext"/>: the component that owns the state keeps the key
/// (a static field), so the context holds every component's state without knowing its type. The state is made on a
/// worker's first <see cref="WorkerContext.Get{T}"/> by the key's factory and lives as long as the worker's context.
/// </summary>
internal sealed class WorkerSlot<T> where T : class
{
  /// <summary>A new key; <paramref name="create"/> makes a worker's state on its first use (null: none until set).</summary>
  public WorkerSlot(Func<T>? create = null)
  {
    Create = create;
    Index = WorkerContext.NewSlot();
  }

  /// <summary>The key's place in every context's slots.</summary>
  public int Index { get; }

  /// <summary>Makes a worker's state, or null.</summary>
  public Func<T>? Create { get; }
}
