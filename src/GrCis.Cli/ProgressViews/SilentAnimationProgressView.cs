using System;
using GrCis.Cli.Animation;

namespace GrCis.Cli.ProgressViews;

/// <summary>No progress output (<c>--quiet</c>).</summary>
public sealed class SilentAnimationProgressView : IAnimationProgressView
{
  public T Run<T>(string title, int framesTotal, int framesSkipped, Func<Action<AnimationProgress>, T> work) => work(_ => { });
}
