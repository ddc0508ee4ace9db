using OpenTK.Mathematics;

namespace Rendering.Accel;

/// <summary>
/// A solid with a walk for shadow queries (<see cref="IntersectAny"/>) besides its records: it may stop at the first
/// blocker instead of searching for the first record. The library's triangle mesh has one; the prepared scene uses it
/// only for a class that changes nothing of the class implementing it (<see cref="LibraryTypes.DirectKernel"/>).
/// </summary>
internal interface IAnyHitSolid
{
  /// <summary>
  /// The shadow query's form of <see cref="IRecordSolid.IntersectFirst"/> for a segment whose blocker counts up to
  /// <paramref name="tMax"/>: a record that changes the list's state at or before it (not necessarily the first), none
  /// when there is none, or the first record where only the full search can tell (the caller then decides by the list).
  /// </summary>
  bool IntersectAny(in Vector3d p0, in Vector3d p1, double len2, double tMax, out SolidRecord hit, out bool insideBefore);

  /// <summary>
  /// <see cref="IRecordSolid.IntersectFirst"/>'s record without the state before it, for a caller that does not need
  /// that state (a scene of this one solid): the same record when its T ≤ <paramref name="tMax"/>, else none. The solid
  /// may then skip the search behind the origin that only the state needs.
  /// </summary>
  bool FirstRecord(in Vector3d p0, in Vector3d p1, double len2, double tMax, out SolidRecord hit);

  /// <summary>
  /// A scene of this one solid's shadow answer: whether <see cref="FirstRecord"/>'s record exists and is not far
  /// (<see cref="PreparedScene.NotFar"/>), where no T beyond <paramref name="tMax"/> is. The solid may stop at a blocker
  /// found in any order when it can prove that the record is no later than it.
  /// </summary>
  bool Occluded(in Vector3d p0, in Vector3d p1, double len2, double tMax);
}
