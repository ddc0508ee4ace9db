using OpenTK.Mathematics;

namespace Rendering;

/// <summary>A source of named animated values.</summary>
public interface ITimeDependentProperty : ITimeDependent
{
  /// <summary>Current value (at <see cref="ITimeDependent.Time"/>) of the named property, boxed; null when the name is unknown or the property has no value.</summary>
  /// <param name="name">The property's name.</param>
  object? GetValue(in string name);

  /// <summary>
  /// Sets <paramref name="value"/> to the named property's current value when there is one of a matching type; true then.
  /// False leaves <paramref name="value"/> as it was, so it may hold a default. The other overloads do the same for their types.
  /// </summary>
  /// <param name="name">The property's name.</param>
  /// <param name="value">Receives the value.</param>
  bool TryGetValue(in string name, ref float value);
  /// <inheritdoc cref="TryGetValue(in string, ref float)"/>
  bool TryGetValue(in string name, ref double value);
  /// <inheritdoc cref="TryGetValue(in string, ref float)"/>
  bool TryGetValue(in string name, ref Vector3 value);
  /// <inheritdoc cref="TryGetValue(in string, ref float)"/>
  bool TryGetValue(in string name, ref Vector4 value);
  /// <inheritdoc cref="TryGetValue(in string, ref float)"/>
  bool TryGetValue(in string name, ref Vector3d value);
  /// <inheritdoc cref="TryGetValue(in string, ref float)"/>
  bool TryGetValue(in string name, ref Vector4d value);
  /// <inheritdoc cref="TryGetValue(in string, ref float)"/>
  bool TryGetValue(in string name, ref Quaterniond value);
  /// <inheritdoc cref="TryGetValue(in string, ref float)"/>
  bool TryGetValue(in string name, ref Matrix4d value);
}
