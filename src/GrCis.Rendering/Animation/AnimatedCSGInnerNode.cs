using System;
using System.Collections.Generic;

namespace Rendering;

/// <summary>
/// A CSG node of an animated scene: passes time to its time-dependent children (and
/// time-dependent attribute values), and clones itself "on write".
/// </summary>
/// <remarks>
/// <para>
/// <see cref="Clone"/> clones the time-dependent children and shares the static ones. A shared
/// child still points to the original node as its parent, which is only right while nothing
/// above it changes with time. So when this node or an animated ancestor moves
/// (<see cref="AnimatesTransform"/>) or carries time-dependent attributes, static children are
/// re-linked instead: each static node below gets a shallow copy whose parent is the clone,
/// while its geometry, attributes and other data stay shared.
/// </para>
/// <para>
/// Nodes that animate their own transform read named values from the scene's animator at
/// their time; see <see cref="AnimatedNodeTransform"/>.
/// </para>
/// </remarks>
[Serializable]
public class AnimatedCSGInnerNode : CSGInnerNode, ITimeDependent
{
  /// <summary>The current time (<see cref="Time"/>).</summary>
  protected double time;

  /// <summary>An animated inner node at time <paramref name="start"/>.</summary>
  /// <param name="op">How the children combine (see <see cref="CSGInnerNode"/>).</param>
  /// <param name="start">Start of the time range in seconds (<see cref="Start"/>), also the initial time.</param>
  /// <param name="end">End of the time range in seconds (<see cref="End"/>).</param>
  public AnimatedCSGInnerNode(SetOperation op, double start = 0.0, double end = 0.0) : base(op)
  {
    Start = start;
    End = end;
    time = start;
  }

  /// <inheritdoc/>
  public double Start { get; set; }

  /// <inheritdoc/>
  public double End { get; set; }

  /// <summary>Current time in seconds; setting it passes the time to the time-dependent children and attribute values.</summary>
  public double Time
  {
    get => time;
    set => setTime(value);
  }

  /// <summary>
  /// True when this node's own transform changes with time. The base class never moves; a
  /// subclass is assumed to move unless it says otherwise.
  /// </summary>
  public virtual bool AnimatesTransform => GetType() != typeof(AnimatedCSGInnerNode);

  /// <summary>Stores the time and passes it to time-dependent children and attribute values.</summary>
  protected virtual void setTime(double newTime)
  {
    time = newTime;
    if (attributes != null)
      foreach (object? value in attributes.Values)
        if (value is ITimeDependent td)
          td.Time = newTime;
    foreach (ISceneNode child in Children)
      if (child is ITimeDependent td)
        td.Time = newTime;
  }

  /// <summary>A copy at the same time: time-dependent children cloned, static ones shared or re-linked.</summary>
  public virtual object Clone()
  {
    var n = (AnimatedCSGInnerNode)MemberwiseClone();
    n.attributes = CloneAttributes(attributes);

    bool relink = StaticChildrenNeedRelinking();
    var children = new LinkedList<ISceneNode>();
    foreach (ISceneNode child in Children)
    {
      ISceneNode copy = child is ITimeDependent td ? (ISceneNode)td.Clone()
        : relink ? SceneNodeRelinker.Relink(child)
        : child;
      if (!ReferenceEquals(copy, child))
        copy.Parent = n;
      children.AddLast(copy);
    }
    n.Children = children;
    return n;
  }

  /// <summary>Shares the attribute dictionary unless a value is time-dependent; those are cloned.</summary>
  static Dictionary<string, object?>? CloneAttributes(Dictionary<string, object?>? source)
  {
    if (source == null)
      return null;
    bool any = false;
    foreach (object? value in source.Values)
      any |= value is ITimeDependent;
    if (!any)
      return source;
    var copy = new Dictionary<string, object?>(source.Count);
    foreach (KeyValuePair<string, object?> kv in source)
      copy[kv.Key] = kv.Value is ITimeDependent td ? td.Clone() : kv.Value;
    return copy;
  }

  bool HasTimeDependentAttributes()
  {
    if (attributes != null)
      foreach (object? value in attributes.Values)
        if (value is ITimeDependent)
          return true;
    return false;
  }

  /// <summary>Whether a static child's world transform or inherited attributes can differ between clones.</summary>
  bool StaticChildrenNeedRelinking()
  {
    for (ISceneNode? node = this; node != null; node = node.Parent)
      if (node is AnimatedCSGInnerNode a && (a.AnimatesTransform || a.HasTimeDependentAttributes()))
        return true;
    return false;
  }
}
