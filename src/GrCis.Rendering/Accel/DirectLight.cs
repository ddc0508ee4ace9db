namespace Rendering.Accel;

/// <summary>The library light a kernel calls by name rather than through <see cref="ILightSource"/> (<see cref="LibraryTypes.DirectLight"/>).</summary>
internal enum DirectLight : byte
{
  /// <summary>Any other light, called through its interface.</summary>
  None,

  /// <summary>Exactly the library's <see cref="PointLightSource"/>.</summary>
  Point,

  /// <summary>Exactly the library's <see cref="AmbientLightSource"/>.</summary>
  Ambient,
}
