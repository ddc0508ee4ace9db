using System;
using OpenTK.Mathematics;

namespace Rendering;

/// <summary>
/// An inner node that moves: whenever its time is set it reads named values from the scene's
/// animator (<c>MT.scene.Animator</c>, an <see cref="ITimeDependentProperty"/>, which the
/// animated scene has already moved to the same time) and rebuilds its transform as
/// <c>Rotation(q) * Origin * Translation(v)</c>: rotate about the local origin, place, then offset.
/// </summary>
/// <remarks>
/// A property that is missing (or a null name) leaves that part at rest: identity rotation,
/// zero offset. The transform given to <c>InsertChild</c> is replaced by this one once time is set,
/// so pass the rest transform as <see cref="Origin"/>.
/// </remarks>
[Serializable]
public class AnimatedNodeTransform : AnimatedCSGInnerNode
{
  /// <summary>Name of a Vector3d property: offset in the parent's space.</summary>
  public string? TranslationName;

  /// <summary>Name of a Quaterniond property: rotation about the node's local origin.</summary>
  public string? RotationName;

  /// <summary>Transform at rest (zero offset, no rotation).</summary>
  public Matrix4d Origin;

  /// <summary>Current offset and rotation (as last read from the animator).</summary>
  public Vector3d Translation { get; protected set; }

  /// <summary>Current rotation, as last read from the animator (identity before that).</summary>
  public Quaterniond Rotation { get; protected set; } = Quaterniond.Identity;

  /// <summary>A moving inner node; its transform is <paramref name="origin"/> until the time is first set.</summary>
  /// <param name="translationName">Name of the animator's Vector3d property with the offset, or null for none.</param>
  /// <param name="rotationName">Name of the animator's Quaterniond property with the rotation, or null for none.</param>
  /// <param name="origin">Transform at rest (<see cref="Origin"/>).</param>
  /// <param name="op">How the children combine (default <see cref="SetOperation.Union"/>).</param>
  /// <param name="start">Start of the time range in seconds, also the initial time.</param>
  /// <param name="end">End of the time range in seconds.</param>
  public AnimatedNodeTransform(
    string? translationName,
    string? rotationName,
    Matrix4d origin,
    SetOperation op = SetOperation.Union,
    double start = 0.0,
    double end = 0.0)
    : base(op, start, end)
  {
    TranslationName = translationName;
    RotationName = rotationName;
    Origin = origin;
    ToParent = origin;
  }

  /// <summary>True: this node's transform changes with time.</summary>
  public override bool AnimatesTransform => true;

  /// <summary>Reads the offset and rotation from the scene's animator (when there is one), rebuilds <see cref="DefaultSceneNode.ToParent"/>, then passes the time on as the base class does.</summary>
  protected override void setTime(double newTime)
  {
    if (WorkerScene.Of(Execution.WorkerContext.Current)?.Animator is ITimeDependentProperty animator)
    {
      Vector3d v = Vector3d.Zero;
      Quaterniond q = Quaterniond.Identity;
      if (TranslationName != null)
        animator.TryGetValue(TranslationName, ref v);
      if (RotationName != null)
        animator.TryGetValue(RotationName, ref q);
      Translation = v;
      Rotation = q;
      ToParent = Matrix4d.CreateFromQuaternion(q) * Origin * Matrix4d.CreateTranslation(v);
    }
    base.setTime(newTime);
  }
}
