using System;

namespace Rendering;

/// <summary>Anything animated. Each render thread gets its own <see cref="ICloneable.Clone"/> ("clone on write").</summary>
public interface ITimeDependent : ICloneable
{
  /// <summary>Start of the animation's time range, in seconds.</summary>
  double Start { get; set; }

  /// <summary>End of the animation's time range, in seconds.</summary>
  double End { get; set; }

  /// <summary>Current time; setting it moves the object (and its time-dependent parts).</summary>
  double Time { get; set; }
}
