namespace Rendering;

/// <summary>Modifies a completed intersection (usually its SurfaceColor); textures apply in order.</summary>
public interface ITexture
{
  /// <summary>Applies the texture; returns a hash of what it chose (for adaptive sampling).</summary>
  long Apply(Intersection inter);
}
