using System.Runtime.CompilerServices;

namespace Rendering.Execution;

/// <summary>
/// Ends a runaway recursion of user code with an exception instead of a stack overflow, which .NET does not let a
/// process survive (the whole <c>grcis</c> or studio would die without a word). Scripts and modules are compiled with
/// every method, local function, accessor and lambda body wrapped in <c>var d = Recursion.Enter(); try { … } finally
/// { d.RecursionDepth--; }</c>; the count lives in the thread's <see cref="WorkerContext"/>.
/// </summary>
public static class Recursion
{
  /// <summary>
  /// The most calls of user code under way on one thread. A render worker's stack (<see cref="TileRenderer.WorkerStackSize"/>)
  /// holds several times as many simple frames; deeper recursion in a student's scene is a bug.
  /// </summary>
  public const int MaxDepth = 10_000;

  // How often (in calls) the remaining stack is checked too: frames of library code between the user's, a big frame
  // or a thread with a small stack (the thread pool's) may fill the stack before MaxDepth.
  const int StackCheckMask = 15;

  /// <summary>Called on entry to every user method: counts the call and throws when the recursion is too deep.</summary>
  [MethodImpl(MethodImplOptions.AggressiveInlining)]
  public static WorkerContext Enter()
  {
    WorkerContext c = WorkerContext.Current;
    int d = ++c.RecursionDepth;
    if ((d & StackCheckMask) == 0)
      Check(c, d);
    return c;
  }

  /// <summary>
  /// Called on entry to every user iterator and async body, which <see cref="Enter"/> does not count (their pieces run
  /// apart, possibly on other threads, so a count would be wrong): throws while some stack is left when it is nearly
  /// full, as a recursion through iterators or async methods that never wait fills it.
  /// </summary>
  /// <exception cref="RecursionTooDeepException">The thread's stack is nearly full.</exception>
  public static void CheckStack()
  {
    if (!RuntimeHelpers.TryEnsureSufficientExecutionStack())
      throw new RecursionTooDeepException("recursion through iterators or async methods fills the thread's stack (is there a case that ends it?)");
  }

  [MethodImpl(MethodImplOptions.NoInlining)]
  static void Check(WorkerContext c, int depth)
  {
    if (depth > MaxDepth)
    {
      // This call's try is never entered, so its finally never runs: uncount it here.
      c.RecursionDepth--;
      throw new RecursionTooDeepException($"recursion deeper than {MaxDepth} calls (is there a case that ends it?)");
    }
    if (!RuntimeHelpers.TryEnsureSufficientExecutionStack())
    {
      c.RecursionDepth--;
      throw new RecursionTooDeepException($"recursion deeper than {depth - 1} calls fills the thread's stack (is there a case that ends it?)");
    }
  }
}
