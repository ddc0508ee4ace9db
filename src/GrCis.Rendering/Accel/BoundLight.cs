namespace Rendering.Accel;

/// <summary>A light source of a <see cref="BoundScene"/> and the library class the kernel calls directly for it.</summary>
internal readonly record struct BoundLight(ILightSource Source, DirectLight Kind);
