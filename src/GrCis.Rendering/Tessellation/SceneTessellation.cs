using System.Collections.Generic;

namespace Rendering.Tessellation;

/// <summary>A scene as triangles, lights and a camera: what <see cref="SceneTessellator.Tessellate"/> makes of an <see cref="IRayScene"/>.</summary>
public sealed class SceneTessellation
{
  /// <summary>One part per solid reached in the scene graph, in the order of the graph (depth first).</summary>
  public required IReadOnlyList<TessellatedPart> Parts { get; init; }

  /// <summary>The lights with a position (ambient lights have none and are left out).</summary>
  public required IReadOnlyList<TessellatedLight> Lights { get; init; }

  /// <summary>The camera, or null when the scene has none.</summary>
  public TessellatedCamera? Camera { get; init; }

  /// <summary>What could not be shown as it is (a script's solid as its box, an ambient light, a node without geometry).</summary>
  public required IReadOnlyList<string> Notes { get; init; }
}
