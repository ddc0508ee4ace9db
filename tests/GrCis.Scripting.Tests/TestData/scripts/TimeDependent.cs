// Animated scenes pass their time range through ITimeDependent.
if (scene is ITimeDependent animated)
{
  animated.Start = 1.0;
  animated.End = 9.0;
  context["animated"] = true;
}
else
  context["animated"] = false;
