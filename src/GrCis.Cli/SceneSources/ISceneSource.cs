using Rendering;

namespace GrCis.Cli.SceneSources;

/// <summary>Something <c>grcis render</c> can render: a built-in scene now, a scene script later.</summary>
public interface ISceneSource
{
  /// <summary>Name shown to the user ("Sphere on the plane", "TwoSpheres.cs").</summary>
  string DisplayName { get; }

  /// <summary>File name stem of the default output file ("sphere-on-the-plane").</summary>
  string OutputStem { get; }

  /// <summary>Builds a fresh scene.</summary>
  IRayScene CreateScene();
}
