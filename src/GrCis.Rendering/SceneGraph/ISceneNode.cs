using System.Collections.Generic;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>A node of the scene hierarchy with a transform to its parent and inherited attributes.</summary>
public interface ISceneNode : IIntersectable
{
  /// <summary>The node this one hangs under, or null for the root of the scene graph.</summary>
  ISceneNode? Parent { get; set; }

  /// <summary>Local → parent transform (row vectors: <c>v * ToParent</c>).</summary>
  Matrix4d ToParent { get; set; }

  /// <summary>Parent → local transform, kept as the inverse of <see cref="ToParent"/>.</summary>
  Matrix4d FromParent { get; set; }

  /// <summary>The child nodes; a child's <see cref="ToParent"/> places it in this node's space.</summary>
  ICollection<ISceneNode> Children { get; }

  /// <summary>
  /// Marks this node as an object root: its local space is the object space of the nodes below it
  /// (<see cref="ToObject"/>, object-space texture coordinates). A flag in every GrCis year.
  /// </summary>
  bool ObjectRoot { get; set; }

  /// <summary>Attribute value, looking up the parents when this node has none.</summary>
  object? GetAttribute(string name);

  /// <summary>Attribute value set on this very node, or null; the parents are not asked.</summary>
  /// <param name="name">Attribute name, usually a <see cref="PropertyName"/> constant.</param>
  object? GetLocalAttribute(string name);

  /// <summary>Sets an attribute of this node; it is inherited by every node below that has none of its own.</summary>
  /// <param name="name">Attribute name, usually a <see cref="PropertyName"/> constant (<see cref="PropertyName.COLOR"/>, <see cref="PropertyName.MATERIAL"/> …).</param>
  /// <param name="value">The value: a <c>double[]</c> colour, an <see cref="IMaterial"/>, an <see cref="ITexture"/> …</param>
  void SetAttribute(string name, object? value);

  /// <summary>Local → world transform.</summary>
  Matrix4d ToWorld();

  /// <summary>Local → object transform: up to the nearest node marked <see cref="ObjectRoot"/> (this one: identity), or the root.</summary>
  Matrix4d ToObject();

  /// <summary>All textures that apply to this node, the outermost parent's first.</summary>
  LinkedList<ITexture>? GetTextures();
}
