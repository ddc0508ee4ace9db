namespace Rendering;

public partial class PropertyAnimator
{
  /// <summary>How a property's curve is played over time.</summary>
  public enum InterpolationStyle
  {
    /// <summary>
    /// The curve is played once over [tStart, tEnd]; before it the first value holds,
    /// after it the last.
    /// </summary>
    Once,

    /// <summary>
    /// The curve is played every <c>tPeriod</c> seconds from tStart, jumping back to its start
    /// at each period (seamless when the data is cyclic).
    /// </summary>
    Cyclic,

    /// <summary>The curve is played forwards, then backwards, each taking <c>tPeriod</c> seconds.</summary>
    Pendulum,
  }
}
