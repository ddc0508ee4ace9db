using System;
using GrCis.Cli.Animation;

namespace GrCis.Cli.ProgressViews;

/// <summary>Shows the progress of an animation while <c>work</c> runs; <c>work</c> reports each finished frame.</summary>
public interface IAnimationProgressView
{
  T Run<T>(string title, int framesTotal, int framesSkipped, Func<Action<AnimationProgress>, T> work);
}
