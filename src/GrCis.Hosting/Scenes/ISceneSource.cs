using Rendering;

namespace GrCis.Hosting;

/// <summary>A scene a front end can render: a built-in scene (<see cref="BuiltInSceneSource"/>) or a scene script (<see cref="ScriptSceneSource"/>).</summary>
public interface ISceneSource
{
  /// <summary>Name shown to the user ("Sphere on the plane", "TwoSpheres.cs").</summary>
  string DisplayName { get; }

  /// <summary>File name stem of the default output file ("sphere-on-the-plane").</summary>
  string OutputStem { get; }

  /// <summary>Builds a fresh scene.</summary>
  IRayScene CreateScene();
}
