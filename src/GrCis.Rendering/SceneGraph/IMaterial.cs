using System;

namespace Rendering;

/// <summary>Surface material: colour, transparency and index of refraction.</summary>
public interface IMaterial : ICloneable
{
  /// <summary>Surface colour, one value per band (usually RGB in [0, 1]); a solid's <see cref="PropertyName.COLOR"/> attribute wins over it.</summary>
  double[] Color { get; set; }

  /// <summary>Transparency coefficient.</summary>
  double Kt { get; set; }

  /// <summary>Relative index of refraction.</summary>
  double n { get; set; }
}
