using Rendering.Imaging;

namespace Rendering.Accel;

/// <summary>
/// What a front end (the command line, the demo, the studio) may do with the objects a scene script hands it,
/// answered by the library's one place for such decisions (<see cref="LibraryTypes"/>): whether a script's image
/// function may be copied per animation frame, whether a renderer may take its samples in progressive passes,
/// whether it renders rectangles its own way.
/// </summary>
public static class FrontEndRules
{
  /// <summary>
  /// Exactly the library's <see cref="RayTracing"/> or <see cref="RayCasting"/>: a new one with
  /// <see cref="RayCasting.CopySettingsFrom"/> is the same function (a subclass may hold settings of its own).
  /// </summary>
  public static bool IsCopyableRayCaster(IImageFunction function) => LibraryTypes.IsCopyableRayCaster(function);

  /// <summary>An object of a class declared in this library, not in a script or a module (whose objects may hold anything).</summary>
  public static bool IsLibraryClass(object o) => LibraryTypes.IsLibraryClass(o);

  /// <summary>
  /// Exactly the library's n×n grid with more than one sample: its samples may be taken in passes over the image that
  /// together give the image of one pass.
  /// </summary>
  public static bool TakesSamplesInPasses(ImageSynthesizer renderer) => LibraryTypes.TakesSamplesInPasses(renderer);

  /// <summary>A renderer class overriding <see cref="ImageSynthesizer.RenderRectangle"/>: it renders its rectangles its own way.</summary>
  public static bool RendersOwnRectangles(System.Type synthesizer) => LibraryTypes.RendersOwnRectangles(synthesizer);
}
