using Rendering;

namespace GrCis.Hosting;

/// <summary>
/// Wires the objects a script hands over (<c>context[CTX_ALGORITHM]</c>) to its scene as GrCis's demos did:
/// GrCis's image functions held the scene in their protected <c>scene</c> field (their constructor took it),
/// and a student's subclass reads that field. Library functions stay unbound and render the worker's scene.
/// </summary>
internal static class ScriptObjects
{
  /// <summary>Binds a student's <see cref="RayCasting"/> subclass that has no scene to <paramref name="scene"/>.</summary>
  public static void Wire(IImageFunction? function, IRayScene scene)
  {
    if (function is RayCasting rc && rc.BoundScene == null && !Rendering.Accel.FrontEndRules.IsLibraryClass(rc))
      rc.Scene = scene;
  }
}
