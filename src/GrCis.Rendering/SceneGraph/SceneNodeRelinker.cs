using System;
using System.Collections.Generic;
using System.Reflection;

namespace Rendering;

/// <summary>
/// Shallow copies of static scene subtrees for a worker's clone: each node object is copied
/// (so its parent link can point into the clone) while everything it references (geometry,
/// attributes, textures, meshes) stays shared.
/// </summary>
internal static class SceneNodeRelinker
{
  static readonly Func<object, object> memberwiseClone = typeof(object)
    .GetMethod(nameof(MemberwiseClone), BindingFlags.Instance | BindingFlags.NonPublic)!
    .CreateDelegate<Func<object, object>>();

  static readonly Action<DefaultSceneNode, ICollection<ISceneNode>> setChildren = typeof(DefaultSceneNode)
    .GetProperty(nameof(DefaultSceneNode.Children))!
    .GetSetMethod(nonPublic: true)!
    .CreateDelegate<Action<DefaultSceneNode, ICollection<ISceneNode>>>();

  /// <summary>
  /// A copy of <paramref name="node"/>'s subtree whose inner parent links point to the copies.
  /// The caller sets the returned node's <see cref="ISceneNode.Parent"/>. Nodes that do not
  /// derive from <see cref="DefaultSceneNode"/> cannot be copied and are returned as they are.
  /// </summary>
  public static ISceneNode Relink(ISceneNode node)
  {
    if (node is not DefaultSceneNode original)
      return node;
    var copy = (DefaultSceneNode)memberwiseClone(original);
    var children = new LinkedList<ISceneNode>();
    foreach (ISceneNode child in original.Children)
    {
      ISceneNode c = child is ITimeDependent td ? (ISceneNode)td.Clone() : Relink(child);
      if (!ReferenceEquals(c, child))
        c.Parent = copy;
      children.AddLast(c);
    }
    setChildren(copy, children);
    return copy;
  }
}
