using System.Collections.Generic;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>A node of the scene hierarchy with a transform to its parent and inherited attributes.</summary>
public interface ISceneNode : IIntersectable
{
  ISceneNode? Parent { get; set; }

  /// <summary>Local → parent transform (row vectors: <c>v * ToParent</c>).</summary>
  Matrix4d ToParent { get; set; }

  /// <summary>Parent → local transform, kept as the inverse of <see cref="ToParent"/>.</summary>
  Matrix4d FromParent { get; set; }

  ICollection<ISceneNode> Children { get; }

  /// <summary>
  /// Marks this node as an object root: its local space is the object space of the nodes below it
  /// (<see cref="ToObject"/>, object-space texture coordinates). A flag in every GrCis year.
  /// </summary>
  bool ObjectRoot { get; set; }

  /// <summary>Attribute value, looking up the parents when this node has none.</summary>
  object? GetAttribute(string name);

  object? GetLocalAttribute(string name);

  void SetAttribute(string name, object? value);

  /// <summary>Local → world transform.</summary>
  Matrix4d ToWorld();

  /// <summary>Local → object transform: up to the nearest node marked <see cref="ObjectRoot"/> (this one: identity), or the root.</summary>
  Matrix4d ToObject();

  /// <summary>All textures that apply to this node, the outermost parent's first.</summary>
  LinkedList<ITexture>? GetTextures();
}
