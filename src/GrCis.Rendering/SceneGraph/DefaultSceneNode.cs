using System;
using System.Collections.Generic;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// Base of every scene node: transform to the parent, children, attributes inherited
/// from the parents, textures collected along the path from the root.
/// </summary>
public class DefaultSceneNode : ISceneNode
{
  /// <summary>GrCis's stand-in for an infinite coordinate (e.g. the far end of a plane's texture range).</summary>
  public static readonly double INFINITY_PLACEHOLDER = 1.0e6;

  /// <summary>This node's own attributes by name (null until the first <see cref="SetAttribute"/>).</summary>
  protected Dictionary<string, object?>? attributes;

  /// <summary>GrCis's field name of <see cref="Children"/>, for subclasses.</summary>
  protected ICollection<ISceneNode> children
  {
    get => Children;
    set => Children = value;
  }
  Matrix4d toParent = Matrix4d.Identity;
  Matrix4d fromParent = Matrix4d.Identity;

  /// <inheritdoc/>
  public ISceneNode? Parent { get; set; }

  /// <summary>Local → parent transform (row vectors: <c>v * ToParent</c>; identity by default). Setting it also sets <see cref="FromParent"/> to its inverse.</summary>
  public virtual Matrix4d ToParent
  {
    get => toParent;
    set
    {
      toParent = value;
      fromParent = value.Inverted();
    }
  }

  /// <summary>Parent → local transform (identity by default). Setting it also sets <see cref="ToParent"/> to its inverse.</summary>
  public virtual Matrix4d FromParent
  {
    get => fromParent;
    set
    {
      fromParent = value;
      toParent = value.Inverted();
    }
  }

  /// <inheritdoc/>
  public ICollection<ISceneNode> Children { get; protected set; } = new LinkedList<ISceneNode>();

  /// <inheritdoc/>
  public bool ObjectRoot { get; set; }

  /// <summary>Attribute value of this node; when it has none (or null), its parent's, and so on up to the root. Null when no node has it.</summary>
  /// <param name="name">Attribute name, usually a <see cref="PropertyName"/> constant.</param>
  public virtual object? GetAttribute(string name)
  {
    if (attributes != null && attributes.TryGetValue(name, out object? value) && value != null)
      return value;
    return Parent?.GetAttribute(name);
  }

  /// <inheritdoc/>
  public virtual object? GetLocalAttribute(string name) =>
    attributes != null && attributes.TryGetValue(name, out object? value) ? value : null;

  /// <inheritdoc/>
  /// <exception cref="ArgumentNullException"><paramref name="name"/> is null.</exception>
  public virtual void SetAttribute(string name, object? value)
  {
    ArgumentNullException.ThrowIfNull(name);
    attributes ??= new Dictionary<string, object?>();
    attributes[name] = value;
  }

  /// <summary>Local → world: <c>ToParent * Parent.ToWorld()</c>; the root's own space is the world.</summary>
  public virtual Matrix4d ToWorld() => Parent == null ? Matrix4d.Identity : ToParent * Parent.ToWorld();

  /// <summary>Local → object space: the transforms up to the nearest node marked <see cref="ObjectRoot"/> (this one: identity), or up to the root.</summary>
  public virtual Matrix4d ToObject()
  {
    Matrix4d m = Matrix4d.Identity;
    ISceneNode? node = this;
    while (node != null && node.Parent != null && !node.ObjectRoot)
    {
      m *= node.ToParent;
      node = node.Parent;
    }
    return m;
  }

  /// <summary>Textures of all ancestors (outermost first) followed by this node's own.</summary>
  public virtual LinkedList<ITexture>? GetTextures()
  {
    LinkedList<ITexture>? list = Parent?.GetTextures();
    object? own = GetLocalAttribute(PropertyName.TEXTURE);
    if (own == null)
      return list;
    list = list == null ? new LinkedList<ITexture>() : new LinkedList<ITexture>(list);
    switch (own)
    {
      case ITexture t:
        list.AddLast(t);
        break;
      case IEnumerable<ITexture> many:
        foreach (ITexture t in many)
          list.AddLast(t);
        break;
    }
    return list;
  }

  /// <summary>Adds a child with its local → parent transform.</summary>
  public virtual void InsertChild(ISceneNode child, Matrix4d toParent)
  {
    ArgumentNullException.ThrowIfNull(child);
    Children.Add(child);
    child.Parent = this;
    child.ToParent = toParent;
  }

  /// <summary>A plain node has no surface of its own: null. Solids and <see cref="CSGInnerNode"/> override it.</summary>
  public virtual LinkedList<Intersection>? Intersect(Vector3d p0, Vector3d p1) => null;

  /// <summary>Nothing to complete for a plain node; solids override it.</summary>
  public virtual void CompleteIntersection(Intersection inter) { }

  /// <summary>
  /// GrCis's helper for a time-dependent node's <c>Clone()</c>: gives <paramref name="n"/> this node's
  /// children, each time-dependent child cloned. A static child is shared (its geometry and attributes
  /// are not copied) through a shallow copy whose parent is <paramref name="n"/>, so clones rendered
  /// by different threads never re-parent one shared node.
  /// </summary>
  public void ShareCloneChildren(DefaultSceneNode n)
  {
    ArgumentNullException.ThrowIfNull(n);
    foreach (ISceneNode child in Children)
    {
      ISceneNode copy = child is ITimeDependent td ? (ISceneNode)td.Clone() : SceneNodeRelinker.Relink(child);
      n.InsertChild(copy, child.ToParent);
    }
  }

  /// <summary>
  /// GrCis's helper for a time-dependent node's <c>Clone()</c>: gives <paramref name="n"/> its own
  /// attribute map: a list value becomes a new list (time-dependent items cloned), a cloneable value
  /// (<see cref="ICloneable"/>: arrays, materials, time-dependent attributes) is cloned, the rest shared.
  /// </summary>
  public void ShareCloneAttributes(DefaultSceneNode n)
  {
    ArgumentNullException.ThrowIfNull(n);
    if (attributes == null || attributes.Count == 0)
    {
      n.attributes = null;
      return;
    }
    var copy = new Dictionary<string, object?>(attributes.Count);
    foreach (KeyValuePair<string, object?> kv in attributes)
      copy[kv.Key] = kv.Value switch
      {
        IEnumerable<ITexture> textures => CloneItems(textures),
        IEnumerable<object> items => CloneItems(items),
        ICloneable cloneable => cloneable.Clone(),
        _ => kv.Value,
      };
    n.attributes = copy;
  }

  static LinkedList<T> CloneItems<T>(IEnumerable<T> items) where T : class
  {
    var list = new LinkedList<T>();
    foreach (T item in items)
      list.AddLast(item is ITimeDependent td ? (T)td.Clone() : item);
    return list;
  }

  /// <summary>Scripts may add several textures with this helper.</summary>
  public void AddTexture(ITexture texture)
  {
    ArgumentNullException.ThrowIfNull(texture);
    object? own = GetLocalAttribute(PropertyName.TEXTURE);
    switch (own)
    {
      case null:
        SetAttribute(PropertyName.TEXTURE, texture);
        break;
      case ITexture t:
        SetAttribute(PropertyName.TEXTURE, new List<ITexture> { t, texture });
        break;
      case List<ITexture> l:
        l.Add(texture);
        break;
      default:
        throw new InvalidOperationException($"Attribute '{PropertyName.TEXTURE}' holds a {own.GetType().Name}, not a texture.");
    }
  }
}
