using System.Collections.Generic;

namespace Rendering.Accel;

/// <summary>
/// What <see cref="WhittedKernel"/> reads of one scene, taken once per frame and worker: the library's own scene
/// classes (<see cref="LibraryTypes.IsLibraryScene"/>) keep their parts in plain properties set before the render,
/// so the camera, background and lights are read here once, each tagged with the library class the kernel calls
/// directly (<see cref="LibraryTypes"/> decides). Any other scene class is asked per ray, as
/// <see cref="RayTracing.shade"/> asks it.
/// </summary>
internal sealed class BoundScene
{
  /// <summary>The kernel (one per frame) this binding was taken for.</summary>
  public readonly WhittedKernel Kernel;

  /// <summary>The scene the worker renders (a clone per worker in an animation).</summary>
  public readonly IRayScene Scene;

  /// <summary>True for the library's scene classes: the fields below hold their parts. False: ask <see cref="Scene"/> per ray.</summary>
  public readonly bool Library;

  /// <summary>The camera, and the same object when it is exactly the library's <see cref="Rendering.StaticCamera"/>.</summary>
  public readonly ICamera? Camera;
  public readonly StaticCamera? StaticCamera;

  /// <summary>The background, and the same object when it is exactly the library's <see cref="Rendering.DefaultBackground"/>.</summary>
  public readonly IBackground? Background;
  public readonly DefaultBackground? DefaultBackground;

  /// <summary>The light sources in the scene's order, each with its direct call; null when the scene has none.</summary>
  public readonly BoundLight[]? Lights;

  /// <summary>The scene's geometry.</summary>
  public readonly IIntersectable? Intersectable;

  /// <summary>
  /// The prepared scene when the kernel's plain-surface path shades this binding's rays (set once, by the kernel, when it
  /// binds: <c>WhittedKernel.PlainSceneOf</c>); null: every ray takes the general path.
  /// </summary>
  public PreparedScene? Plain;

  public BoundScene(WhittedKernel kernel, IRayScene scene)
  {
    Kernel = kernel;
    Scene = scene;
    Library = LibraryTypes.IsLibraryScene(scene);
    if (!Library)
      return;
    Camera = scene.Camera;
    StaticCamera = LibraryTypes.DirectCamera(Camera);
    Background = scene.Background;
    DefaultBackground = LibraryTypes.DirectBackground(Background);
    Intersectable = scene.Intersectable;
    if (scene.Sources is { Count: > 0 } sources)
    {
      var lights = new List<BoundLight>(sources.Count);
      foreach (ILightSource source in sources)
      {
        DirectLight kind = LibraryTypes.DirectLight(source);
        lights.Add(new BoundLight(source, kind, kind != DirectLight.None ? source.GetHashCode() : 0));
      }
      Lights = lights.ToArray();
    }
  }
}
