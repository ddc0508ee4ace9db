using System.Collections.Generic;
using Rendering.Tessellation;

namespace GrCis.Studio;

/// <summary>
/// The 3D view's parts (<see cref="SceneView3d.SceneJson.Parts"/>, the same indices and names) by the scene node each was
/// tessellated from: which part a probed ray or a hit point hit. A hit names the leaf whose surface it is (a CSG
/// operand, not the CSG node), the node the tessellator recorded for that leaf's part.
/// </summary>
internal sealed class SceneParts
{
  readonly Dictionary<object, int> index = new(ReferenceEqualityComparer.Instance);
  readonly List<string> names = new();

  public SceneParts(SceneTessellation scene)
  {
    foreach (TessellatedPart part in SceneView3d.Shown(scene))
    {
      index.TryAdd(part.Node, names.Count);
      names.Add(part.Name);
    }
  }

  /// <summary>The index of the part made from <paramref name="solid"/>, or null (a miss, or a solid the view does not show).</summary>
  public int? IndexOf(object? solid) => solid != null && index.TryGetValue(solid, out int i) ? i : null;

  /// <summary>The name of part <paramref name="i"/>, e.g. <c>Sphere 2</c>.</summary>
  public string NameOf(int i) => names[i];
}
