using System;
using System.Threading;

namespace GrCis.Hosting;

/// <summary>Raising a front end's events where it wants them: on its UI context when it set one, else on the calling thread.</summary>
public static class EventContextExtensions
{
  /// <summary>Calls <paramref name="handler"/> (if any) directly when <paramref name="context"/> is null, else posts it there.</summary>
  public static void Raise<T>(this SynchronizationContext? context, EventHandler<T>? handler, object sender, T args)
  {
    if (handler == null)
      return;
    if (context == null)
      handler(sender, args);
    else
      context.Post(_ => handler(sender, args), null);
  }
}
