using OpenTK.Mathematics;

namespace Rendering;

/// <summary>A source of named animated values.</summary>
public interface ITimeDependentProperty : ITimeDependent
{
  object? GetValue(in string name);

  bool TryGetValue(in string name, ref float value);
  bool TryGetValue(in string name, ref double value);
  bool TryGetValue(in string name, ref Vector3 value);
  bool TryGetValue(in string name, ref Vector4 value);
  bool TryGetValue(in string name, ref Vector3d value);
  bool TryGetValue(in string name, ref Vector4d value);
  bool TryGetValue(in string name, ref Quaterniond value);
  bool TryGetValue(in string name, ref Matrix4d value);
}
