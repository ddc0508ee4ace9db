using Rendering.Execution;

namespace Rendering;

/// <summary>The scene a worker renders (<c>MT.scene</c>): its slot in the worker's context.</summary>
internal static class WorkerScene
{
  static readonly WorkerSlot<IRayScene> slot = new();

  /// <summary>The scene <paramref name="context"/>'s worker renders, or null.</summary>
  public static IRayScene? Of(WorkerContext context) => context.Peek(slot);

  /// <summary>Sets the scene <paramref name="context"/>'s worker renders.</summary>
  public static void Set(WorkerContext context, IRayScene? scene) => context.Set(slot, scene);
}
