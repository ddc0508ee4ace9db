namespace Rendering.Accel;

/// <summary>
/// A light source of a <see cref="BoundScene"/>, the library class the kernel calls directly for it, and for such a
/// class its <see cref="object.GetHashCode"/> (the library's lights keep object's, which never changes), taken once
/// instead of per hit.
/// </summary>
internal readonly record struct BoundLight(ILightSource Source, DirectLight Kind, int Hash);
