using System;

namespace Rendering;

/// <summary>Surface material: colour, transparency and index of refraction.</summary>
public interface IMaterial : ICloneable
{
  double[] Color { get; set; }

  /// <summary>Transparency coefficient.</summary>
  double Kt { get; set; }

  /// <summary>Relative index of refraction.</summary>
  double n { get; set; }
}
